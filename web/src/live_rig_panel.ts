// The live rig (docs/web-api.md, "The live rig"): the real rig's Arduino on a serial port of the
// lab's computer, its Hall signal, its periods and its T and mu_k by the rig's estimator with
// this session's spacing, beside the simulation of the same set-up. GET /api/rig gives the
// ports and the port's state, asked every 2 s while no rig events come; the rig events on the
// session's stream bring the samples, the periods and the estimate. A lab without the live rig
// (404) hides the panel.
import { byId, byTestId, setText } from "./dom";
import { t } from "./i18n";
import { fixed, significant, trimmed, withError } from "./page_numbers";
import { closeRig, getRig, LabError, openRig, RIG_PORTS_LISTED, rigLogHref } from "./lab_client";
import type { Estimate, LiveRig, PulseGeometry, LiveRigEvent } from "./lab_types";
import { PeriodsTable } from "./periods_table";
import { RigPlot } from "./live_rig_plot";
import { appendWords, labWords } from "./lab_says";

const POLL_MS = 2000;

export interface RigPanelActions {
  /** This page opened a port: run the simulation from t = 0 at 1x beside the rig. */
  connected: () => void;
}

/** The port's state, from GET /api/rig or a rig event, whichever came last. */
type PortStatus = Pick<LiveRigEvent, "port" | "state" | "message" | "said" | "lines">;

/** The keys of PortStatus taken from a status or an event. */
function portStatusOf({ port, state, message, said, lines }: PortStatus): PortStatus {
  return { port, state, message, said, lines };
}

function linesOf(count: number): string {
  return t("rig-lines", { lines: count });
}

/** The state in plain words, e.g. "receiving from /dev/ttyACM0, 5123 lines". */
function stateWords(status: PortStatus): string {
  const port = status.port ?? t("rig-the-port");
  const lines = linesOf(status.lines);
  switch (status.state) {
    case "closed":
      return status.port === null
        ? t("rig-state-none")
        : t("rig-state-closed", { port: status.port, lines });
    case "waiting":
      return t("rig-state-waiting", { port });
    case "receiving":
      return t("rig-state-receiving", { port, lines });
    case "unplugged":
      return t("rig-state-unplugged", { port, lines });
    case "failed":
      return t("rig-state-failed", { port });
    default:
      return t("rig-state-other", { state: t("rig-port-state", { state: status.state }), port });
  }
}

function geometryWords(geometry: PulseGeometry): string {
  switch (geometry) {
    case "one-pulse":
      return t("rig-geometry-one-pulse");
    case "pair":
      return t("rig-geometry-pair");
    default:
      return t("rig-geometry-unknown");
  }
}

function paragraph(text: string, className: string): HTMLParagraphElement {
  const p = document.createElement("p");
  p.className = className;
  p.textContent = text;
  return p;
}

export class RigPanel {
  private readonly section = byTestId("rig-panel");
  private readonly details = byId<HTMLDetailsElement>("rig-details");
  private readonly summary = byId("rig-summary");
  private readonly portSelect = byTestId<HTMLSelectElement>("rig-port");
  private readonly connectButton = byTestId<HTMLButtonElement>("rig-connect");
  private readonly closeButton = byTestId<HTMLButtonElement>("rig-close");
  private readonly chooseNote = byId("rig-choose-note");
  private readonly stateLine = byTestId("rig-state");
  private readonly problem = byId("rig-problem");
  private readonly estimate = byTestId("rig-estimate");
  private readonly logLink = byTestId<HTMLAnchorElement>("rig-log");
  private readonly plot = new RigPlot(byTestId("rig-plot"));
  private readonly periods = new PeriodsTable(
    byTestId<HTMLTableSectionElement>("rig-periods"),
    byId("rig-periods-tally"),
    {
      newestFirst: true,
      decimals: 6, // to the microsecond, as `frictionlab estimate` prints it
      maxRows: 300,
      periodTestId: "rig-period",
      accepted: t("periods-accepted"),
      rejected: t("periods-rejected"),
    },
  );
  private rig: LiveRig | null = null;
  private status: PortStatus = {
    port: null,
    state: "closed",
    message: null,
    said: null,
    lines: 0,
  };
  /** The board's run the plot and periods show; null before a rig event. */
  private run: number | null = null;
  private lastEventAt = -Infinity;
  private timer = 0;
  private polling = false;
  private asking = false;
  /** The panel opens by itself once, when a port or a rig shows; after that it is the user's. */
  private openedItself = false;
  private estimateKey = "";
  /** The lines the log's link holds, and when it was pointed (performance.now()). */
  private logLines = -1;
  private logAt = -Infinity;
  private logTimer = 0;

