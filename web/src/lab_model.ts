// The page's model: what the lab's session says, as observable properties (web/src/property.ts).
// Only the controller (web/src/main.ts) writes them, from the session's events and the user's
// commands; the views (the 3D view, the plots, the readouts, the stopwatch, the playback buttons)
// read them, and none reads another view.
import type { LabState, Rig } from "./lab_types";
import { Property } from "./property";
import type { Headline } from "./summary";

export class LabModel {
  /** The set-up the session runs (null before the first). */
  readonly rig = new Property<Rig | null>(null);
  /** The run's latest state (null at t = 0: a new set-up or a reset). */
  readonly state = new Property<LabState | null>(null);
  readonly playing = new Property(false);
  /** The run has reached its end (its summary came). */
  readonly done = new Property(false);
  /** The finished run's headline (null before the end, or without a period). */
  readonly headline = new Property<Headline | null>(null);
  /** The rig's estimator's period: the run's result once done, else the running estimate. */
  readonly period = new Property<number | null>(null);

  /** A new state from the lab: a time before the last one means the run started again. */
  setState(state: LabState): void {
    const last = this.state.value;
    if (last && state.t < last.t - 1e-9) this.clearRun();
    this.state.value = state;
    if (this.headline.value === null) this.period.value = state.estimate?.period ?? null;
    this.playing.value = state.playing;
  }

  /** The run is over: its summary's headline. */
  finish(headline: Headline | null): void {
    this.headline.value = headline;
    if (headline) this.period.value = headline.period;
    this.playing.value = false;
    this.done.value = true;
  }

  /** Back to t = 0 of the same set-up. */
  clearRun(): void {
    this.done.value = false;
    this.headline.value = null;
    this.period.value = null;
    this.state.value = null;
  }
}
