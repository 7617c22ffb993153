// The regimes the lab names (src/core/regime.cpp's regime_name, a summary's `regime`) in the page's
// language, each by its message; a regime the catalogues lack shows as the lab wrote it.
import { hasMessage, t } from "./i18n";

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

export function regimeWords(regime: string): string {
  const id = REGIME_MESSAGES[regime];
  return id !== undefined && hasMessage(id) ? t(id) : regime;
}
