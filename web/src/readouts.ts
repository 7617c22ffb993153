// The readouts: simulated time, run status, the estimator's period and mu_k, the regime and the
// rig's set-up. The estimate's block is written only when the estimate changes (once per accepted
// period), never at the stream's 30 Hz; a screen reader hears it through the rig's description
// (rig_description.ts), at most every few seconds, not at each period.
import { byTestId, setText } from "./dom";
import { fixed, trimmed, withError } from "./format";
import type { Lab, LabState, Rig } from "./lab_types";
import type { Headline } from "./summary";

export type RunStatus = "connecting" | "paused" | "playing" | "done" | "no session";

export class Readouts {
  private readonly time = byTestId("time");
  private readonly status = byTestId("status");
  private readonly failure = byTestId("failure");
  private readonly period = byTestId("period");
  private readonly periodDetail = byTestId("period-detail");
  private readonly muK = byTestId("mu-k");
  private readonly regime = byTestId("regime");
  private readonly spacing = byTestId("spacing");
  private readonly speed = byTestId("speed");
  private readonly material = byTestId("material");
  private readonly theory = byTestId("theory");
  private lastEstimateKey = "";
  private finished = false;

  setRig(rig: Rig, lab: Lab): void {
    this.reset();
    setText(this.spacing, `${trimmed(rig.spacing * 1000, 1)} mm`);
    setText(
      this.speed,
      `${trimmed(rig.roller_speed_rpm, 0)} rpm${rig.drive ? " (motor drive)" : ""}`,
    );
    const name = lab.materials.find((m) => m.key === rig.plate.material)?.name;
    setText(this.material, name ? `${name} (${rig.plate.material})` : rig.plate.material);
    const parts = [
      `thin plate T = ${fixed(rig.period_thin, 3)} s`,
      rig.period_thick === null ? null : `thick plate ${fixed(rig.period_thick, 3)} s`,
      `μₖ = ${fixed(rig.mu_k, 3)}`,
      rig.paper
        ? `paper: T = ${withError(rig.paper.period, rig.paper.period_err)} s, ` +
          `μₖ = ${withError(rig.paper.mu_k, rig.paper.mu_k_err)}`
        : null,
    ];
    setText(this.theory, parts.filter((p) => p !== null).join("; "));
  }

  /** Back to t = 0: no estimate, no regime yet. */
  reset(): void {
    this.finished = false;
    this.lastEstimateKey = "";
    setText(this.time, "t = 0.000 s");
    setText(this.period, "T = — s");
    setText(this.periodDetail, "no period accepted yet");
    setText(this.muK, "μₖ = —");
    setText(this.regime, "—");
    setText(this.failure, "");
  }

  setStatus(status: RunStatus): void {
    if (this.finished && status !== "done") return;
    setText(this.status, status);
  }

  setFailure(message: string): void {
    setText(this.failure, `The run stopped: ${message}`);
  }

  setState(state: LabState): void {
    setText(this.time, `t = ${state.t.toFixed(3)} s`);
    if (this.finished) return;
    this.setStatus(state.playing ? "playing" : "paused");
    if (state.regime) setText(this.regime, state.regime);
    const e = state.estimate;
    const key = e ? `${e.periods_used}:${e.period}:${e.period_sd}` : "";
    if (!e || key === this.lastEstimateKey) return;
    this.lastEstimateKey = key;
    setText(this.period, `T = ${withError(e.period, e.period_sd, 4)} s`);
    this.period.dataset["value"] = String(e.period);
    const periods = `${e.periods_used} period${e.periods_used === 1 ? "" : "s"}`;
    setText(
      this.periodDetail,
      e.period_sd === null
        ? `from ${periods}: no spread yet`
        : `± is the standard deviation of ${periods}; standard error ${fixed(e.period_se, 4)} s`,
    );
    if (e.mu_k !== null) setText(this.muK, `μₖ = ${withError(e.mu_k, e.mu_k_err, 3)}`);
  }

  /** The run is over: the summary's headline replaces the running estimate. */
  setDone(headline: Headline | null): void {
    this.finished = true;
    setText(this.status, "done");
    if (headline) {
      setText(this.period, `T = ${withError(headline.period, headline.periodSd, 4)} s`);
      // T in seconds at full precision (data-value), for a test to hold against `frictionlab
      // run`'s period_s.
      this.period.dataset["value"] = String(headline.period);
      setText(
        this.periodDetail,
        `the run's result: ± is the standard deviation; standard error ${fixed(headline.periodSe, 4)} s`,
      );
      if (headline.muK !== null) {
        setText(this.muK, `μₖ = ${withError(headline.muK, headline.muKErr, 3)}`);
      }
      if (headline.regime) setText(this.regime, headline.regime);
    }
  }
}
