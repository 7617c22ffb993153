// The regimes the lab names (src/core/regime.cpp's regime_name, a summary's `regime`) in the page's
// language, each by its message, with what each means in a sentence; a regime the catalogues lack
// shows as the lab wrote it. A live run's regime line adds when it began and the plate's jumps
// (src/lab/run/regime_monitor.cpp's regime_so_far: "clipped since t = 0.016 s; 2 jumps off a
// roller, up to 0.3 mm"), said in the page's words too.
import { hasMessage, t } from "./i18n";
import { inPageLanguage } from "./page_numbers";

export const REGIME_MESSAGES: Readonly<Record<string, string>> = {
  oscillates: "regime-oscillates",
  clipped: "regime-clipped",
  "stick-slip": "regime-stick-slip",
  grows: "regime-grows",
  decays: "regime-decays",
  sticks: "regime-sticks",
  tips: "regime-tips",
  "no restoring force": "regime-no-restoring-force",
  lost: "regime-lost",
  "numerically failed": "regime-numerically-failed",
};

/** What each regime means, in a sentence. */
export const REGIME_HELP: Readonly<Record<string, string>> = {
  oscillates: "regime-help-oscillates",
  clipped: "regime-help-clipped",
  "stick-slip": "regime-help-stick-slip",
  grows: "regime-help-grows",
  decays: "regime-help-decays",
  sticks: "regime-help-sticks",
  tips: "regime-help-tips",
  "no restoring force": "regime-help-no-restoring-force",
  lost: "regime-help-lost",
  "numerically failed": "regime-help-numerically-failed",
};

/** The regime a line names (its first words), and the rest of the line. */
function split(line: string): { regime: string; rest: string } {
  for (const regime of Object.keys(REGIME_MESSAGES)) {
    if (line === regime || line.startsWith(`${regime} `) || line.startsWith(`${regime};`)) {
      return { regime, rest: line.slice(regime.length) };
    }
  }
  return { regime: line, rest: "" };
}

const SINCE = /^ since t = ([\d.]+) s/;
const JUMPS = /^; (\d+) jumps? off a roller, up to ([\d.]+) mm$/;

/** The lab's regime line in the page's words. */
export function regimeWords(line: string): string {
  const { regime, rest } = split(line);
  const id = REGIME_MESSAGES[regime];
  if (id === undefined || !hasMessage(id)) return line;
  let words = t(id);
  let left = rest;
  const since = SINCE.exec(left);
  if (since) {
    words += t("regime-since", { t: inPageLanguage(since[1]!) });
    left = left.slice(since[0].length);
  }
  const jumps = JUMPS.exec(left);
  if (jumps) {
    words += t("regime-jumps", { jumps: Number(jumps[1]), height: inPageLanguage(jumps[2]!) });
    left = "";
  }
  return words + left;
}

/** What the line's regime means, or "" for a regime the page does not know. */
export function regimeHelp(line: string): string {
  const id = REGIME_HELP[split(line).regime];
  return id !== undefined && hasMessage(id) ? t(id) : "";
}
