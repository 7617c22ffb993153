// The shapes of the lab's web API (docs/web-api.md): every object the server sends, written by
// tools/generate-fields from the lab's one declaration of them (src/api/api_fields.cpp), which
// serve's C++ and the page's mock server are both held to; a test fails when this file is not what
// the declaration gives. Lengths in metres, times in seconds, angles in radians unless a key's
// name says otherwise (_mm, _rpm, _deg, _k for kelvin); null: not measured, or the rig has none.
import type { RunSummaryJson } from "./run_summary";

/** `event: done`: the run's summary, summary.json's object. */
export type Summary = RunSummaryJson;

// generated: web-api-types
/** One period as the estimator judged it: [start, end, period, accepted], in seconds. */
export type PeriodRow = [number, number, number, boolean];

/** One Hall sample: [t, adc], t in seconds from the run's first sample. */
export type HallPoint = [number, number];

/** How fast simulated time runs against the wall's. */
export type PlaybackSpeed = 1 | 0.25 | 0.0625;

/** The live rig's serial port: none open, open with nothing yet, lines coming, gone, failed, or its log full. */
export type BoardPortState = "closed" | "waiting" | "receiving" | "unplugged" | "failed" | "full";

/** How many Hall pulses the magnets give per period, as the rig's estimator recognised it. */
export type PulseGeometry = "one-pulse" | "pair" | "unknown";

/** Where a session's run stands. */
export type SessionState = "paused" | "playing" | "done";

/** Where a period comes from: the Hall sensor's estimator, or the fit to the plate's motion. */
export type PeriodFrom = "sensor" | "trajectory";

/** A scene the lab offers (`GET /api/lab`). */
export interface SceneEntry {
  /** the name a session asks for */
  name: string;
  /** the scene's title */
  title: string;
}

/** A material of the paper's Table I (`GET /api/lab`). */
export interface MaterialEntry {
  /** `plate.material`'s value for it */
  key: string;
  /** its name in Table I */
  name: string;
  /** [K] the temperatures Table I measured it at */
  temperatures_k: number[];
}

/** `GET /api/lab`: what the page is offered. */
export interface Lab {
  /** the scenes, by name */
  scenes: SceneEntry[];
  /** the paper's Table I */
  materials: MaterialEntry[];
  /** the lab's version */
  version: string;
}

/** A LEGO part on the plate. */
export interface PlateBlock {
  /** the part, served as /parts/NAME.glb */
  part: string;
  /** [m] its centre along the plate from the plate's centre */
  x: number;
  /** [m] its centre across the plate */
  y: number;
  /** its turn about the vertical, in degrees */
  turn_deg: number;
}

/** The friction plate. */
export interface Plate {
  /** [m] along the rollers' spacing */
  length: number;
  /** [m] along the rollers' axes */
  width: number;
  /** [m] the plate's own, blocks not included */
  thickness: number;
  /** [kg] with its blocks and magnets */
  mass: number;
  /** [m] its centre of mass above the rollers' contact line */
  h_c: number;
  /** the plate's material (`plate.material`) */
  material: string;
  /** the LEGO parts on it */
  blocks: PlateBlock[];
}

/** A magnet on the plate. */
export interface Magnet {
  /** [m] its centre along the plate from the plate's centre */
  x: number;
  /** [m] its bottom face above the plate's top face */
  height: number;
  /** [m] its diameter */
  diameter: number;
  /** [m] its thickness */
  thickness: number;
}

/** Where the Hall sensor sits. */
export interface HallSensor {
  /** [m] along the plate's motion from the rollers' midpoint */
  x: number;
  /** [m] across */
  y: number;
  /** [m] up */
  z: number;
}

/** A LEGO part of the rig's frame. */
export interface FramePart {
  /** the part, served as /parts/NAME.glb */
  part: string;
  /** [m] its position */
  position: [number, number, number];
  /** its turn about z after the position, in degrees */
  turn_deg: number;
  /** red, green, blue from 0 to 1 */
  color: [number, number, number];
}

/** What the paper measured for the rig's material (its Table I row). */
export interface PaperValues {
  /** the material's name in Table I */
  material: string;
  /** `plate.material`'s value for it */
  key: string;
  /** [K] the rollers' temperature of the row */
  temperature_k: number;
  /** [s] the period the paper measured */
  period: number;
  /** [s] its uncertainty */
  period_err: number;
  /** the paper's mu_k */
  mu_k: number;
  /** its uncertainty */
  mu_k_err: number;
}

