// The static site (tools/site) on localhost, in Debian's chromium, headless (software WebGL),
// served by python3 -m http.server:
//  - what the first load transfers, gzipped (the WebAssembly, the scripts, the parts: what a
//    school's web server sends compressed);
//  - the time from opening the paper rig's link to the first period on screen, `rounds` times in
//    fresh browsers (no cache);
//  - the physics' speed in the page's worker: the paper's rig stepped to its end (the session's
//    events and JSON included), as simulated seconds per wall second;
//  - the page's frame rate over 5 s with the lab playing the paper's rig, and over 5 s paused;
//  - a phone's video (assets/examples/instruments/phone-video.mp4, 12 s at 480x270) chosen in
//    "Your measurement": decoded by the browser, its plate followed by the lab, until T shows;
//    with --exe and --web, the same page's frame rate with the physics on `frictionlab serve`
//    on this machine instead (the page's own drawing, not the physics, sets its pace).
//
//   node tests/site_bench.mjs --site DIR [--rounds 5] [--exe FRICTIONLAB --web DIR]
import { spawn } from "node:child_process";
import { readdirSync, readFileSync, statSync } from "node:fs";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { createInterface } from "node:readline";
import { parseArgs } from "node:util";
import { gzipSync } from "node:zlib";
import { launchChromium, serveFolder } from "./browser_checks.mjs";

const { values: options } = parseArgs({
  options: {
    site: { type: "string" },
    rounds: { type: "string", default: "5" },
    exe: { type: "string" },
    web: { type: "string" },
  },
});
if (!options.site) {
  console.error("usage: node tests/site_bench.mjs --site DIR [--rounds N]");
  process.exit(2);
}
const site = resolve(options.site);
const repository = resolve(dirname(fileURLToPath(import.meta.url)), "../..");

// What the first load fetches: every file but the service worker's own copies (it is the same
// files again, fetched once in the background).
let raw = 0;
let gzipped = 0;
const walk = (dir) => {
  for (const name of readdirSync(dir)) {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) walk(path);
    else {
      const bytes = readFileSync(path);
      raw += bytes.length;
      gzipped += gzipSync(bytes, { level: 9 }).length;
    }
  }
};
walk(site);
console.log(`the site: ${(raw / 1e6).toFixed(2)} MB, ${(gzipped / 1e6).toFixed(2)} MB gzipped`);

const served = await serveFolder(site);
const base = served.base;
const launch = launchChromium;

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];
const firsts = [];
for (let round = 0; round < Number(options.rounds); round += 1) {
  const browser = await launch();
  const page = await (
    await browser.newContext({ viewport: { width: 1366, height: 768 } })
  ).newPage();
  const start = Date.now();
  await page.goto(`${base}/?scene=paper-rig`);
  // The first period the estimator accepts: the readout's data-value.
  await page.waitForFunction(
    () => document.querySelector('[data-testid="period"]')?.getAttribute("data-value"),
    null,
    { timeout: 60000, polling: 20 },
  );
  firsts.push(Date.now() - start);
  await browser.close();
}
console.log(
  `the first period on screen after ${(median(firsts) / 1000).toFixed(2)} s ` +
    `(median of ${firsts.length}: ${firsts.map((ms) => (ms / 1000).toFixed(2)).join(", ")} s)`,
);

const browser = await launch();
const page = await (await browser.newContext({ viewport: { width: 1366, height: 768 } })).newPage();
await page.goto(`${base}/?scene=paper-rig`);
await page.getByTestId("status").filter({ hasText: "playing" }).waitFor({ timeout: 60000 });

// Frames the page draws in 5 s (requestAnimationFrame), playing, then paused.
const frameRateOf = (on) =>
  on.evaluate(
    () =>
      new Promise((done) => {
        let frames = 0;
        const start = performance.now();
        const count = () => {
          frames += 1;
          if (performance.now() - start < 5000) requestAnimationFrame(count);
          else done((frames * 1000) / (performance.now() - start));
        };
        requestAnimationFrame(count);
      }),
  );
const frameRate = () => frameRateOf(page);
const playing = await frameRate();
await page.getByRole("button", { name: "Pause" }).click();
await page.getByTestId("status").filter({ hasText: "paused" }).waitFor();
const paused = await frameRate();
console.log(`the page's frames: ${playing.toFixed(1)}/s playing, ${paused.toFixed(1)}/s paused`);

// A phone's video read in the page: from choosing the file to its T on screen.
{
  const started = Date.now();
  await page
    .getByTestId("measurement-file")
    .setInputFiles(join(repository, "assets/examples/instruments/phone-video.mp4"));
  await page
    .getByTestId("measured-detail")
    .filter({ hasText: "N = " })
    .waitFor({ timeout: 120000 });
  console.log(
    `a phone's 12 s video read in the page: ${((Date.now() - started) / 1000).toFixed(1)} s`,
  );
}

// The worker's physics: a worker of the site's own, the paper's rig (100 s) stepped to its end.
const speed = await page
  .evaluate(async (site) => {
    // A Blob's worker resolves names against the Blob's address: the site's are given whole.
    const source = `
    importScripts("${site}/frictionlab-lab.js");
    createLab({ print: () => {}, locateFile: (name) => "${site}/" + name }).then((lab) => {
      lab.open_lab("/lab/scenes", "/lab/assets");
      const made = JSON.parse(lab.create_session(JSON.stringify({ scene: "paper-rig", set: ["world.duration=100s"] })));
      const id = made.body.id;
      const start = performance.now();
      let simulated = 0;
      for (;;) {
        lab.control(id, JSON.stringify({ action: "step" }));
        const frame = JSON.parse(lab.events(id));
        const done = frame.body.find((e) => e.event === "done");
        if (done) { simulated = done.data.duration_s; break; }
      }
      postMessage(simulated / ((performance.now() - start) / 1000));
    });`;
    const url = URL.createObjectURL(new Blob([source], { type: "text/javascript" }));
    const worker = new Worker(url);
    return new Promise((done, fail) => {
      worker.onmessage = (event) => done(event.data);
      worker.onerror = (event) => fail(new Error(event.message));
    });
  }, base)
  .catch((error) => `failed: ${error.message}`);
console.log(
  typeof speed === "number"
    ? `the paper's rig in the page's worker: ${speed.toFixed(0)} x real time`
    : `the worker's speed: ${speed}`,
);
await browser.close();

if (options.exe && options.web) {
  const lab = spawn(
    options.exe,
    ["serve", "--port", "0", "--web", options.web, "--scenes", join(repository, "scenes")],
    { stdio: ["ignore", "pipe", "ignore"] },
  );
  const served = await new Promise((done) => {
    createInterface({ input: lab.stdout }).on("line", (line) => {
      const found = /http:\/\/[\d.]+:\d+/.exec(line);
      if (found) done(found[0]);
    });
  });
  const other = await launch();
  const page2 = await (
    await other.newContext({ viewport: { width: 1366, height: 768 } })
  ).newPage();
  await page2.goto(`${served}/?scene=paper-rig`);
  await page2.getByTestId("status").filter({ hasText: "playing" }).waitFor({ timeout: 60000 });
  const rate = await frameRateOf(page2);
  console.log(`the same page with the physics on frictionlab serve: ${rate.toFixed(1)}/s playing`);
  await other.close();
  lab.kill();
}
served.stop();
