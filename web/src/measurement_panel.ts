// Your measurement: a file the student chose, read by the lab's own readers (the instrument
// recognised from its content, as `frictionlab estimate` does), its T +- dT and mu_k with this
// set-up's spacing, shown beside the simulation's.
import { byTestId, setText } from "./dom";
import { t } from "./i18n";
import { estimateFile, LabError } from "./lab_client";
import { appendWords, problemWords } from "./lab_says";
import type { MeasurementEstimate } from "./lab_types";
import { trimmed, withError } from "./page_numbers";

const BUSY_TRIES = 10;
const BUSY_WAIT_MS = 2000;

export class MeasurementPanel {
  private readonly panel = byTestId("measurement-panel");
  private readonly input = byTestId<HTMLInputElement>("measurement-file");
  private readonly period = byTestId("measured-period");
  private readonly detail = byTestId("measured-detail");
  private readonly problem = byTestId("problem-measurement");
  private file: File | null = null;
  private spacing: number | null = null; // m, the set-up's l the shown mu_k was computed with
  private asked = 0; // the latest estimate asked for: an older answer is not shown
  private shown: MeasurementEstimate | null = null; // the estimate on screen, for the report

  constructor() {
    this.input.addEventListener("change", () => {
      this.file = this.input.files?.[0] ?? null;
      void this.estimate();
    });
    // A file dropped on the panel is read as a file chosen.
    this.panel.addEventListener("dragover", (event) => {
      if (!event.dataTransfer?.types.includes("Files")) return;
      event.preventDefault();
      event.dataTransfer.dropEffect = "copy";
      this.panel.classList.add("dropping");
    });
    this.panel.addEventListener("dragleave", () => this.panel.classList.remove("dropping"));
    this.panel.addEventListener("drop", (event) => {
      this.panel.classList.remove("dropping");
      const file = event.dataTransfer?.files[0];
      if (!file) return;
      event.preventDefault();
      this.file = file;
      void this.estimate();
    });
  }

  /** The set-up's spacing [m]: a file already read is read again with it. */
  setSpacing(spacing: number): void {
    if (spacing === this.spacing) return;
    this.spacing = spacing;
    if (this.file) void this.estimate();
  }

  private async estimate(): Promise<void> {
    const file = this.file;
    if (!file || this.spacing === null) return;
    const asked = ++this.asked;
    setText(this.problem, "");
    this.shown = null;
    setText(this.period, t("period-waiting"));
    setText(this.detail, t("measurement-reading", { file: file.name }));
    this.period.removeAttribute("data-value");
    try {
      // The server reads two files at once for the whole class: busy (503), it is asked again.
      for (let attempt = 1; ; attempt++) {
        try {
          const estimate = await estimateFile(file, file.name, this.spacing);
          if (asked === this.asked) this.show(estimate);
          return;
        } catch (error) {
          if (!(error instanceof LabError && error.status === 503) || attempt === BUSY_TRIES)
            throw error;
          if (asked !== this.asked) return;
          setText(this.detail, t("measurement-busy", { file: file.name }));
          await new Promise((resume) => setTimeout(resume, BUSY_WAIT_MS));
          if (asked !== this.asked) return;
        }
      }
    } catch (error) {
      if (asked !== this.asked) return;
      setText(this.period, t("period-none"));
      setText(this.detail, "");
      setText(this.problem, "");
      if (error instanceof LabError && error.problem) {
        // The lab's own words, in the page's language where its catalogue has them, after the
        // place in the file ("log.csv:3:5").
        const place = error.problem.value;
        appendWords(this.problem, problemWords(error.problem), place ? `${place}: ` : "");
      } else {
        setText(this.problem, error instanceof Error ? error.message : String(error));
      }
    }
  }

  /** The measurement on screen, as the lab's estimate answered it; null while there is none. */
  get measured(): MeasurementEstimate | null {
    return this.shown;
  }

  /** The file of the measurement on screen; null while there is none. */
  get measuredFile(): File | null {
    return this.shown ? this.file : null;
  }

  private show(e: MeasurementEstimate): void {
    this.shown = e;
    this.period.dataset.value = String(e.period_s);
    setText(this.period, t("period", { period: withError(e.period_s, e.period_std_s, 4) }));
    // The instrument and its channel are the lab's words.
    const instrument = e.channel === null ? e.instrument : `${e.instrument} (${e.channel})`;
    const result = t("measurement-result", {
      file: e.file,
      instrument,
      periods: e.periods_used,
      muK: withError(e.mu_k, e.mu_k_err_quadrature, 3),
      spacing: trimmed(e.spacing_m * 1e3, 1),
    });
    // A phone lying on the plate raises its centre of mass: the thin formula reads mu_k high.
    const phone = e.instrument.startsWith("phyphox accelerometer");
    setText(this.detail, phone ? `${result}. ${t("measurement-phone-note")}` : result);
  }
}