/** The values the set-up accepts for a key a student turns, every other value as it is. */
export interface AcceptedRange {
  /** the scene key, as a `set` entry names it (`rollers.spacing`, `rollers.speed` or `drive.motor.duty`, `plate.offset`, `world.duration`) */
  key: string;
  /** the least value accepted, in `unit` */
  least: number;
  /** the most accepted, in `unit` */
  most: number;
  /** the SI unit of least and most (`m`, `rad/s`, `s`; none for a duty) */
  unit: string;
}

/** A session's rig as compiled from its set-up (`POST /api/sessions`). */
export interface Rig {
  /** the scene's name */
  scene: string;
  /** [m] l, between the rollers' axes */
  spacing: number;
  /** [m] the rollers' radius */
  roller_radius: number;
  /** [m] the rollers' length */
  roller_length: number;
  /** whether the rollers' tops turn toward each other (restoring) or apart */
  roller_sense: "inward" | "outward";
  /** the rollers' nominal speed, in rpm */
  roller_speed_rpm: number;
  /** whether a motor and gearbox drive the rollers */
  drive: boolean;
  /** the motor's duty; null without a drive */
  motor_duty: number | null;
  /** [m] the rollers' run-out */
  runout: number;
  /** the friction plate */
  plate: Plate;
  /** the magnets on the plate */
  magnets: Magnet[];
  /** the Hall sensor; null for a rig without one */
  sensor: HallSensor | null;
  /** the LEGO frame's parts (none for a bare rig) */
  frame: FramePart[];
  /** [m] where the plate starts, from the rollers' midpoint */
  offset: number;
  /** [s] the run's simulated length */
  duration: number;
  /** [s] the physics step */
  time_step: number;
  /** `world.seed`, which draws the sensor's noise */
  seed: number;
  /** [m/s^2] g */
  gravity: number;
  /** whether mu depends on the slip speed */
  friction_law: "slip-dependent" | "coulomb";
  /** the kinetic friction coefficient set */
  mu_k: number;
  /** [K] the rollers' temperature at the start */
  temperature_k: number;
  /** [s] the paper's period, pi sqrt(2 l / (mu_k g)) */
  period_thin: number;
  /** [s] the period with the plate's thickness; null when the rollers do not restore it */
  period_thick: number | null;
  /** [rad/s] 2 pi / period_thick; null likewise */
  omega: number | null;
  /** [m] the amplitude beyond which the plate tips off a roller; null likewise */
  tipping_amplitude: number | null;
  /** what the paper measured; null when the friction is not a Table I row */
  paper: PaperValues | null;
  /** what each key a student turns accepts with the rest of the set-up as it is: the page's controls offer these ranges only */
  accepts: AcceptedRange[];
}

/** `POST /api/sessions`'s answer (201). */
export interface Session {
  /** the session's public id; the class's table lists it */
  id: string;
  /** the session's secret: only requests that carry it control the session */
  key: string;
  /** the compiled rig */
  rig: Rig;
}

/** One problem of a request the lab refused, by field. */
export interface Problem {
  /** the request's key (`scene`, `set`, `name`; `file` for a measurement's file) */
  field: string | null;
  /** the entry at fault (a `set` entry; the place in the file, `log.csv:3:5`) */
  value: string | null;
  /** what was expected, what was found, what to do */
  message: string;
  /** the message as the catalogues (assets/locales) say it, for a page to say in its reader's language; null where the lab says it in English only */
  said: Said | null;
}

/** A message the lab says: its id in assets/locales/LANG.ftl and its values. */
export interface Said {
  /** the message's id (`check-rollers-overlap`) */
  id: string;
  /** its values, by the names its pattern uses */
  args: SaidArg[];
}

/** One value of a message: exactly one of `number`, `text` and `said`. */
export interface SaidArg {
  /** the name its pattern uses (`spacing_mm`) */
  name: string;
  /** a number, in the unit the name says */
  number?: number;
  /** a text said as it is */
  text?: string;
  /** another message, said in the same language */
  said?: Said;
}

