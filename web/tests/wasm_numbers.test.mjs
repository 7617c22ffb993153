// The lab compiled to WebAssembly (src/browser, tools/site) against the native `frictionlab run`:
// every scene the site offers, stepped to its end in the module under node, gives the summary the
// native run gives for the same scene (every value but the wall clock's). Where the maths
// libraries differ (wasm's libm against glibc's, ../docs/physics.md), the period may differ: it is
// held within 1e-9 relative and the regime must agree; the test prints how many summaries were
// identical to the bit.
//
//   node tests/wasm_numbers.test.mjs --lab build/wasm/src/browser --exe build/release/src/cli/frictionlab
// Exit status: 0 all agree, 1 one does not, 77 no module built (the test is skipped).
import { execFileSync } from "node:child_process";
import { existsSync, readFileSync } from "node:fs";
import { createRequire } from "node:module";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { parseArgs } from "node:util";

const repository = resolve(dirname(fileURLToPath(import.meta.url)), "../..");
const { values: options } = parseArgs({
  options: { lab: { type: "string" }, exe: { type: "string" }, scene: { type: "string" } },
});
if (!options.lab || !options.exe) {
  console.error(
    "usage: node tests/wasm_numbers.test.mjs --lab DIR --exe FRICTIONLAB [--scene NAME]",
  );
  process.exit(2);
}
const script = join(resolve(options.lab), "frictionlab-lab.js");
if (!existsSync(script)) {
  console.error(`skipped: no module at ${script} (tools/site builds it)`);
  process.exit(77);
}

// emcc's module for node (-sENVIRONMENT=worker,node, CommonJS): its wasm and preloaded files
// given as bytes, so that it fetches nothing.
const require = createRequire(import.meta.url);
const createLab = require(script);
const bytes = (name) => readFileSync(join(dirname(script), name));
const data = bytes("frictionlab-lab.data");
const lab = await createLab({
  print: () => {},
  printErr: (text) => console.error(text),
  wasmBinary: bytes("frictionlab-lab.wasm"),
  getPreloadedPackage: () => data.buffer.slice(data.byteOffset, data.byteOffset + data.byteLength),
});
lab.open_lab("/lab/scenes", "/lab/assets");
const ask = (text) => JSON.parse(text);

/** The summary of `scene` stepped to its end in the module. */
function wasmSummary(scene) {
  const made = ask(lab.create_session(JSON.stringify({ scene })));
  if (made.status !== 201) throw new Error(`${scene}: ${JSON.stringify(made.body)}`);
  const id = made.body.id;
  for (;;) {
    ask(lab.control(id, JSON.stringify({ action: "step" })));
    const frame = ask(lab.events(id));
    const done = frame.body.find((e) => e.event === "done");
    if (done) {
      lab.end(id);
      return done.data;
    }
  }
}

/** The wall clock's values, which no two runs share. */
const WALL = new Set(["wall_s", "real_time_factor", "steps_per_second"]);

let failed = 0;
let identical = 0;
const scenes = ask(lab.lab()).body.scenes.map((s) => s.name);
for (const scene of options.scene ? [options.scene] : scenes) {
  const started = Date.now();
  const wasm = wasmSummary(scene);
  const native = JSON.parse(
    execFileSync(options.exe, ["run", `${repository}/scenes/${scene}.yaml`, "--json"], {
      encoding: "utf8",
    }),
  );
  const differing = Object.keys(native).filter(
    (key) => !WALL.has(key) && JSON.stringify(native[key]) !== JSON.stringify(wasm[key]),
  );
  const period = native.period_s ?? native.period_trajectory_s;
  const wasmPeriod = wasm.period_s ?? wasm.period_trajectory_s;
  const relative = period === null ? 0 : Math.abs(wasmPeriod / period - 1);
  const agrees = relative <= 1e-9 && native.regime === wasm.regime;
  if (differing.length === 0) identical += 1;
  if (!agrees) failed += 1;
  console.log(
    `${agrees ? "ok  " : "FAIL"} ${scene}: T ${wasmPeriod} s in wasm, ${period} s native ` +
      `(${relative.toExponential(1)} apart), regime ${wasm.regime}; ` +
      (differing.length === 0 ? "every value identical" : `differing: ${differing.join(", ")}`) +
      ` (${Date.now() - started} ms)`,
  );
}
console.log(`${identical} of ${options.scene ? 1 : scenes.length} summaries identical to the bit`);
process.exit(failed === 0 ? 0 : 1);
