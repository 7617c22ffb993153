// The shapes of the lab's web API (docs/web-api.md). Lengths in metres, times in seconds,
// angles in radians unless a key's name says otherwise (_mm, _rpm, _k for kelvin); null: not measured.
import type { RunSummaryJson } from "./run_summary";

export interface SceneEntry {
  name: string;
  title: string;
}

export interface MaterialEntry {
  key: string;
  name: string;
  temperatures_k: number[];
}

export interface Lab {
  scenes: SceneEntry[];
  materials: MaterialEntry[];
  version: string;
}

export interface PlateBlock {
  part: string;
  x: number;
  y: number;
  turn_deg: number;
}

export interface Plate {
  length: number;
  width: number;
  thickness: number;
  mass: number;
  h_c: number;
  material: string;
  blocks: PlateBlock[];
}

export interface Magnet {
  x: number;
  height: number | null;
  diameter: number;
  thickness: number;
}

export interface HallSensor {
  x: number;
  y: number;
  z: number;
}

export interface FramePart {
  part: string;
  position: [number, number, number];
  turn_deg: number;
  color: [number, number, number] | null;
}

export interface PaperValues {
  material: string;
  period: number;
  period_err: number;
  mu_k: number;
  mu_k_err: number;
}

export interface Rig {
  scene: string;
  spacing: number;
  roller_radius: number;
  roller_length: number;
  roller_sense: string;
  roller_speed_rpm: number;
  drive: boolean;
  plate: Plate;
  magnets: Magnet[];
  sensor: HallSensor | null;
  frame: FramePart[];
  offset: number;
  duration: number;
  time_step: number;
  seed: number;
  mu_k: number;
  period_thin: number;
  period_thick: number | null;
  omega: number | null;
  tipping_amplitude: number | null;
  paper: PaperValues | null;
}

export interface Session {
  /** Public: the class's table lists it. */
  id: string;
  /** The session's secret: only requests that carry it control the session (docs/web-api.md). */
  key: string;
  rig: Rig;
}

export interface Problem {
  field: string;
  value?: string;
  message: string;
}

export interface ContactForce {
  normal: number;
  friction: number;
}

/** One period as the estimator judged it: [start, end, period, accepted]. */
export type PeriodRow = [number, number, number, boolean];

export interface Estimate {
  periods_used: number;
  period: number;
  period_sd: number | null;
  period_se: number | null;
  mu_k: number | null;
  /** In quadrature: mu_k sqrt((dl/l)^2 + (2 dT/T)^2). */
  mu_k_err: number | null;
  /** The paper's worst case, mu_k (dl/l + 2 dT/T), where the server sends it. */
  mu_k_err_worst?: number | null;
}

export type PlaybackSpeed = 1 | 0.25 | 0.0625;

export interface LabState {
  t: number;
  x: number;
  /** Where the thick plate's theory has the plate now [m], from where the run started; null
   * when the rollers do not restore the plate. The page draws it as sent: no formula of its own. */
  x_theory: number | null;
  z: number;
  pitch: number;
  vx: number;
  roller_angles: [number, number];
  contacts: ContactForce[];
  hall: [number, number][];
  pulses: number[];
  periods: PeriodRow[];
  estimate: Estimate | null;
  regime: string;
  playing: boolean;
  speed: PlaybackSpeed;
}

/** The run's summary (the same object as its summary.json); its keys are the CLI's (the
 * headline: period_s, period_std_s, period_std_error_s, mu_k_recovered, mu_k_err_quadrature,
 * regime). */
/** A finished run's summary: summary.json's object, typed from the lab's declaration of its fields. */
export type Summary = RunSummaryJson;

export interface Failure {
  message: string;
}

export type ControlAction = "play" | "pause" | "step" | "reset";

export interface ControlReply {
  t: number;
  playing: boolean;
  speed: PlaybackSpeed;
}

/** `event: closed`: the server is stopping (Ctrl-C, SIGTERM); the stream ends after it. */
export interface Closed {
  message: string;
}

/** The live rig's serial port: none open, open with nothing yet, lines coming, gone, or failed. */
export type RigPortState = "closed" | "waiting" | "receiving" | "unplugged" | "failed";

/** `GET /api/rig`: the serial ports the server sees and the one open (or last open). */
export interface LiveRig {
  ports: string[];
  /** Whether this page may open or close a port (false on a shared server). */
  may_choose: boolean;
  port: string | null;
  baud: number | null;
  state: RigPortState;
  /** What happened and what to do; null while all is well. */
  message: string | null;
  /** The lines received. */
  lines: number;
  /** The name the raw log downloads under; null before a line came. */
  log_name: string | null;
}

/** How many Hall pulses the magnet gives per period, as the rig's estimator recognised it. */
export type PulseGeometry = "one-pulse" | "pair" | "unknown";

/** `event: rig`: what the live rig sent since the last event, through the rig's estimator with
 * the session's spacing. */
export interface RigEvent {
  port: string | null;
  state: RigPortState;
  message: string | null;
  lines: number;
  /** The board's restarts: a new value starts the rig's plot and periods again. */
  run: number;
  /** [t, adc]: t in seconds from the run's first sample. */
  hall: [number, number][];
  periods: PeriodRow[];
  estimate: Estimate | null;
  geometry: PulseGeometry;
  /** The l [m] mu_k is computed with: the session's rig's. */
  spacing: number;
}

/** One session's row of `GET /api/class`: its set-up and its result so far. */
export interface ClassRow {
  session: string;
  name: string | null;
  scene: string;
  /** The plate's material in the paper's Table I; null for a mu_k given as a number. */
  material: string | null;
  temperature_k: number | null;
  spacing: number;
  h_c: number | null;
  state: "paused" | "playing" | "done";
  /** The simulated time reached. */
  t: number;
  period: number | null;
  /** The standard error of the mean of the accepted periods (or of the fit). */
  period_err: number | null;
  /** Where the period comes from: the Hall sensor's estimator, or (a rig without a sensor, its
   * run done) the fit to the plate's motion; null before a period. */
  period_from: "sensor" | "trajectory" | null;
  mu_k: number | null;
  /** In quadrature. */
  mu_k_err: number | null;
  paper_period: number | null;
  paper_mu_k: number | null;
}

/** `GET /api/class`: every open session, and the live rig (null when none was open). */
export interface ClassTable {
  sessions: ClassRow[];
  rig: { port: string | null; state: RigPortState; lines: number } | null;
}