/** A 4xx's body. */
export interface ErrorBody {
  /** what went wrong, in a line */
  error: string;
  /** each problem by field (none for the API's own) */
  problems: Problem[];
  /** the error as the catalogues say it, where they do; absent otherwise */
  said?: Said;
  /** true when the lab is full (503); absent otherwise */
  refused?: boolean;
}

/** A roller's contact with the plate. */
export interface ContactForce {
  /** [N] the normal force on the plate */
  normal: number;
  /** [N] the friction force on the plate, along its motion */
  friction: number;
}

/** The rig's estimator's statistics of the accepted periods. */
export interface Estimate {
  /** N, the accepted periods */
  periods_used: number;
  /** the periods it rejected */
  periods_discarded: number;
  /** the Hall pulses it detected */
  pulses: number;
  /** [s] the mean period */
  period: number;
  /** [s] the periods' standard deviation; null below two */
  period_sd: number | null;
  /** [s] the standard error of their mean; null below two */
  period_se: number | null;
  /** mu_k through the paper's formula */
  mu_k: number;
  /** mu_k sqrt((dl/l)^2 + (2 dT/T)^2), dl = 2 mm; null below two periods */
  mu_k_err: number | null;
  /** the paper's worst case, mu_k (dl/l + 2 dT/T); null below two periods */
  mu_k_err_worst: number | null;
}

/** `event: state`: the run now, and what came since the last event. */
export interface LabState {
  /** [s] the simulated time */
  t: number;
  /** [m] the plate's centre along its motion */
  x: number;
  /** [m] where the thick plate's theory has the plate now, from where the run started; null when the rollers do not restore the plate */
  x_theory: number | null;
  /** [m] the plate's centre across */
  y: number;
  /** [m] its height */
  z: number;
  /** [rad] its tilt about the rollers' axes */
  pitch: number;
  /** [rad] its turn about the vertical */
  yaw: number;
  /** [m/s] its speed along its motion */
  vx: number;
  /** [rad] the rollers' angles */
  roller_angles: [number, number];
  /** the two rollers' contacts */
  contacts: ContactForce[];
  /** the Hall samples since the last event */
  hall: HallPoint[];
  /** [s] the pulses detected since the last event */
  pulses: number[];
  /** the periods judged since the last event */
  periods: PeriodRow[];
  /** the estimate so far; null before a period */
  estimate: Estimate | null;
  /** the diagnosis so far */
  regime: string;
  /** whether the run plays */
  playing: boolean;
  /** its playback speed */
  speed: PlaybackSpeed;
}

/** `POST /api/sessions/ID/control`'s answer. */
export interface ControlReply {
  /** [s] the simulated time */
  t: number;
  /** whether the run plays */
  playing: boolean;
  /** its playback speed */
  speed: PlaybackSpeed;
}

/** `event: closed`: the server is stopping; the stream ends after it. */
export interface Closed {
  /** what happened and what to do */
  message: string;
}

/** `event: failed`: a guard stopped the run (its summary follows as `done`). */
export interface Failure {
  /** the guard's message */
  message: string;
}

/** `GET /api/rig`: the serial ports the server sees and the one open (or last open). */
export interface LiveRig {
  /** the ports a page may open (none on a shared server) */
  ports: string[];
  /** whether this page may open or close a port */
  may_choose: boolean;
  /** the port open or last open; null before one */
  port: string | null;
  /** its baud rate; null before a port */
  baud: number | null;
  /** the port's state */
  state: BoardPortState;
  /** what happened and what to do; null while all is well */
  message: string | null;
  /** the message as the catalogues say it; null where they do not */
  said: Said | null;
  /** the lines received */
  lines: number;
  /** the raw log's download name; null before a line */
  log_name: string | null;
}

/** `event: rig`: what the live rig sent since the last event, through the rig's estimator with the session's spacing. */
export interface LiveRigEvent {
  /** the port */
  port: string | null;
  /** the port's state */
  state: BoardPortState;
  /** what happened and what to do; null while all is well */
  message: string | null;
  /** the message as the catalogues say it; null where they do not */
  said: Said | null;
  /** the lines received */
  lines: number;
  /** the board's restarts: a new value starts the rig's plot and periods again */
  run: number;
  /** the samples since the last event (the last 10 s at most) */
  hall: HallPoint[];
  /** the periods judged since the last event */
  periods: PeriodRow[];
  /** the estimate so far; null before a period */
  estimate: Estimate | null;
  /** the pulses per period recognised */
  geometry: PulseGeometry;
  /** [m] the l mu_k is computed with: the session's rig's */
  spacing: number;
}

