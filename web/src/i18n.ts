// The page's language and its words, by Mozilla's Fluent: one catalogue a language
// (../assets/locales/TAG.ftl, bundled by build.mjs), each message by its id. The language is the
// address's `?lang=TAG` where a catalogue offers it, else the first of the browser's languages that
// one offers (by its primary subtag: fr-CA is fr), else English. A message missing from the page's
// catalogue is English's; one missing from English too is its id. The words the lab itself writes
// (a refused set-up's problems, a file's reading error) come as the lab wrote them.
import { FluentBundle, FluentNumber, FluentResource, type FluentVariable } from "@fluent/bundle";
import catalogues from "frictionlab:catalogues";

/** Every message's fallback, and the page's language where nothing else is offered. */
export const FALLBACK_LANGUAGE = "en";

/** The languages the catalogues offer, by tag. */
export function languages(): string[] {
  return Object.keys(catalogues).sort();
}

/** The catalogue for a language tag: the same tag, else its primary subtag's (fr-CA: fr). */
export function offeredLanguage(tag: string): string | null {
  const wanted = tag.trim().toLowerCase();
  if (wanted === "") return null;
  const offered = languages();
  const same = offered.find((code) => code.toLowerCase() === wanted);
  if (same) return same;
  const primary = (tag: string) => tag.toLowerCase().split(/[-_]/)[0];
  return offered.find((code) => primary(code) === primary(wanted)) ?? null;
}

export interface LanguageChoice {
  language: string;
  /** Chosen by the address's `?lang=`: links the page makes carry it on. */
  byAddress: boolean;
}

/** The language for an address's query (`?lang=`) and the browser's languages, in its order. */
export function chooseLanguage(search: string, browser: readonly string[]): LanguageChoice {
  const asked = new URLSearchParams(search).get("lang");
  const fromAddress = asked === null ? null : offeredLanguage(asked);
  if (fromAddress) return { language: fromAddress, byAddress: true };
  for (const tag of browser) {
    const offered = offeredLanguage(tag);
    if (offered) return { language: offered, byAddress: false };
  }
  return { language: FALLBACK_LANGUAGE, byAddress: false };
}

let choice: LanguageChoice | null = null;

/** The page's language, chosen once from its address and the browser (English outside one). */
export function pageChoice(): LanguageChoice {
  if (choice) return choice;
  const search = typeof location === "undefined" ? "" : location.search;
  const browser =
    typeof navigator === "undefined"
      ? []
      : navigator.languages?.length
        ? navigator.languages
        : [navigator.language];
  choice = chooseLanguage(search, browser);
  return choice;
}

export function pageLanguage(): string {
  return pageChoice().language;
}

const bundles = new Map<string, FluentBundle>();

function bundleOf(language: string): FluentBundle | null {
  const made = bundles.get(language);
  if (made) return made;
  const text = catalogues[language];
  if (text === undefined) return null;
  // No Unicode isolation marks around the values: the page's languages are written left to
  // right, and its texts are read back by tests and screen readers as they show.
  const bundle = new FluentBundle(language, { useIsolating: false });
  bundle.addResource(new FluentResource(text));
  bundles.set(language, bundle);
  return bundle;
}

/** A message's values: a text as it is shown (a number the page rounded and wrote already), or a
 * number the message may choose by (one period, two periods), written without grouping. */
export type MessageArgs = Record<string, string | number>;

function fluentArgs(args: MessageArgs | undefined): Record<string, FluentVariable> | undefined {
  if (!args) return undefined;
  const out: Record<string, FluentVariable> = {};
  for (const [name, value] of Object.entries(args)) {
    out[name] =
      typeof value === "number"
        ? new FluentNumber(value, { useGrouping: false, maximumFractionDigits: 20 })
        : value;
  }
  return out;
}

const warned = new Set<string>();

/** Says once, on the console, what the catalogues lack: the page's tests fail on it. */
function warnOnce(what: string): void {
  if (warned.has(what)) return;
  warned.add(what);
  console.warn(`frictionlab: ${what}`);
}

/** The languages a message is looked for in: the page's, then English. */
function lookedIn(): string[] {
  const language = pageLanguage();
  return language === FALLBACK_LANGUAGE ? [language] : [language, FALLBACK_LANGUAGE];
}

function format(
  bundle: FluentBundle,
  pattern: Parameters<FluentBundle["formatPattern"]>[0],
  args: MessageArgs | undefined,
  id: string,
): string {
  const errors: Error[] = [];
  const text = bundle.formatPattern(pattern, fluentArgs(args), errors);
  for (const error of errors) warnOnce(`${bundle.locales[0]}: "${id}": ${error.message}`);
  return text;
}

/** The message `id` in the page's language, with its values; English's where the page's
 * catalogue lacks it, and the id itself where English's does too. */
export function t(id: string, args?: MessageArgs): string {
  for (const language of lookedIn()) {
    const bundle = bundleOf(language);
    const message = bundle?.getMessage(id);
    if (bundle && message?.value) return format(bundle, message.value, args, id);
  }
  warnOnce(`no message "${id}" in the catalogues`);
  return id;
}

/** Whether a catalogue, the page's or English, has the message `id`. */
export function hasMessage(id: string): boolean {
  return lookedIn().some((language) => bundleOf(language)?.hasMessage(id) ?? false);
}

/** A message's text (null where it has none) and its attributes (`.aria-label = ...`), in the
 * page's language, English's where it lacks the message; null where no catalogue has it. */
export function messageOf(
  id: string,
): { value: string | null; attributes: Record<string, string> } | null {
  for (const language of lookedIn()) {
    const bundle = bundleOf(language);
    const message = bundle?.getMessage(id);
    if (!bundle || !message) continue;
    const attributes: Record<string, string> = {};
    for (const [name, pattern] of Object.entries(message.attributes)) {
      attributes[name] = format(bundle, pattern, undefined, `${id}.${name}`);
    }
    const value = message.value ? format(bundle, message.value, undefined, id) : null;
    return { value, attributes };
  }
  warnOnce(`no message "${id}" in the catalogues`);
  return null;
}

/** Each catalogue's own name for its language (its message `language-name`), by tag. */
export function languageNames(): { tag: string; name: string }[] {
  return languages().map((tag) => {
    const bundle = bundleOf(tag);
    const message = bundle?.getMessage("language-name");
    const name = bundle && message?.value ? format(bundle, message.value, undefined, tag) : tag;
    return { tag, name };
  });
}
