// The shapes of the lab's web API (docs/web-api.md). Lengths in metres, times in seconds,
// angles in radians unless a key's name says otherwise (_mm, _rpm, _K); null: not measured.

export interface SceneEntry {
  name: string;
  title: string;
}

export interface MaterialEntry {
  key: string;
  name: string;
  temperatures_K: number[];
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
  id: string;
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
export type Summary = Record<string, unknown>;

export interface Failure {
  message: string;
}

export type ControlAction = "play" | "pause" | "step" | "reset";

export interface ControlReply {
  t: number;
  playing: boolean;
  speed: PlaybackSpeed;
}
