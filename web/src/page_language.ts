// The page in its language (i18n.ts chooses it): <html lang>, which the controls read and show
// numbers by (settings.ts: "89,5" in French); the static texts, each element with a
// `data-l10n-id` taking its message's text, and the attributes its `data-l10n-attrs` names
// (aria-label, title, placeholder) the message's attributes of those names; and the language
// switcher (#language), which opens the same address with `?lang=TAG`. Texts are set as text,
// never as HTML.
import { languageNames, messageOf, pageChoice, pageLanguage } from "./i18n";

/** Sets the page's language and its static texts: called before any control is made. */
export function showPageLanguage(): void {
  document.documentElement.lang = pageLanguage();
  translateElements(document);
  offerLanguages();
}

/** Every element under `root` with a `data-l10n-id`, in the page's language. */
export function translateElements(root: ParentNode): void {
  for (const element of root.querySelectorAll<HTMLElement>("[data-l10n-id]")) {
    const id = element.dataset["l10nId"] ?? "";
    const message = messageOf(id);
    if (!message) continue;
    if (message.value !== null) {
      // Its text only: an element it holds would be lost (index.html wraps text in a span).
      if (element.childElementCount > 0) console.warn(`frictionlab: "${id}" holds elements`);
      else element.textContent = message.value;
    }
    const names = (element.dataset["l10nAttrs"] ?? "").split(",").map((name) => name.trim());
    for (const name of names) {
      const value = message.attributes[name];
      if (name !== "" && value !== undefined) element.setAttribute(name, value);
    }
  }
}

/** The address of one of the lab's pages (`/class.html?token=...`), with `lang=` where this
 * page's language was chosen by its own address: a French link opens the next page in French. */
export function withPageLanguage(href: string): string {
  const { byAddress, language } = pageChoice();
  if (!byAddress) return href;
  const at = href.indexOf("?");
  const path = at < 0 ? href : href.slice(0, at);
  const query = new URLSearchParams(at < 0 ? "" : href.slice(at + 1));
  query.set("lang", language);
  return `${path}?${query.toString()}`;
}

/** The switcher: each catalogue's language by its own name; a choice opens this address again
 * with `?lang=`, its other parameters kept. */
function offerLanguages(): void {
  const select = document.getElementById("language");
  if (!(select instanceof HTMLSelectElement)) return;
  select.replaceChildren(
    ...languageNames().map(({ tag, name }) => {
      const option = new Option(name, tag);
      option.lang = tag;
      return option;
    }),
  );
  select.value = pageLanguage();
  select.addEventListener("change", () => {
    const address = new URL(location.href);
    address.searchParams.set("lang", select.value);
    location.assign(address.toString());
  });
}
