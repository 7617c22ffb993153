// The page's rule for a student's name against the server's: problemOf (web/src/student_name.ts)
// accepts and refuses the names of tests/data/student_names.json as the server's is_student_name
// does (tests/serve/lab_server_test.cpp holds that one to the same file).
import { build } from "esbuild";
import { readFile } from "node:fs/promises";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
// The module alone: its DOM helpers are not called by problemOf.
const bundled = await build({
  entryPoints: [join(here, "../src/student_name.ts")],
  bundle: true,
  format: "esm",
  write: false,
  logLevel: "warning",
});
const module = await import(
  "data:text/javascript;base64," + Buffer.from(bundled.outputFiles[0].text).toString("base64")
);
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
