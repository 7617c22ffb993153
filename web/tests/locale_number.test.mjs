// Numbers typed and shown in the page's language (web/src/locale_number.ts): what is shown reads
// back as the same number in every language; it is what Intl (the browser's own formatter) writes;
// a comma in French is a decimal comma; what could mean two numbers is refused, never guessed.
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { importTs } from "./import_ts.mjs";

const here = dirname(fileURLToPath(import.meta.url));
const { readNumber, showNumber } = await importTs(join(here, "../src/locale_number.ts"));
let failed = 0;
const fail = (message) => {
  console.error(message);
  failed += 1;
};
const reads = (text, locale, value) => {
  const got = readNumber(text, locale);
  if (!("value" in got) || got.value !== value) {
    fail(`readNumber("${text}", ${locale}): ${JSON.stringify(got)}, expected ${value}`);
  }
};
const refuses = (text, locale, words) => {
  const got = readNumber(text, locale);
  if (!("problem" in got) || !got.problem.includes(words)) {
    fail(`readNumber("${text}", ${locale}): ${JSON.stringify(got)}, expected a problem "${words}"`);
  }
};

reads("89,5", "fr", 89.5);
reads("89.5", "fr", 89.5);
reads(" 89,5 ", "de", 89.5);
reads("-0,25", "es", -0.25);
reads("89.5", "en", 89.5);
reads("1e-3", "en", 0.001);
reads("120", "fr", 120);
refuses("89,5", "en", "decimal point");
refuses("1,500", "en", "decimal point");
refuses("1 000", "fr", "expected a number");
refuses("1.000,5", "de", "expected a number");
refuses("12mm", "en", "expected a number");
refuses("", "fr", "found nothing");
if (showNumber(89.5, 1, "fr") !== "89,5")
  fail(`showNumber(89.5, fr): ${showNumber(89.5, 1, "fr")}`);

// Random values at a control's decimals: shown as Intl shows them without grouping, and read back.
let seed = 12345;
const random = () => (seed = (seed * 1103515245 + 12345) % 2 ** 31) / 2 ** 31;
let count = 0;
for (const locale of ["en", "fr", "de", "es"]) {
  for (let i = 0; i < 500; i += 1) {
    const decimals = i % 5;
    const value = (random() - 0.3) * 10 ** (1 + (i % 4));
    const shown = showNumber(value, decimals, locale);
    const intl = new Intl.NumberFormat(locale, {
      useGrouping: false,
      maximumFractionDigits: decimals,
    }).format(value);
    // A value that rounds to zero is 0, never Intl's "-0".
    if (shown !== intl.replace("−", "-").replace(/^-0$/, "0"))
      fail(`${locale} ${value}: shown "${shown}", Intl "${intl}"`);
    const back = readNumber(shown, locale);
    if (!("value" in back) || back.value !== Number(value.toFixed(decimals))) {
      fail(`${locale} ${value}: "${shown}" reads back as ${JSON.stringify(back)}`);
    }
    count += 1;
  }
}
console.log(`locale numbers: ${count} values shown as Intl shows them and read back`);
process.exit(failed === 0 ? 0 : 1);
