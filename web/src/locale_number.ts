// Numbers typed and shown in the page's language: in French "89,5" is 89.5 mm, and the page shows
// 89,5 back. A number is read whole or refused, saying what was expected: never a number the user
// did not mean (a browser's number field reads "89,5" as 895 in some languages).
import { t } from "./i18n";

/** The page's language, which numbers are read and shown in ("89,5" in French): <html lang>,
 * which page_language.ts sets before any control is made. */
export function pageLocale(): string {
  // Outside a page (a test under node) there is no document: English.
  if (typeof document === "undefined") return "en";
  return document.documentElement.lang || "en";
}

/** The decimal sign of `locale`: "," in French and German, "." in English. */
export function decimalSign(locale: string): string {
  const parts = new Intl.NumberFormat(locale).formatToParts(1.5);
  return parts.find((part) => part.type === "decimal")?.value ?? ".";
}

export type NumberReading = { value: number } | { problem: string };

const NUMBER = /^[-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?$/;

/**
 * Reads a number typed in `locale`. The locale's decimal sign is the decimal sign; where that is
 * a comma a point is read as one too (no grouping is read, so neither is ambiguous). Where it is a
 * point, a comma is refused: "1,500" would be 1500 to one reader and 1.5 to another.
 */
export function readNumber(text: string, locale: string): NumberReading {
  const trimmed = text.trim().replace(/^−/, "-");
  const sign = decimalSign(locale);
  if (trimmed === "") return { problem: t("number-nothing") };
  if (sign === "." && trimmed.includes(",")) {
    return { problem: t("number-decimal-point", { text: trimmed }) };
  }
  const plain = sign === "," ? trimmed.replace(",", ".") : trimmed;
  if (!NUMBER.test(plain)) {
    return {
      problem: t("number-expected", { example: showNumber(89.5, 1, locale), text: trimmed }),
    };
  }
  return { value: Number(plain) };
}

/** Up to `decimals` decimals, trailing zeros dropped, with the locale's decimal sign: 89,5. */
export function showNumber(value: number, decimals: number, locale: string): string {
  const text = String(Number(value.toFixed(decimals)));
  if (/e/i.test(text)) return text; // far from any control's range; kept exact
  return text.replace(".", decimalSign(locale));
}