  constructor(private readonly actions: RigPanelActions) {
    this.connectButton.addEventListener("click", () => void this.connect());
    this.closeButton.addEventListener("click", () => void this.close());
    this.portSelect.addEventListener("change", () => this.showButtons());
    this.clearRun();
    this.showStatus();
  }

  /** Asks GET /api/rig now and every 2 s while no rig events come. */
  start(): void {
    if (this.timer) return;
    void this.poll();
    this.timer = window.setInterval(() => {
      if (document.hidden || performance.now() - this.lastEventAt < POLL_MS) return;
      void this.poll();
    }, POLL_MS);
  }

  /** Asks nothing more (the lab stopped). */
  stop(): void {
    window.clearInterval(this.timer);
    this.timer = 0;
  }

  /** Empty plot, periods and estimate: a new session (another spacing), or a new board run. */
  clearRun(): void {
    this.run = null;
    this.plot.clear();
    this.periods.clear();
    this.showEstimate(null, 0, "unknown");
  }

  /** A rig event from the session's stream. */
  showEvent(event: LiveRigEvent): void {
    this.lastEventAt = performance.now();
    if (this.run !== null && event.run !== this.run) this.clearRun();
    this.run = event.run;
    this.status = portStatusOf(event);
    this.plot.push(event.hall, event.periods);
    this.periods.add(event.periods);
    this.showEstimate(event.estimate, event.spacing, event.geometry);
    this.showStatus();
    // What only GET /api/rig says (the log's name, the ports) may have changed with the port.
    const known = this.rig;
    if (known && (event.port !== known.port || (event.lines > 0 && known.log_name === null))) {
      void this.poll();
    }
  }

  private async poll(): Promise<void> {
    if (this.polling) return;
    this.polling = true;
    try {
      this.showRig(await getRig());
      setText(this.problem, "");
    } catch (error) {
      if (error instanceof LabError && error.status === 404) {
        // A lab without the live rig: nothing to show, nothing to ask again.
        this.stop();
        this.section.hidden = true;
        return;
      }
      this.showProblem(error);
    } finally {
      this.polling = false;
    }
  }

  private async connect(): Promise<void> {
    const port = this.portSelect.value;
    if (!port) return;
    if (await this.ask(() => openRig(port))) {
      this.clearRun();
      this.actions.connected();
    }
  }

  private async close(): Promise<void> {
    await this.ask(() => closeRig());
  }

  private async ask(request: () => Promise<LiveRig>): Promise<boolean> {
    this.asking = true;
    this.showButtons();
    try {
      this.showRig(await request());
      setText(this.problem, "");
      return true;
    } catch (error) {
      this.showProblem(error);
      return false;
    } finally {
      this.asking = false;
      this.showButtons();
    }
  }

  private showProblem(error: unknown): void {
    const message = error instanceof Error ? error.message : String(error);
    setText(this.problem, t("rig-problem", { message }));
  }

  private showRig(rig: LiveRig): void {
    this.rig = rig;
    this.showPorts(rig);
    this.status = portStatusOf(rig);
    const name = rig.log_name ?? "rig.log";
    this.logLink.download = name;
    setText(this.logLink, t("rig-log-named", { name }));
    this.chooseNote.hidden = rig.may_choose;
    this.showStatus();
  }

  /** The port list, keeping the one chosen while it is listed; a page that may not choose is
   * shown the port open (a shared server lists no ports). */
  private showPorts(rig: LiveRig): void {
    const ports = rig.ports.length > 0 || rig.port === null ? rig.ports : [rig.port];
    const listed = Array.from(this.portSelect.options, (o) => o.value);
    const chosen = this.portSelect.value;
    if (listed.join("\n") !== (ports.length > 0 ? ports : [""]).join("\n")) {
      this.portSelect.replaceChildren();
      for (const port of ports) this.portSelect.append(new Option(port, port));
      if (ports.length === 0) this.portSelect.append(new Option(t("rig-no-port-found"), ""));
    }
    const keep = ports.includes(chosen) ? chosen : null;
    const open = rig.port !== null && ports.includes(rig.port) ? rig.port : null;
    this.portSelect.value = keep ?? open ?? ports[0] ?? "";
  }

