// The rig in words, for a screen reader, in the manner of PhET's interactive descriptions: a
// sentence on the set-up (the 3D view's description), and a polite live region that says where
// the plate is and which way it moves, which roller carries more of its weight, and the period
// so far. While the run plays it speaks at most every ANNOUNCE_EVERY_MS, and only when the words
// changed; paused, it speaks once, on the pause; the run's end is said at once.
import { byId, setText } from "./dom";
import { t } from "./i18n";
import { fixed, trimmed, withError } from "./page_numbers";
import type { Lab, LabState, Rig } from "./lab_types";
import type { LabModel } from "./lab_model";
import type { Headline } from "./summary";
import { materialWords } from "./material_words";

const ANNOUNCE_EVERY_MS = 5000;
/** [m/s] slower than this the plate is said to be at rest */
const AT_REST = 0.001;
/** The rollers carry the same weight when their normal forces differ by less than this share. */
const SAME_SHARE = 0.01;

/** "12 mm left of centre": x [m] from the rollers' midpoint, positive to the right. */
export function whereThePlateIs(x: number): string {
  const mm = Math.round(Math.abs(x) * 1000);
  const side = mm === 0 ? "centre" : x < 0 ? "left" : "right";
  return t("plate-where", { side, mm });
}

/** The rollers' normal forces [N], left then right: the lab's contacts where it sent both and
 * has stepped (at t = 0, before the first step, they are not computed yet), else a thin plate's
 * under its own weight, N_left = m g (l/2 - x)/l, N_right = m g (l/2 + x)/l. */
export function normalForces(state: LabState, rig: Rig): [number, number] {
  const [left, right] = state.contacts;
  if (left && right && left.normal + right.normal > 0) return [left.normal, right.normal];
  const weight = rig.plate.mass * rig.gravity;
  const l = rig.spacing;
  return [(weight * (l / 2 - state.x)) / l, (weight * (l / 2 + state.x)) / l];
}

/** Which roller carries more of the plate's weight, in words. */
export function heavierRoller([left, right]: [number, number]): string {
  const newtons = (n: number) => trimmed(Math.max(0, n), 2);
  if (left <= 0 && right > 0) return t("rollers-one", { side: "right", newtons: newtons(right) });
  if (right <= 0 && left > 0) return t("rollers-one", { side: "left", newtons: newtons(left) });
  if (Math.abs(left - right) <= SAME_SHARE * (left + right)) {
    return t("rollers-same", { newtons: newtons(left) });
  }
  return t("rollers-more", {
    more: left > right ? "left" : "right",
    most: newtons(Math.max(left, right)),
    least: newtons(Math.min(left, right)),
  });
}

/** The period so far: the estimator's running estimate, or the finished run's result. */
export function periodSoFar(state: LabState, headline: Headline | null): string {
  if (headline) {
    return t("period-said-done", { period: withError(headline.period, headline.periodSd, 4) });
  }
  const e = state.estimate;
  if (!e) return t("period-said-none");
  return t("period-said-so-far", {
    period: withError(e.period, e.period_sd, 4),
    periods: e.periods_used,
  });
}

/** The plate's motion and forces and the period, without the time (what "changed" compares). */
function describeMotion(state: LabState, rig: Rig, headline: Headline | null): string {
  const motion = Math.abs(state.vx) < AT_REST ? "rest" : state.vx < 0 ? "left" : "right";
  return [
    t("plate-now", { where: whereThePlateIs(state.x), motion }),
    heavierRoller(normalForces(state, rig)),
    periodSoFar(state, headline),
  ].join(" ");
}

/** The set-up in a sentence: the rollers, the plate, where it starts, the theory's period. */
export function describeSetUp(rig: Rig, material: string): string {
  return t("set-up-said", {
    spacing: trimmed(rig.spacing * 1000, 1),
    sense: rig.roller_sense === "inward" ? "inward" : "outward",
    rpm: trimmed(rig.roller_speed_rpm, 0),
    material,
    length: trimmed(rig.plate.length * 1000, 0),
    mass: trimmed(rig.plate.mass * 1000, 0),
    start: whereThePlateIs(rig.offset),
    period: trimmed(rig.period_thin, 3),
  });
}

export class RigDescription {
  private readonly setUp = byId("rig-setup");
  private readonly now = byId("rig-now");
  private lastSaid = -Infinity;
  private lastMotion = "";

  /** It reads the model; `lab` gives the materials' names once the lab has answered. */
  constructor(
    private readonly model: LabModel,
    private readonly lab: () => Lab | null,
  ) {
    model.rig.link((rig) => this.showSetUp(rig));
    model.state.lazyLink((state) => {
      if (state === null) this.forget();
      else if (state.playing && !model.done.value) this.follow(state);
    });
    model.playing.lazyLink((playing) => {
      // A pause, unless it is the run's end (which says more, in the same task).
      if (!playing) queueMicrotask(() => this.sayPause());
    });
    model.done.lazyLink((done) => {
      const state = model.state.value;
      if (done && state) this.say("over", state);
    });
  }

  private sayPause(): void {
    const { state, playing, done } = this.model;
    if (state.value && !playing.value && !done.value) this.say("paused", state.value);
  }

  private showSetUp(rig: Rig | null): void {
    if (!rig) return;
    const key = rig.plate.material;
    const entry = this.lab()?.materials.find((m) => m.key === key);
    const material = entry ? materialWords(entry.key, entry.name) : (rig.paper?.material ?? key);
    setText(this.setUp, describeSetUp(rig, material));
    this.forget();
  }

  /** A playing run's state: said when the words changed and the last words are old enough. */
  private follow(state: LabState): void {
    if (performance.now() - this.lastSaid < ANNOUNCE_EVERY_MS) return;
    const rig = this.model.rig.value;
    if (!rig || describeMotion(state, rig, null) === this.lastMotion) return;
    this.say("playing", state);
  }

  private say(moment: "playing" | "paused" | "over", state: LabState): void {
    const rig = this.model.rig.value;
    if (!rig) return;
    this.lastMotion = describeMotion(state, rig, this.model.headline.value);
    this.lastSaid = performance.now();
    setText(this.now, t("moment-said", { moment, t: fixed(state.t, 1), motion: this.lastMotion }));
  }

  /** Back to t = 0: nothing to say until the run plays. */
  private forget(): void {
    this.lastSaid = -Infinity;
    this.lastMotion = "";
    setText(this.now, "");
  }
}
