// The lab compiled to WebAssembly (src/browser, tools/site) against the native `frictionlab run`:
// every scene the suite runs (the site's, the imperfect rigs, the extreme cases), stepped to its
// end in the module under node, against the native run of the same scene, every value but the
// wall clock's. Where the maths libraries differ (wasm's libm against glibc's, docs/physics.md),
// values may differ in their last digits: the regime must agree, and the period of a harmonic run
// within 1e-9 relative; the test prints how many summaries were identical to the bit and what
// differs in the others.
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

/** `frictionlab run FILE --json`'s summary, also of a run that failed (exit status 3: the plate
 * left the rollers, as some extreme cases are meant to). */
function nativeRun(file) {
  try {
    return execFileSync(options.exe, ["run", file, "--json"], { encoding: "utf8" });
  } catch (error) {
    if (error.status === 3 && error.stdout) return error.stdout;
    throw error;
  }
}

// Every scene the suite runs: the site's own (scenes/), the rig's imperfections and the extreme
// cases (the stability catalogue), each folder opened as the lab's scenes in turn.
const FOLDERS = ["scenes", "scenes/imperfect", "scenes/extreme"];
let failed = 0;
let identical = 0;
let count = 0;
for (const folder of FOLDERS) {
  lab.open_lab(`/lab/${folder}`, "/lab/assets");
  const scenes = ask(lab.lab()).body.scenes.map((s) => s.name);
  for (const scene of scenes) {
    if (options.scene && scene !== options.scene) continue;
    count += 1;
    const started = Date.now();
    const wasm = wasmSummary(scene);
    const native = JSON.parse(nativeRun(`${repository}/${folder}/${scene}.yaml`));
    const differing = Object.keys(native).filter(
      (key) => !WALL.has(key) && JSON.stringify(native[key]) !== JSON.stringify(wasm[key]),
    );
    const period = native.period_s ?? native.period_trajectory_s;
    const wasmPeriod = wasm.period_s ?? wasm.period_trajectory_s;
    const relative =
      period === null || wasmPeriod === null
        ? period === wasmPeriod
          ? 0
          : Infinity
        : Math.abs(wasmPeriod / period - 1);
    // A harmonic run carries a last-digit difference without growing it: its period is held to
    // 1e-9. A plate that hops, sticks or is flung off amplifies one: its difference is shown.
    const harmonic = native.regime === "oscillates" && !(native.jumps > 0);
    const agrees = native.regime === wasm.regime && (!harmonic || relative <= 1e-9);
    if (differing.length === 0) identical += 1;
    if (!agrees) failed += 1;
    console.log(
      `${agrees ? "ok  " : "FAIL"} ${folder}/${scene}: T ${wasmPeriod} s in wasm, ${period} s ` +
        `native (${relative.toExponential(1)} apart), regime ${wasm.regime}` +
        (wasm.regime === native.regime ? "" : ` (native: ${native.regime})`) +
        "; " +
        (differing.length === 0 ? "every value identical" : `differing: ${differing.join(", ")}`) +
        ` (${Date.now() - started} ms)`,
    );
  }
}
console.log(`${identical} of ${count} summaries identical to the bit`);
process.exit(failed === 0 ? 0 : 1);
