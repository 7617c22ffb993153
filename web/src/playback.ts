// Playback: play/pause (one button), a single step, slow motion and reset.
import { byId, setText } from "./dom";
import { t } from "./i18n";
import type { PlaybackSpeed } from "./lab_types";

export interface PlaybackActions {
  toggle: () => void;
  step: () => void;
  reset: () => void;
  speed: (speed: PlaybackSpeed) => void;
}

const SPEEDS: PlaybackSpeed[] = [1, 0.25, 0.0625];

export class Playback {
  private readonly play = byId<HTMLButtonElement>("play");
  private readonly step = byId<HTMLButtonElement>("step");
  private readonly reset = byId<HTMLButtonElement>("reset");
  private readonly slowMotion = byId<HTMLSelectElement>("slow-motion");

  constructor(actions: PlaybackActions) {
    this.play.addEventListener("click", () => actions.toggle());
    this.step.addEventListener("click", () => actions.step());
    this.reset.addEventListener("click", () => actions.reset());
    this.slowMotion.addEventListener("change", () => actions.speed(this.speed));
    this.show({ playing: false, done: false, ready: false });
  }

  get speed(): PlaybackSpeed {
    const chosen = Number(this.slowMotion.value);
    return SPEEDS.find((s) => s === chosen) ?? 1;
  }

  /** Shows the server's speed (another tab may have set it). */
  showSpeed(speed: PlaybackSpeed): void {
    if (this.speed !== speed) this.slowMotion.value = String(speed);
  }

  show(run: { playing: boolean; done: boolean; ready: boolean }): void {
    setText(this.play, t(run.playing ? "run-pause" : run.done ? "run-play-again" : "run-play"));
    this.play.setAttribute("aria-pressed", String(run.playing));
    this.play.disabled = !run.ready;
    this.step.disabled = !run.ready || run.playing || run.done;
    this.reset.disabled = !run.ready;
  }
}
