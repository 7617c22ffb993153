// The page's rule for a student's name against the server's: problemOf (web/src/student_name.ts)
// accepts and refuses the names of tests/data/student_names.json as the server's is_student_name
// does (tests/serve/lab_server_test.cpp holds that one to the same file).
import { readFile } from "node:fs/promises";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { importTs } from "./import_ts.mjs";

const here = dirname(fileURLToPath(import.meta.url));
const module = await importTs(join(here, "../src/student_name.ts"));
const cases = JSON.parse(await readFile(join(here, "../../tests/data/student_names.json"), "utf8"));
let failed = 0;
for (const name of cases.accepted) {
  if (module.problemOf(name) !== null) {
    console.error(`"${name}": the page refuses it, the server accepts it`);
    failed += 1;
  }
}
for (const name of cases.refused) {
  if (name !== "" && module.problemOf(name) === null) {
    console.error(`"${name}": the page accepts it, the server refuses it`);
    failed += 1;
  }
}
const total = cases.accepted.length + cases.refused.length;
console.log(`student names: ${total - failed} of ${total} as the server decides them`);
process.exit(failed === 0 ? 0 : 1);