/** One session's row of `GET /api/class` (and of class.csv): its set-up and result so far. */
export interface ClassRow {
  /** the session's id */
  session: string;
  /** who runs it; null when not given */
  name: string | null;
  /** the scene's name */
  scene: string;
  /** the plate's material in Table I; null for a mu_k given as a number */
  material: string | null;
  /** [K] the rollers' temperature at the start */
  temperature_k: number;
  /** [m] l */
  spacing: number;
  /** [m] the plate's centre of mass above the contact line */
  h_c: number;
  /** where the run stands */
  state: SessionState;
  /** [s] the simulated time reached */
  t: number;
  /** [s] the mean accepted period; null before one */
  period: number | null;
  /** [s] the standard error of that mean (or of the fit); null below two periods */
  period_err: number | null;
  /** where the period comes from */
  period_from: PeriodFrom | null;
  /** through the paper's formula; null before a period */
  mu_k: number | null;
  /** in quadrature; null below two periods */
  mu_k_err: number | null;
  /** [s] the paper's period for the material */
  paper_period: number | null;
  /** the paper's mu_k for the material */
  paper_mu_k: number | null;
}

/** The live rig as the class's table shows it. */
export interface ClassLiveRig {
  /** the port */
  port: string | null;
  /** the port's state */
  state: BoardPortState;
  /** the lines received */
  lines: number;
}

/** `GET /api/class`: every open session, and the live rig. */
export interface ClassTable {
  /** one row a session */
  sessions: ClassRow[];
  /** the live rig; null when no port was opened */
  rig: ClassLiveRig | null;
}

/** `POST /api/estimate?name=FILE`: a measurement file's estimate, the keys of `frictionlab estimate --json` (docs/cli.md) the page shows. */
export interface MeasurementEstimate {
  /** the file read (a folder's log; a followed port's raw log, or the port) */
  file: string;
  /** what measured: `Hall sensor` (the rig's), `phyphox magnetometer` (a phone beside the rig), `phyphox accelerometer` or `phyphox accelerometer (without g)` (a phone on the plate), `Tracker` (a video's marks), `position-time table`, `video` (a phone's video, the plate followed without clicks) */
  instrument: string;
  /** the channel read of the instrument's several, the one that swings clearest: a magnetometer's `x`, `y`, `z` or `|B|`, an accelerometer's axis (or, for a phone lying between them, its axes combined along the motion: `0.866 x + 0.500 y`), a table's position column, a video's `x (px)` or `x (mm)` */
  channel: string | null;
  /** samples used */
  samples: number;
  /** [Hz] the mean sample rate */
  sample_rate_hz: number;
  /** [s] last sample time minus first */
  duration_s: number;
  /** N, the accepted periods */
  periods_used: number;
  /** rejected periods: outliers and periods at broken turning points */
  periods_discarded: number;
  /** [s] T, the mean accepted period */
  period_s: number;
  /** [s] dT, the accepted periods' standard deviation (the paper's) */
  period_std_s: number;
  /** [s] the standard error of the mean, dT/sqrt(N) */
  period_sem_s: number;
  /** mu_k = 2 pi^2 l / (g T^2), the paper's (thin) formula */
  mu_k: number;
  /** d mu_k, the paper's worst case: mu_k (dl/l + 2 dT/T) */
  mu_k_err_worst: number;
  /** d mu_k in quadrature: mu_k sqrt((dl/l)^2 + (2 dT/T)^2) */
  mu_k_err_quadrature: number;
  /** mu_k through the thick formula, 2 pi^2 l / (g T^2 + 4 pi^2 h_c), with the request's h_c (the plate's centre of mass above the contact line) */
  mu_k_thick: number | null;
  /** [m] l used */
  spacing_m: number;
  /** the plate's amplitude in `amplitude_unit`: the least-squares sinusoid's at the strongest frequency of the positions read, or of the accelerometer's axis over omega^2 = (2 pi / T)^2 (a mean over the record, if the swing changes) */
  amplitude: number | null;
  /** the amplitude's unit: the position column's (`m`, `mm`, `px`), `m` from an accelerometer */
  amplitude_unit: string | null;
}
// end generated
