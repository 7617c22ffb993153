// A classroom's load on `frictionlab serve`: N sessions of the paper's rig playing at once, each
// streamed by its own client, for a while; then sessions opened and closed for a minute. Reports
// each session's event rate and its 99th-percentile gap between events, the server's CPU per
// session and its resident memory, and whether the memory came back after the churn.
//
//   node tests/load_bench.mjs --exe build/release/src/cli/frictionlab --web build/release/src/cli/web
//                             [--sessions 30] [--seconds 20] [--churn 60]
import { readFileSync } from "node:fs";
import { spawn } from "node:child_process";
import { dirname, resolve } from "node:path";
import { createInterface } from "node:readline";
import { fileURLToPath } from "node:url";
import { parseArgs } from "node:util";

const repository = resolve(dirname(fileURLToPath(import.meta.url)), "../..");
const { values: options } = parseArgs({
  options: {
    exe: { type: "string" },
    web: { type: "string" },
    sessions: { type: "string", default: "30" },
    seconds: { type: "string", default: "20" },
    churn: { type: "string", default: "60" },
  },
});
const sessions = Number(options.sessions);
const child = spawn(
  options.exe,
  [
    "serve",
    "--port",
    "0",
    "--web",
    options.web,
    "--scenes",
    `${repository}/scenes`,
    "--max-sessions",
    String(sessions + 10),
    // One client opens every session: its share of requests is a classroom's.
    "--rate",
    "1000",
  ],
  { stdio: ["ignore", "pipe", "inherit"] },
);
const base = await new Promise((done) => {
  createInterface({ input: child.stdout }).on("line", (line) => {
    const found = /http:\/\/[\d.]+:\d+/.exec(line);
    if (found) done(found[0]);
  });
});

/** The server's resident memory [MiB] and CPU time [s]. */
function usage() {
  const status = readFileSync(`/proc/${child.pid}/status`, "utf8");
  const rss = Number(/VmRSS:\s+(\d+)/.exec(status)[1]) / 1024;
  const stat = readFileSync(`/proc/${child.pid}/stat`, "utf8").split(") ")[1].split(" ");
  const ticks = Number(stat[11]) + Number(stat[12]); // utime + stime
  return { rss, cpu: ticks / 100 };
}

/** A playing session: its id and its key (docs/web-api.md). */
async function start(scene) {
  const made = await (
    await fetch(`${base}/api/sessions`, {
      method: "POST",
      body: JSON.stringify({ scene, set: ["world.duration=1000s"] }),
    })
  ).json();
  await fetch(`${base}/api/sessions/${made.id}/control`, {
    method: "POST",
    headers: { "X-Session-Key": made.key },
    body: JSON.stringify({ action: "play" }),
  });
  return made;
}

async function endSession(session) {
  await fetch(`${base}/api/sessions/${session.id}`, {
    method: "DELETE",
    headers: { "X-Session-Key": session.key },
  });
}

/** Reads a session's stream for `ms`: the arrival time of each state event. */
async function listen(session, ms) {
  const response = await fetch(`${base}/api/sessions/${session.id}/stream?key=${session.key}`);
  const reader = response.body.getReader();
  const decoder = new TextDecoder();
  const arrivals = [];
  const end = Date.now() + ms;
  while (Date.now() < end) {
    const { value, done } = await reader.read();
    if (done) break;
    for (const _ of decoder.decode(value).matchAll(/^event: state$/gm)) arrivals.push(Date.now());
  }
  await reader.cancel();
  return arrivals;
}

const idle = usage();
const playing = [];
for (let i = 0; i < sessions; i += 1) playing.push(await start("paper-rig"));
const before = usage();
const seconds = Number(options.seconds);
const streams = await Promise.all(playing.map((session) => listen(session, seconds * 1000)));
const after = usage();
const rates = [];
const gaps = [];
for (const arrivals of streams) {
  const span = (arrivals.at(-1) - arrivals[0]) / 1000;
  rates.push((arrivals.length - 1) / span);
  const own = arrivals.slice(1).map((t, i) => t - arrivals[i]);
  own.sort((a, b) => a - b);
  gaps.push(own[Math.floor(0.99 * (own.length - 1))]);
}
rates.sort((a, b) => a - b);
gaps.sort((a, b) => a - b);
const cpu = (after.cpu - before.cpu) / seconds; // cores
console.log(
  `${sessions} sessions of the paper's rig for ${seconds} s: events/s per session ` +
    `min ${rates[0].toFixed(1)}, median ${rates[Math.floor(rates.length / 2)].toFixed(1)}; ` +
    `99th-percentile gap per session: median ${gaps[Math.floor(gaps.length / 2)]} ms, ` +
    `worst ${gaps.at(-1)} ms`,
);
console.log(
  `server CPU ${(100 * cpu).toFixed(0)} % of one core (${((100 * cpu) / sessions).toFixed(2)} % ` +
    `a session); resident ${idle.rss.toFixed(1)} MiB idle, ${after.rss.toFixed(1)} MiB with ` +
    `${sessions} sessions (${((after.rss - idle.rss) / sessions).toFixed(2)} MiB a session)`,
);
for (const session of playing) await endSession(session);

// Churn: sessions opened, streamed for a second and closed, three at a time, for `churn` seconds,
// twice: the first round warms the server's threads (their stacks, their allocator caches), the
// second shows whether anything is kept.
async function churn(seconds) {
  const end = Date.now() + seconds * 1000;
  let opened = 0;
  while (Date.now() < end) {
    await Promise.all(
      [0, 1, 2].map(async () => {
        const session = await start("minimal");
        await listen(session, 1000);
        await endSession(session);
        opened += 1;
      }),
    );
  }
  return opened;
}
const cold = usage();
const first = await churn(Number(options.churn));
const warm = usage();
const second = await churn(Number(options.churn));
const churned = usage();
console.log(
  `churn: ${first} then ${second} sessions opened and closed in ${options.churn} s each; ` +
    `resident ${cold.rss.toFixed(1)} MiB before, ${warm.rss.toFixed(1)} MiB after the first ` +
    `(warm), ${churned.rss.toFixed(1)} MiB after the second ` +
    `(${(100 * (churned.rss / warm.rss - 1)).toFixed(1)} % of warm)`,
);
child.kill("SIGTERM");
