// Export: the finished run's files, a PNG of the 3D view, and a link to this set-up.
import { byId, byTestId } from "./dom";
import { fileHref, type SessionHandle } from "./lab_client";

const FILES = ["summary.json", "trajectory.csv", "hall.csv", "periods.csv"];

/** `/?scene=NAME&set=KEY%3DVALUE&set=...`: the page opens that set-up and plays it. */
export function setupLink(scene: string, entries: string[]): string {
  const params = new URLSearchParams([["scene", scene], ...entries.map((e) => ["set", e])]);
  // A shared server's token goes with the link, so that it opens for whoever is sent it.
  const token = new URLSearchParams(location.search).get("token");
  if (token !== null) params.append("token", token);
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

  constructor(viewPng: () => string) {
    byId("png").addEventListener("click", () => download(viewPng(), "frictionlab-view.png"));
    byId("copy-link").addEventListener("click", () => void this.copyLink());
    this.disableFiles();
  }

  disableFiles(): void {
    for (const { anchor } of this.links) {
      anchor.removeAttribute("href");
      anchor.setAttribute("aria-disabled", "true");
    }
  }

  /** Offers the run's files; a file the run did not keep stays disabled. */
  async enableFiles(session: SessionHandle): Promise<void> {
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
        this.copyStatus.textContent = "Select the link and copy it by hand.";
        return;
      }
    }
    this.copyStatus.textContent = "Copied.";
  }
}
