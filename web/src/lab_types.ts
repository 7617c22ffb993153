// The shapes of the lab's web API (docs/web-api.md): what the server sends is web/src/api_types.ts,
// written from the lab's declaration; here only what the page sends.
export * from "./api_types";
import type { MeasurementEstimate } from "./api_types";

export type ControlAction = "play" | "pause" | "step" | "reset";

/** Periods timed by hand with the page's stopwatch, for the lab report. */
export interface StopwatchTiming {
  periods: number;
  wall_s: number;
  simulated_s: number | null;
}

/** What `POST /api/sessions/ID/report` takes: who hands it in, what the stopwatch timed, in
 * which language. */
export interface ReportAsk {
  student?: string;
  stopwatch?: StopwatchTiming[];
  /** The report's language: the page's ("en", "fr"). */
  language?: string;
  /** The student's measurement, as `POST /api/estimate` answered it: a part of the report. */
  measurement?: MeasurementEstimate;
  /** Its file, read again for the report's signal and periods (beside `measurement`). */
  measurement_file?: { name: string; base64: string };
}
