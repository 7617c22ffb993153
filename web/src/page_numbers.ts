// The lab's numbers as the page shows them, in its language: format.ts's rule (the lab's one rule
// for a value with its uncertainty, held to the C++ one), with the decimal sign of the page's
// language: T = 0,7766 ± 0,0001 s in French. Plots' tick labels are written the same way.
import * as lab from "./format";
import { decimalSign, pageLocale } from "./locale_number";

const signs = new Map<string, string>();

/** A number's text (digits, ".", "-", "e") with the page's decimal sign in place of the point. */
export function inPageLanguage(text: string): string {
  const locale = pageLocale();
  let sign = signs.get(locale);
  if (sign === undefined) {
    sign = decimalSign(locale);
    signs.set(locale, sign);
  }
  return sign === "." ? text : text.replaceAll(".", sign);
}

/** format.ts's withError, in the page's language: "0,7912 ± 0,0012". */
export function withError(value: number, error: number | null, minDecimals = 2): string {
  return inPageLanguage(lab.withError(value, error, minDecimals));
}

/** format.ts's fixed, in the page's language: "0,792", or "—" for no number. */
export function fixed(value: number | null | undefined, decimals: number): string {
  return inPageLanguage(lab.fixed(value, decimals));
}

/** format.ts's significant, in the page's language: 0,000041. */
export function significant(value: number | null | undefined, digits = 2): string {
  return inPageLanguage(lab.significant(value, digits));
}

/** format.ts's trimmed, in the page's language: 89, 89,5, 1600. */
export function trimmed(value: number, decimals = 3): string {
  return inPageLanguage(lab.trimmed(value, decimals));
}

/** A plot's tick labels, as uPlot's own but in the page's language (uPlot's follow the browser's). */
export function tickLabels(): (u: unknown, splits: number[]) => string[] {
  const format = new Intl.NumberFormat(pageLocale());
  return (_u, splits) => splits.map((v) => (v === null || v === undefined ? "" : format.format(v)));
}
