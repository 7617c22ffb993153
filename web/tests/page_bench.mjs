// What a user waits for and what the stream delivers, against the real `frictionlab serve` on
// localhost: the page's load (navigation to `load`, and to the first state drawn from a running
// session) in Debian's chromium, headless; the first period: the simulated time the estimator
// accepted it at (the first state carrying an estimate) and how long after that state arrived
// the page showed it; and the stream's event rate and the largest gap between events over 10 s
// of a playing session, read by a plain HTTP client.
//
//   node tests/page_bench.mjs --exe build/release/src/cli/frictionlab --web build/release/src/cli/web
import { spawn } from "node:child_process";
import { dirname, resolve } from "node:path";
import { createInterface } from "node:readline";
import { fileURLToPath } from "node:url";
import { parseArgs } from "node:util";
import { chromium } from "playwright-core";

const repository = resolve(dirname(fileURLToPath(import.meta.url)), "../..");
const { values: options } = parseArgs({
  options: {
    exe: { type: "string" },
    web: { type: "string" },
    rounds: { type: "string", default: "5" },
  },
});
const server = spawn(
  options.exe,
  ["serve", "--port", "0", "--web", options.web, "--scenes", `${repository}/scenes`],
  { stdio: ["ignore", "pipe", "inherit"] },
);
const base = await new Promise((done) => {
  createInterface({ input: server.stdout }).on("line", (line) => {
    const found = /http:\/\/[\d.]+:\d+/.exec(line);
    if (found) done(found[0]);
  });
});

// The page's load, `rounds` times in fresh contexts.
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
  args: ["--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--no-sandbox"],
});
const loads = [];
const firstStates = [];
const accepted = [];
const shownAfter = [];
/** Runs before the page's script: the arrival of the first state with an estimate, and the
 * moment the period readout gets its value. */
function watchFirstPeriod() {
  const watch = { arrived: null, t: null, shown: null };
  window.__firstPeriod = watch;
  const PageEventSource = window.EventSource;
  window.EventSource = class extends PageEventSource {
    constructor(url, init) {
      super(url, init);
      this.addEventListener("state", (event) => {
        if (watch.arrived !== null) return;
        const state = JSON.parse(event.data);
        if (state.estimate) {
          watch.arrived = performance.now();
          watch.t = state.t;
        }
      });
    }
  };
  new MutationObserver(() => {
    const readout = document.querySelector('[data-testid="period"]');
    if (watch.shown === null && readout?.getAttribute("data-value"))
      watch.shown = performance.now();
  }).observe(document, { subtree: true, attributes: true, childList: true });
}
for (let round = 0; round < Number(options.rounds); round += 1) {
  const context = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const page = await context.newPage();
  await page.addInitScript(watchFirstPeriod);
  const start = Date.now();
  await page.goto(`${base}/?scene=paper-rig`, { waitUntil: "load" });
  loads.push(Date.now() - start);
  await page.waitForFunction(
    () => document.querySelector('[data-testid="time"]')?.textContent !== "t = 0.000 s",
  );
  firstStates.push(Date.now() - start);
  await page.waitForFunction(() => window.__firstPeriod.shown !== null, null, { timeout: 60000 });
  const watch = await page.evaluate(() => window.__firstPeriod);
  accepted.push(watch.t);
  shownAfter.push(watch.shown - watch.arrived);
  await context.close();
}
await browser.close();

// The stream: events a second and the largest gap, over 10 s of the paper's rig playing.
const session = await (
  await fetch(`${base}/api/sessions`, {
    method: "POST",
    body: JSON.stringify({ scene: "paper-rig", set: ["world.duration=100s"] }),
  })
).json();
await fetch(`${base}/api/sessions/${session.id}/control`, {
  method: "POST",
  headers: { "X-Session-Key": session.key },
  body: JSON.stringify({ action: "play" }),
});
const response = await fetch(`${base}/api/sessions/${session.id}/stream?key=${session.key}`);
const reader = response.body.getReader();
const arrivals = [];
let bytes = 0;
const started = Date.now();
while (Date.now() - started < 10000) {
  const { value, done } = await reader.read();
  if (done) break;
  bytes += value.length;
  const text = new TextDecoder().decode(value);
  for (const _ of text.matchAll(/^event: state$/gm)) arrivals.push(Date.now());
}
await reader.cancel();
server.kill("SIGTERM");

const gaps = arrivals.slice(1).map((t, i) => t - arrivals[i]);
gaps.sort((a, b) => a - b);
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
console.log(
  `page load (navigation to load), median of ${loads.length}: ${median(loads)} ms (${loads.join(", ")})`,
);
console.log(
  `page load to the first state drawn, median: ${median(firstStates)} ms (${firstStates.join(", ")})`,
);
console.log(
  `the first period: the estimator accepted it at t = ${median(accepted).toFixed(3)} s ` +
    `(simulated, at 1x); on screen ${median(shownAfter).toFixed(0)} ms after its state ` +
    `arrived (median; ${shownAfter.map((ms) => ms.toFixed(0)).join(", ")} ms), its state sent ` +
    `within one 33 ms tick of the step that accepted it`,
);
const seconds = (arrivals.at(-1) - arrivals[0]) / 1000;
console.log(
  `stream: ${((arrivals.length - 1) / seconds).toFixed(1)} events/s over ${seconds.toFixed(1)} s, ` +
    `gap p99 ${gaps[Math.floor(0.99 * (gaps.length - 1))]} ms, largest ${gaps.at(-1)} ms, ` +
    `${(bytes / seconds / 1024).toFixed(1)} KiB/s`,
);
