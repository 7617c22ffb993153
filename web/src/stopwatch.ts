// The student's stopwatch: started and stopped by hand (the button, or Space when the focus is
// not in a control that Space types into or presses, the run's own buttons excepted: Space is the
// stopwatch's key and never pauses the run) to time ten periods. It shows the wall time and the
// simulated time between the presses, so it measures the plate's period in slow motion too, and
// it stops when the run ends.
import { byId, setText } from "./dom";
import { t } from "./i18n";
import { fixed } from "./page_numbers";
import type { LabModel } from "./lab_model";
import type { StopwatchTiming } from "./lab_types";

const PERIODS_TIMED = 10;

/** The run's buttons (Play or Pause, Step, Reset): Space there is the stopwatch's, so that a
 * student who has just pressed Play times the run without pausing it (Enter presses them). */
const RUN_BUTTONS = "#play, #step, #reset";

/** Space toggles the stopwatch unless it would also type, pick or press something. */
function spaceIsFree(target: EventTarget | null): boolean {
  if (!(target instanceof HTMLElement)) return true;
  if (target.isContentEditable) return false;
  if (target.closest(RUN_BUTTONS)) return true;
  return !target.closest("input, select, textarea, button, a[href], summary, [role='button']");
}

function isSpace(event: KeyboardEvent): boolean {
  return event.code === "Space" || event.key === " ";
}

export class Stopwatch {
  private readonly toggleButton = byId<HTMLButtonElement>("stopwatch-toggle");
  private readonly clearButton = byId<HTMLButtonElement>("stopwatch-clear");
  private readonly wall = byId("stopwatch-wall");
  private readonly simulated = byId("stopwatch-sim");
  private readonly estimator = byId("stopwatch-estimator");
  private wallStart = 0;
  private wallEnd = 0;
  private simStart: number | null = null;
  private simEnd: number | null = null;
  private running = false;
  private frame = 0;
  /** The timings made since the last Clear, for the lab report. */
  private made: StopwatchTiming[] = [];

  /** It reads the model (the run's time, the estimator's period), never another view. */
  constructor(private readonly model: LabModel) {
    model.period.lazyLink(() => this.showEstimator());
    this.toggleButton.addEventListener("click", () => this.toggle());
    this.clearButton.addEventListener("click", () => this.clear());
    document.addEventListener("keydown", (event) => {
      if (!isSpace(event)) return;
      if (event.ctrlKey || event.altKey || event.metaKey) return;
      if (!spaceIsFree(event.target)) return;
      event.preventDefault();
      if (!event.repeat) this.toggle();
    });
    // A button takes Space on its release: there, the run's buttons are not pressed.
    document.addEventListener("keyup", (event) => {
      if (
        isSpace(event) &&
        event.target instanceof HTMLElement &&
        event.target.closest(RUN_BUTTONS)
      )
        event.preventDefault();
    });
    // The run's end ends the timing: the wall clock would count on past the plate's last swing.
    model.done.lazyLink((done) => {
      if (done && this.running) this.stop();
    });
    this.clear();
  }

  toggle(): void {
    if (this.running) this.stop();
    else this.start();
  }

  private start(): void {
    this.running = true;
    this.wallStart = performance.now();
    this.simStart = this.simTime();
    this.toggleButton.textContent = t("stopwatch-stop");
    this.toggleButton.setAttribute("aria-pressed", "true");
    const tick = () => {
      this.show(performance.now(), this.simTime());
      this.frame = requestAnimationFrame(tick);
    };
    tick();
  }

  private stop(): void {
    cancelAnimationFrame(this.frame);
    this.running = false;
    this.wallEnd = performance.now();
    this.simEnd = this.simTime();
    this.toggleButton.textContent = t("stopwatch-start");
    this.toggleButton.setAttribute("aria-pressed", "false");
    this.show(this.wallEnd, this.simEnd);
    const wallS = (this.wallEnd - this.wallStart) / 1000;
    const simS =
      this.simEnd !== null && this.simStart !== null ? this.simEnd - this.simStart : null;
    if (wallS > 0) {
      this.made.push({
        periods: PERIODS_TIMED,
        wall_s: wallS,
        simulated_s: simS !== null && simS > 0 ? simS : null,
      });
    }
  }

  /** Every timing made since the last Clear. */
  timings(): StopwatchTiming[] {
    return [...this.made];
  }

  clear(): void {
    if (this.running) this.stop();
    this.made = [];
    this.wallStart = this.wallEnd = 0;
    this.simStart = this.simEnd = null;
    setText(this.wall, "—");
    setText(this.simulated, "—");
    this.showEstimator();
  }

  private show(wallNow: number, simNow: number | null): void {
    const wallS = (wallNow - this.wallStart) / 1000;
    setText(
      this.wall,
      t("stopwatch-timed", {
        total: fixed(wallS, 2),
        periods: PERIODS_TIMED,
        period: fixed(wallS / PERIODS_TIMED, 3),
      }),
    );
    const simS = simNow !== null && this.simStart !== null ? simNow - this.simStart : null;
    setText(
      this.simulated,
      simS === null || simS < 0
        ? "—"
        : t("stopwatch-timed", {
            total: fixed(simS, 3),
            periods: PERIODS_TIMED,
            period: fixed(simS / PERIODS_TIMED, 4),
          }),
    );
    this.showEstimator();
  }

  private simTime(): number | null {
    return this.model.state.value?.t ?? null;
  }

  /** Shows the estimator's period beside the hand-timed one. */
  private showEstimator(): void {
    const period = this.model.period.value;
    setText(this.estimator, period === null ? "—" : t("seconds", { seconds: fixed(period, 4) }));
  }
}
