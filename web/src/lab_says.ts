// The lab's own messages in the page's language. The lab sends each problem as it wrote it in
// English and, where the catalogues hold it, as a message id with its values (docs/web-api.md's
// `Said`); the page says that message from its catalogue, its numbers in the page's way of
// writing them. A message the lab wrote in English only is shown as written, marked as English
// (lang="en") for a screen reader to read it as English.
import type { Problem, Said } from "./api_types";
import { hasMessage, pageLanguage, t, type MessageArgs } from "./i18n";

/** A lab's message as the page shows it: its text, and its language where not the page's. */
export interface LabWords {
  text: string;
  /** "en" where the text is the lab's English on a page in another language; else null */
  lang: string | null;
}

/** The numbers of a message, as the lab writes them in English: six significant digits. */
function sixDigits(value: number): number {
  return Number.isFinite(value) ? Number(value.toPrecision(6)) : value;
}

/** The message in the page's language, or null where no catalogue has it (or one it quotes). */
function saidText(said: Said): string | null {
  if (!hasMessage(said.id)) return null;
  const args: MessageArgs = {};
  for (const value of said.args) {
    if (typeof value.number === "number") args[value.name] = sixDigits(value.number);
    else if (typeof value.text === "string") args[value.name] = value.text;
    else if (value.said) {
      const quoted = saidText(value.said);
      if (quoted === null) return null;
      args[value.name] = quoted;
    }
  }
  return t(said.id, args);
}

/** What the lab said (`said`, else its English `message`) in the words the page shows. */
export function labWords(said: Said | null | undefined, message: string): LabWords {
  const text = said ? saidText(said) : null;
  if (text !== null) return { text, lang: null };
  return { text: message, lang: pageLanguage() === "en" ? null : "en" };
}

/** A refusal's body (docs/web-api.md's ErrorBody) in the page's words: its `said` in the page's
 * language where a catalogue has it, else its English `error`, else `fallback` (the page's own). */
export function errorWords(body: unknown, fallback: string): string {
  const { error, said } = (body ?? {}) as { error?: unknown; said?: Said | null };
  if (typeof error !== "string" || !error) return fallback;
  return labWords(said, error).text;
}

/** A problem the lab found, in the page's words. */
export function problemWords(problem: Problem): LabWords {
  return labWords(problem.said, problem.message);
}

/** Adds the words to `element` after what it holds, as a span marked with their language. */
export function appendWords(element: HTMLElement, words: LabWords, prefix = ""): void {
  if (element.childNodes.length > 0) element.append(" ");
  const span = document.createElement("span");
  span.textContent = prefix + words.text;
  if (words.lang) span.lang = words.lang;
  element.append(span);
}
