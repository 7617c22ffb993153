// Export: the finished run's files, a PNG of the 3D view, and a link to this set-up.
import { byId, byTestId } from "./dom";
import { pageChoice, t } from "./i18n";
import { fileHref, reportHtml, type SessionHandle } from "./lab_client";
import type { ReportAsk } from "./lab_types";

const FILES = ["summary.json", "trajectory.csv", "hall.csv", "periods.csv"];

/** `/?scene=NAME&set=KEY%3DVALUE&set=...`: the page opens that set-up and plays it. */
export function setupLink(scene: string, entries: string[]): string {
  const params = new URLSearchParams([["scene", scene], ...entries.map((e) => ["set", e])]);
  // A shared server's token goes with the link, so that it opens for whoever is sent it.
  const token = new URLSearchParams(location.search).get("token");
  if (token !== null) params.append("token", token);
  // A language the page was asked for goes too: a teacher's French link opens in French.
  const { byAddress, language } = pageChoice();
  if (byAddress) params.append("lang", language);
  // The page's own address: the static site may be served from any folder of a web space.
  return `${location.origin}${location.pathname}?${params.toString()}`;
}

function download(href: string, name: string): void {
  const anchor = document.createElement("a");
  anchor.href = href;
  anchor.download = name;
  document.body.append(anchor);
  anchor.click();
  anchor.remove();
}

export class ExportPanel {
  private readonly links = FILES.map((name) => ({
    name,
    anchor: byTestId<HTMLAnchorElement>(`file-${name.split(".")[0]}`),
  }));
  private readonly linkField = byId<HTMLInputElement>("setup-link");
  private readonly copyStatus = byId("copy-status");
  private readonly reportButton = byId<HTMLButtonElement>("export-report");
  private readonly reportHint = byId("report-hint");
  private finished: SessionHandle | null = null;

  /** `reportAsk`: who hands the report in and what the stopwatch timed, when it is asked. */
  constructor(viewPng: () => string, reportAsk: () => Promise<ReportAsk>) {
    byId("png").addEventListener("click", () => download(viewPng(), "frictionlab-view.png"));
    byId("copy-link").addEventListener("click", () => void this.copyLink());
    this.reportButton.addEventListener("click", () => void this.report(reportAsk()));
    this.disableFiles();
  }

  disableFiles(): void {
    for (const { anchor } of this.links) {
      anchor.removeAttribute("href");
      anchor.setAttribute("aria-disabled", "true");
    }
    this.finished = null;
    this.reportButton.disabled = true;
  }

  /** The lab report of the finished run, downloaded as report.html. */
  private async report(asking: Promise<ReportAsk>): Promise<void> {
    if (!this.finished) return;
    this.reportHint.textContent = t("export-report-writing");
    try {
      const html = await reportHtml(this.finished, await asking);
      download(URL.createObjectURL(new Blob([html], { type: "text/html" })), "report.html");
      this.reportHint.textContent = t("export-report-done");
    } catch (error) {
      this.reportHint.textContent = error instanceof Error ? error.message : String(error);
    }
  }

  /** Offers the run's files; a file the run did not keep stays disabled. */
  async enableFiles(session: SessionHandle): Promise<void> {
    this.finished = session;
    this.reportButton.disabled = false;
    for (const { name, anchor } of this.links) {
      try {
        anchor.href = await fileHref(session, name);
      } catch {
        continue;
      }
      anchor.download = name;
      anchor.removeAttribute("aria-disabled");
    }
  }

  showLink(scene: string, entries: string[]): void {
    this.linkField.value = setupLink(scene, entries);
    this.copyStatus.textContent = "";
  }

  private async copyLink(): Promise<void> {
    const text = this.linkField.value;
    try {
      await navigator.clipboard.writeText(text);
    } catch {
      this.linkField.select();
      if (!document.execCommand("copy")) {
        this.copyStatus.textContent = t("export-copy-by-hand");
        return;
      }
    }
    this.copyStatus.textContent = t("export-copied");
  }
}
