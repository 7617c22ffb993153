// The page's numbers against the lab's: withErrorSign (web/src/format.ts) gives, for every case
// of tests/data/plus_minus_cases.json, the text the C++ plus_minus gives (tests/io/
// plus_minus_test.cpp holds that one to the same file): one rule for a value with its uncertainty.
import { readFile } from "node:fs/promises";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { importTs } from "./import_ts.mjs";

const here = dirname(fileURLToPath(import.meta.url));
const format = await importTs(join(here, "../src/format.ts"));
const { cases } = JSON.parse(
  await readFile(join(here, "../../tests/data/plus_minus_cases.json"), "utf8"),
);
let failed = 0;
for (const c of cases) {
  const text = format.withErrorSign(c.value, c.uncertainty, c.min_decimals, "+-");
  if (text !== c.text) {
    console.error(
      `withErrorSign(${c.value}, ${c.uncertainty}, ${c.min_decimals}): "${text}", the lab gives "${c.text}"`,
    );
    failed += 1;
  }
}
if (cases.length < 10) {
  console.error(`only ${cases.length} cases`);
  failed += 1;
}
console.log(`format: ${cases.length - failed} of ${cases.length} cases as the lab gives them`);
process.exit(failed === 0 ? 0 : 1);
