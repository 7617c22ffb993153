// The readouts: simulated time, run status, the estimator's period and mu_k, the regime and the
// rig's set-up. The estimate's block is written only when the estimate changes (once per accepted
// period), never at the stream's 30 Hz; a screen reader hears it through the rig's description
// (rig_description.ts), at most every few seconds, not at each period.
import { byTestId, setText } from "./dom";
import { t } from "./i18n";
import type { Lab, LabState, Rig } from "./lab_types";
import { fixed, significant, trimmed, withError } from "./page_numbers";
import { regimeHelp, regimeWords } from "./regime_words";
import type { Headline } from "./summary";
import { materialWords } from "./material_words";

export type RunStatus = "connecting" | "paused" | "playing" | "done" | "no session";

/** The run's status in the page's words. */
function statusWords(status: RunStatus): string {
  switch (status) {
    case "connecting":
      return t("run-status-connecting");
    case "paused":
      return t("run-status-paused");
    case "playing":
      return t("run-status-playing");
    case "done":
      return t("run-status-done");
    case "no session":
      return t("run-status-no-session");
  }
}

export class Readouts {
  private readonly time = byTestId("time");
  private readonly status = byTestId("status");
  private readonly failure = byTestId("failure");
  private readonly period = byTestId("period");
  private readonly periodDetail = byTestId("period-detail");
  private readonly muK = byTestId("mu-k");
  private readonly regime = byTestId("regime");
  private readonly regimeHelp = byTestId("regime-help");
  private readonly spacing = byTestId("spacing");
  private readonly speed = byTestId("speed");
  private readonly material = byTestId("material");
  private readonly theory = byTestId("theory");
  private lastEstimateKey = "";
  private finished = false;

  constructor() {
    setText(this.time, t("run-time", { t: fixed(0, 3) }));
  }

  setRig(rig: Rig, lab: Lab): void {
    this.reset();
    setText(this.spacing, t("spacing-value", { spacing: trimmed(rig.spacing * 1000, 1) }));
    const rpm = trimmed(rig.roller_speed_rpm, 0);
    setText(this.speed, t(rig.drive ? "rollers-value-driven" : "rollers-value", { rpm }));
    const entry = lab.materials.find((m) => m.key === rig.plate.material);
    const name = entry ? materialWords(entry.key, entry.name) : null;
    setText(this.material, name ? `${name} (${rig.plate.material})` : rig.plate.material);
    const parts = [
      t("theory-thin", { period: fixed(rig.period_thin, 3) }),
      rig.period_thick === null ? null : t("theory-thick", { period: fixed(rig.period_thick, 3) }),
      t("theory-mu-k", { muK: fixed(rig.mu_k, 3) }),
      rig.paper
        ? t("theory-paper", {
            period: withError(rig.paper.period, rig.paper.period_err),
            muK: withError(rig.paper.mu_k, rig.paper.mu_k_err),
          })
        : null,
    ];
    setText(this.theory, parts.filter((p) => p !== null).join(t("parts-separator")));
  }

  /** The lab's regime line in the page's words, and what the regime means. */
  private showRegime(line: string): void {
    setText(this.regime, regimeWords(line));
    setText(this.regimeHelp, regimeHelp(line));
  }

  /** Back to t = 0: no estimate, no regime yet. */
  reset(): void {
    this.finished = false;
    this.lastEstimateKey = "";
    setText(this.time, t("run-time", { t: fixed(0, 3) }));
    setText(this.period, t("period-none"));
    setText(this.periodDetail, t("period-detail-none"));
    setText(this.muK, t("mu-k-none"));
    setText(this.regime, "—");
    setText(this.regimeHelp, "");
    setText(this.failure, "");
  }

  setStatus(status: RunStatus): void {
    if (this.finished && status !== "done") return;
    setText(this.status, statusWords(status));
  }

  /** The run stopped: the lab's message, in the page's words. */
  setFailure(message: string): void {
    setText(this.failure, t("run-failure", { message }));
  }

  setState(state: LabState): void {
    setText(this.time, t("run-time", { t: fixed(state.t, 3) }));
    if (this.finished) return;
    this.setStatus(state.playing ? "playing" : "paused");
    if (state.regime) this.showRegime(state.regime);
    const e = state.estimate;
    const key = e ? `${e.periods_used}:${e.period}:${e.period_sd}` : "";
    if (!e || key === this.lastEstimateKey) return;
    this.lastEstimateKey = key;
    setText(this.period, t("period", { period: withError(e.period, e.period_sd, 4) }));
    this.period.dataset["value"] = String(e.period);
    const periods = e.periods_used;
    setText(
      this.periodDetail,
      e.period_sd === null
        ? t("period-detail-no-spread", { periods })
        : t("period-detail-spread", { periods, se: significant(e.period_se) }),
    );
    if (e.mu_k !== null) setText(this.muK, t("mu-k", { muK: withError(e.mu_k, e.mu_k_err, 3) }));
  }

  /** The run is over: the summary's headline replaces the running estimate. */
  setDone(headline: Headline | null): void {
    this.finished = true;
    setText(this.status, statusWords("done"));
    if (headline) {
      setText(
        this.period,
        t("period", { period: withError(headline.period, headline.periodSd, 4) }),
      );
      // T in seconds at full precision (data-value), for a test to hold against `frictionlab
      // run`'s period_s.
      this.period.dataset["value"] = String(headline.period);
      setText(this.periodDetail, t("period-detail-done", { se: significant(headline.periodSe) }));
      if (headline.muK !== null) {
        setText(this.muK, t("mu-k", { muK: withError(headline.muK, headline.muKErr, 3) }));
      }
      if (headline.regime) this.showRegime(headline.regime);
    }
  }
}