  private showStatus(): void {
    const status = this.status;
    // The port's state in the page's words, then the lab's message in the page's language where
    // its catalogue has it (marked English where not).
    setText(this.stateLine, stateWords(status) + (status.message ? "." : ""));
    if (status.message) appendWords(this.stateLine, labWords(status.said, status.message));
    this.stateLine.dataset["state"] = status.state;
    this.logLink.hidden = status.lines <= 0;
    this.offerLog(status);
    const ports = this.rig?.ports.length ?? 0;
    const rigShown = status.state !== "closed" || status.lines > 0;
    const state = t("rig-port-state", { state: status.state });
    setText(
      this.summary,
      rigShown
        ? status.lines > 0
          ? `${state}, ${linesOf(status.lines)}`
          : state
        : !RIG_PORTS_LISTED
          ? ports > 0
            ? t("rig-summary-connect")
            : t("rig-summary-no-web-serial")
          : ports > 0
            ? t("rig-summary-ports", { ports })
            : t("rig-no-port-found"),
    );
    this.section.classList.toggle("quiet", !rigShown && ports === 0);
    if (!this.openedItself && (rigShown || ports > 0)) {
      this.openedItself = true;
      this.details.open = true;
    }
    this.showButtons();
  }

  /** Points the log's link at the log as it stands: at most every 2 s while lines come, and once
   * more when they stop. */
  private offerLog(status: PortStatus): void {
    const receiving = status.state === "receiving" || status.state === "waiting";
    const stale = status.lines !== this.logLines;
    if (status.lines <= 0 || !stale) return;
    if (receiving && performance.now() - this.logAt < POLL_MS) {
      // Once more when the lines may have stopped coming.
      if (!this.logTimer)
        this.logTimer = window.setTimeout(() => {
          this.logTimer = 0;
          this.offerLog(this.status);
        }, POLL_MS);
      return;
    }
    this.logLines = status.lines;
    this.logAt = performance.now();
    void rigLogHref()
      .then((href) => (this.logLink.href = href))
      .catch(() => (this.logLines = -1));
  }

  private showButtons(): void {
    const mayChoose = this.rig?.may_choose ?? false;
    this.portSelect.disabled = !mayChoose || (this.rig?.ports.length ?? 0) === 0;
    this.connectButton.disabled = this.asking || !mayChoose || this.portSelect.value === "";
    // Only an open port closes: an unplugged or failed one has closed already.
    const open = this.status.state === "waiting" || this.status.state === "receiving";
    this.closeButton.disabled = this.asking || !mayChoose || !open;
  }

  private showEstimate(estimate: Estimate | null, spacing: number, geometry: PulseGeometry): void {
    const key = estimate === null ? "" : JSON.stringify([estimate, spacing, geometry]);
    if (key === this.estimateKey && this.estimate.textContent !== "") return;
    this.estimateKey = key;
    if (estimate === null) {
      this.estimate.replaceChildren("—");
      return;
    }
    const n = estimate.periods_used;
    const detail = [
      t("rig-estimate-periods", { periods: n }),
      estimate.period_se === null
        ? null
        : t("rig-estimate-se", { se: significant(estimate.period_se) }),
      t("rig-estimate-spacing", { spacing: trimmed(spacing * 1000, 1) }),
      geometryWords(geometry),
      t("rig-estimate-note"),
    ];
    this.estimate.replaceChildren(
      paragraph(t("period", { period: withError(estimate.period, estimate.period_sd, 4) }), "big"),
      paragraph(
        estimate.mu_k === null
          ? t("mu-k-none")
          : t("mu-k", { muK: withError(estimate.mu_k, estimate.mu_k_err, 3) }),
        "big",
      ),
      paragraph(detail.filter((d) => d !== null).join(t("parts-separator")), "detail"),
    );
  }
}
