// A stand-in for `frictionlab serve` for testing the page only (docs/web-api.md): serves a built
// page, the LEGO parts, and fakes the lab's API with a harmonic plate, a fake rig on a fake
// serial port and the class's table. Not the lab's physics, nor its estimator; but the paper's
// Table I is the lab's own file and a student's name is checked by the page's copy of the server's
// rule (both held to one list of cases), and, as the lab, it runs a session on the wall clock (simulated time = wall time x speed, however
// often its stream ticks) and obeys only requests that carry the session's key.
//
//   node tests/mock_server.mjs [--port 8765] [--dist DIR]
//
// For the tests, beside the API: GET /__mock/log (the requests it was sent), /__mock/rig (the
// fake rig's periods so far), /__mock/rig-unplug (the fake board goes away), /__mock/rig-shared
// (may_choose false from now on, until /__mock/rig-shared?off), /__mock/refuse?path=P&count=N
// (the next N requests to a path ending in P answer 429), /__mock/close-streams (every stream gets
// `event: closed`, as when the server stops) and /__mock/streams?session=ID (how many streams of
// that session are open).
import { randomBytes } from "node:crypto";
import { createServer } from "node:http";
import { readFile } from "node:fs/promises";
import { dirname, extname, join, normalize, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { importTs } from "./import_ts.mjs";

const here = dirname(fileURLToPath(import.meta.url));
const partsDir = resolve(here, "../../assets/lego");
const G = 9.81;
const DURATION = 4.0; // s: the mock's runs are short

const SCENES = [
  { name: "minimal", title: "The minimal rig: a plate on two counter-rotating rollers" },
  { name: "paper-rig", title: 'The paper\'s rig (Henaff et al., section "Experimental setup")' },
  { name: "stribeck-drop", title: "Stability catalogue: stribeck-drop" },
];

/** The paper's Table I as the lab reads it (assets/paper/table1-measured.csv, the file `frictionlab
 * compare` reads): [key, name, mu_k at 300 K, mu_k at 77 K or null], no copy of its own. */
const MATERIALS = await (async () => {
  const text = await readFile(resolve(here, "../../assets/paper/table1-measured.csv"), "utf8");
  const lines = text.split("\n").filter((l) => l.trim() !== "" && !l.startsWith("#"));
  const header = lines[0].split(",");
  const column = (name) => header.indexOf(name);
  const byKey = new Map();
  for (const line of lines.slice(1)) {
    const cells = line.split(",");
    const key = cells[column("plate.material")];
    const kelvin = Number.parseFloat(cells[column("friction.temperature")]);
    const muK = Number(cells[column("mu_k")]);
    const entry = byKey.get(key) ?? [key, cells[column("label")], null, null];
    entry[kelvin < 100 ? 3 : 2] = muK;
    byKey.set(key, entry);
  }
  return [...byKey.values()];
})();

/** A name for the class's table: the server's rule, as the page keeps it (web/src/student_name.ts). */
const { problemOf: nameProblem } = await importTs(resolve(here, "../src/student_name.ts"));

// The fake rig: a stand-in for the rig's Arduino on a serial port, for testing the page only.
// Once its port is opened it "samples" a Hall sensor at 1 kHz as wall-clock time passes, a pulse
// at the end of each period; its periods are known numbers (FAKE_RIG_PERIOD and a small
// deterministic wobble, whole microseconds), the first one rejected, and its estimate their mean.
// No estimator runs here: the periods are told, not measured from the samples.
export const FAKE_RIG_PORT = "/dev/ttyFAKE0";
export const FAKE_RIG_PERIOD = 0.792134;
const FAKE_RIG_RATE = 1000; // samples a second
const FAKE_RIG_FIRST_PULSE = 0.25; // s after the run's first sample
const FAKE_RIG_BOOT_S = 0.3; // an Uno resets when its port opens: nothing comes for this long
const FAKE_RIG_KEEP_S = 12; // samples older than this are dropped (a stream sends the last 10 s)

/** The fake rig's n-th period (n from 0), in seconds, a whole number of microseconds. */
export function fakeRigPeriod(n) {
  return Math.round((FAKE_RIG_PERIOD + 0.0004 * Math.sin(1.7 * n + 0.4)) * 1e6) / 1e6;
}

/** What the rig's estimator reports for accepted periods, as the lab's `estimate` object. */
function estimateOf(periods, spacing) {
  const n = periods.length;
  if (n === 0) return null;
  const mean = periods.reduce((s, v) => s + v, 0) / n;
  const sd = n > 1 ? Math.sqrt(periods.reduce((s, v) => s + (v - mean) ** 2, 0) / (n - 1)) : null;
  const mu = (2 * Math.PI ** 2 * spacing) / (G * mean ** 2);
  return {
    periods_used: n,
    period: mean,
    period_sd: sd,
    period_se: sd === null ? null : sd / Math.sqrt(n),
    mu_k: mu,
    mu_k_err: sd === null ? null : mu * Math.hypot(0.002 / spacing, (2 * sd) / mean),
    mu_k_err_worst: sd === null ? null : mu * (0.002 / spacing + (2 * sd) / mean),
  };
}

class FakeRig {
  constructor() {
    this.ports = [FAKE_RIG_PORT];
    this.mayChoose = true;
    this.port = null;
    this.state = "closed";
    this.message = null;
    this.run = 0;
    this.logLines = [];
    this.logName = null;
    this.openedAt = 0;
    this.pulses = [FAKE_RIG_FIRST_PULSE];
    this.samples = []; // [t, adc] of the last FAKE_RIG_KEEP_S
    this.sampleCount = 0; // every sample made since the port opened
    this.periods = []; // [start, end, period, accepted], every one judged
  }
  open(port) {
    this.port = port;
    this.state = "waiting";
    this.message = null;
    this.run = 0;
    this.logLines = [];
    this.logName = null;
    this.openedAt = Date.now();
    this.samples = [];
    this.sampleCount = 0;
    this.periods = [];
  }
  close() {
    this.advance();
    if (this.state !== "waiting" && this.state !== "receiving") return; // as the server does
    this.state = "closed";
    this.message = null;
  }
  unplug() {
    this.advance();
    this.state = "unplugged";
    this.message =
      "the port went away: the board was unplugged or reset its USB; the log so far is kept " +
      "(download it below); plug it in again and connect";
  }
  /** The n-th pulse's time (n from 0). */
  pulse(n) {
    while (this.pulses.length <= n) {
      this.pulses.push(this.pulses.at(-1) + fakeRigPeriod(this.pulses.length - 1));
    }
    return this.pulses[n];
  }
  /** Makes the samples and judges the periods up to now. */
  advance() {
    if (this.state !== "waiting" && this.state !== "receiving") return;
    const now = (Date.now() - this.openedAt) / 1000 - FAKE_RIG_BOOT_S;
    if (now < 0) return;
    if (this.logLines.length === 0) {
      this.logName = `rig-fake-${new Date(this.openedAt).toISOString().replace(/[-:]|\..*/g, "")}.log`;
      this.logLines.push(
        `# frictionlab rig firmware 1: sample_hz=${FAKE_RIG_RATE} (the mock's fake board)`,
        "t_us,adc",
      );
      this.state = "receiving";
    }
    for (; this.sampleCount / FAKE_RIG_RATE <= now; this.sampleCount++) {
      const t = this.sampleCount / FAKE_RIG_RATE;
      let adc = 512 + 3 * Math.sin(t * 977);
      // the pulses within 0.1 s of t
      let n = Math.max(0, Math.floor((t - FAKE_RIG_FIRST_PULSE) / FAKE_RIG_PERIOD) - 1);
      for (; this.pulse(n) < t + 0.1; n++) {
        adc += 300 * Math.exp(-(((t - this.pulse(n)) / 0.012) ** 2) / 2);
      }
      const sample = [Number(t.toFixed(3)), Math.round(adc)];
      this.samples.push(sample);
      this.logLines.push(`${this.sampleCount * (1e6 / FAKE_RIG_RATE)},${sample[1]}`);
    }
    const keepFrom = now - FAKE_RIG_KEEP_S;
    let drop = 0;
    while (drop < this.samples.length && this.samples[drop][0] < keepFrom) drop++;
    if (drop > 0) this.samples.splice(0, drop);
    // A period is judged once its closing pulse is 50 ms past.
    for (let n = this.periods.length; this.pulse(n + 1) + 0.05 <= now; n++) {
      const start = this.pulse(n);
      this.periods.push([start, start + fakeRigPeriod(n), fakeRigPeriod(n), n > 0]);
    }
  }
  get lines() {
    return this.logLines.length;
  }
  status() {
    this.advance();
    return {
      ports: this.mayChoose ? this.ports : [], // a shared server lists none
      may_choose: this.mayChoose,
      port: this.port,
      baud: this.port === null ? null : 250000,
      state: this.state,
      message: this.message,
      lines: this.lines,
      log_name: this.logName,
    };
  }
  /** A stream's next rig event from its cursor (null: nothing changed), with its spacing. */
  eventFor(cursor, spacing) {
    if (this.port === null) return null;
    this.advance();
    if (cursor.run !== this.run || cursor.opened !== this.openedAt) {
      // A new stream, or a new port or board run: the last 10 s and every period of the run.
      Object.assign(cursor, { run: this.run, opened: this.openedAt, sample: 0, period: 0 });
      cursor.sample = Math.max(0, this.sampleCount - 10 * FAKE_RIG_RATE);
    }
    const first = this.sampleCount - this.samples.length;
    const hall = this.samples.slice(Math.max(0, cursor.sample - first));
    const periods = this.periods.slice(cursor.period);
    const key = `${this.state}|${this.message}|${this.lines}`;
    if (hall.length === 0 && periods.length === 0 && key === cursor.key) return null;
    cursor.sample = this.sampleCount;
    cursor.period = this.periods.length;
    cursor.key = key;
    const accepted = this.periods.filter((p) => p[3]).map((p) => p[2]);
    return {
      port: this.port,
      state: this.state,
      message: this.message,
      lines: this.lines,
      run: this.run,
      hall,
      periods,
      estimate: estimateOf(accepted, spacing),
      geometry: accepted.length > 0 ? "one-pulse" : "unknown",
      spacing,
    };
  }
}

function csvCell(value) {
  if (value === null || value === undefined) return "";
  const text = String(value);
  return /[",\n]/.test(text) ? `"${text.replaceAll('"', '""')}"` : text;
}

const TYPES = {
  ".html": "text/html; charset=utf-8",
  ".js": "text/javascript; charset=utf-8",
  ".css": "text/css; charset=utf-8",
  ".glb": "model/gltf-binary",
  ".json": "application/json",
  ".csv": "text/csv",
};

function json(res, status, body) {
  res.writeHead(status, { "Content-Type": "application/json" });
  res.end(JSON.stringify(body));
}

async function readBody(req) {
  const chunks = [];
  for await (const chunk of req) chunks.push(chunk);
  return Buffer.concat(chunks).toString("utf8");
}

function lengthMm(value) {
  const match = /^(-?[\d.]+)\s*mm$/.exec(value);
  return match ? Number(match[1]) : null;
}

function paperFrame() {
  const frame = [];
  const red = [0.788, 0.102, 0.035];
  const yellow = [0.949, 0.804, 0.216];
  for (const y of [-0.033, 0.033]) {
    for (let level = 0; level < 5; level++) {
      frame.push({
        part: "technic-brick-1x16",
        position: [0, y * 1.6, -0.0542 + level * 0.0096],
        turn_deg: 0,
        color: red,
      });
    }
  }
  for (const x of [-0.02, 0.02]) {
    for (const y of [-0.033, 0.033]) {
      for (let level = 0; level < 7; level++) {
        frame.push({
          part: "brick-2x2",
          position: [x, y, -0.0542 + level * 0.0096],
          turn_deg: 0,
          color: yellow,
        });
      }
    }
  }
  return frame;
}

/** The rig as the API describes it, with the set entries the mock understands applied. */
function makeRig(scene, set) {
  const problems = [];
  const rig = {
    scene,
    spacing: 0.089,
    roller_radius: 0.01,
    roller_length: scene === "paper-rig" ? 0.05 : 0.1,
    roller_sense: "inward",
    roller_speed_rpm: scene === "stribeck-drop" ? 200 : 1600,
    drive: scene === "paper-rig",
    plate: {
      length: 0.2,
      width: scene === "paper-rig" ? 0.048 : 0.06,
      thickness: scene === "paper-rig" ? 0.0032 : 0.005,
      mass: 0.06,
      h_c: 0.0025,
      material: "lego",
      blocks:
        scene === "paper-rig"
          ? [-0.084, -0.028, 0.028, 0.084].map((x) => ({
              part: "brick-2x4",
              x,
              y: 0,
              turn_deg: 90,
            }))
          : [],
    },
    magnets: [
      {
        x: -0.084,
        height: scene === "paper-rig" ? 0.0096 : null,
        diameter: 0.006,
        thickness: 0.003,
      },
      {
        x: 0.084,
        height: scene === "paper-rig" ? 0.0096 : null,
        diameter: 0.006,
        thickness: 0.003,
      },
    ],
    sensor: scene === "stribeck-drop" ? null : { x: 0.114, y: 0, z: 0.022 },
    frame: scene === "paper-rig" ? paperFrame() : [],
    offset: scene === "stribeck-drop" ? 0.03 : 0.02,
    duration: DURATION,
    time_step: 0.001,
    seed: 1,
    mu_k: 0.29,
    period_thin: 0,
    period_thick: 0,
    omega: 0,
    tipping_amplitude: 0.044,
    paper: { material: "LEGO blocks", period: 0.79, period_err: 0.03, mu_k: 0.29, mu_k_err: 0.03 },
  };
  let temperature = 300;
  for (const entry of set) {
    const at = entry.indexOf("=");
    const key = entry.slice(0, at);
    const value = entry.slice(at + 1);
    if (key === "rollers.spacing") {
      const mm = lengthMm(value);
      if (mm === null || mm <= 0) {
        problems.push({
          field: "set",
          value: entry,
          message: `expected a positive length, found ${value.replace("mm", " mm")}; rollers.spacing is the distance between the rollers' axes`,
        });
      } else rig.spacing = mm / 1000;
    } else if (key === "plate.offset") {
      const mm = lengthMm(value);
      if (mm === null) problems.push({ field: "set", value: entry, message: "expected a length" });
      else rig.offset = mm / 1000;
    } else if (key === "rollers.speed") {
      rig.roller_speed_rpm = Number(value.replace("rpm", ""));
    } else if (key === "plate.material") {
      if (!MATERIALS.some((m) => m[0] === value)) {
        problems.push({ field: "set", value: entry, message: `no material "${value}" in Table I` });
      } else rig.plate.material = value;
    } else if (key === "friction.temperature") {
      temperature = Number(value.replace("K", ""));
    } else if (key === "world.duration") {
      const seconds = Number(value.replace(/\s*s$/, ""));
      if (!(seconds > 0)) {
        problems.push({ field: "set", value: entry, message: "expected a positive time" });
      } else rig.duration = seconds;
    }
  }
  const material = MATERIALS.find((m) => m[0] === rig.plate.material);
  rig.mu_k = (temperature === 77 ? material[3] : material[2]) ?? material[2];
  rig.omega = Math.sqrt((2 * rig.mu_k * G) / rig.spacing);
  rig.period_thin = (2 * Math.PI) / rig.omega;
  rig.period_thick = rig.period_thin * 1.01;
  const paperMuK = temperature === 77 ? material[3] : material[2];
  const table = { material: material[1], temperature, paperMuK: paperMuK ?? null };
  return { rig, problems, table };
}

class FakeRun {
  constructor(rig, table = null, name = null) {
    this.rig = rig;
    this.table = table; // the material's name in Table I, the temperature, the paper's mu_k
    this.name = name;
    this.key = randomBytes(16).toString("hex"); // only requests that carry it control the run
    this.speed = 1;
    this.resets = 0;
    this.reset();
  }
  /** Advances a playing run to the wall clock's `now` [ms], at its speed. */
  catchUp(now) {
    if (this.playing) this.advance((this.speed * (now - this.wallAt)) / 1000);
    this.wallAt = now;
  }
  reset() {
    this.wallAt = performance.now();
    this.t = 0;
    this.playing = false;
    this.done = false;
    this.doneSent = false;
    this.hall = [];
    this.pulses = [];
    this.periods = [];
    this.allPulses = [];
    this.accepted = [];
    this.nextSample = 0;
  }
  x(t) {
    return this.rig.offset * Math.cos(this.rig.omega * t);
  }
  advance(dt) {
    if (this.done) return;
    const from = this.t;
    const to = Math.min(this.rig.duration, from + dt);
    const rig = this.rig;
    const T = (2 * Math.PI) / rig.omega;
    for (; this.nextSample <= to; this.nextSample += 0.001) {
      const s = this.nextSample;
      const magnet = this.x(s) + 0.084;
      const h = 0.0124;
      const dx = magnet - 0.114;
      const adc = 512 + 380 * (h ** 3 / (dx * dx + h * h) ** 1.5) + 3 * Math.sin(s * 977);
      if (rig.sensor) this.hall.push([Number(s.toFixed(4)), Math.round(adc)]);
    }
    const n0 = Math.floor(from / T);
    const n1 = Math.floor(to / T);
    for (let n = n0 + 1; n <= n1; n++) {
      const pulse = n * T + 0.002 * Math.sin(n * 2.3);
      this.pulses.push(pulse);
      const before = this.allPulses.at(-1);
      this.allPulses.push(pulse);
      if (before !== undefined) {
        const accepted = this.allPulses.length > 2;
        this.periods.push([before, pulse, pulse - before, accepted]);
        if (accepted) this.accepted.push(pulse - before);
      }
    }
    this.t = to;
    if (this.t >= this.rig.duration) {
      this.done = true;
      this.playing = false;
    }
  }
  estimate() {
    const a = this.accepted;
    if (a.length === 0) return null;
    const mean = a.reduce((s, v) => s + v, 0) / a.length;
    const sd =
      a.length > 1 ? Math.sqrt(a.reduce((s, v) => s + (v - mean) ** 2, 0) / (a.length - 1)) : null;
    const mu = (2 * Math.PI ** 2 * this.rig.spacing) / (G * mean ** 2);
    return {
      periods_used: a.length,
      period: mean,
      period_sd: sd,
      period_se: sd === null ? null : sd / Math.sqrt(a.length),
      mu_k: mu,
      mu_k_err: sd === null ? null : mu * Math.hypot(0.002 / this.rig.spacing, (2 * sd) / mean),
      mu_k_err_worst: sd === null ? null : mu * (0.002 / this.rig.spacing + (2 * sd) / mean),
    };
  }
  state() {
    const rig = this.rig;
    const x = this.x(this.t);
    const weight = rig.plate.mass * G;
    const n0 = weight * (0.5 - x / rig.spacing);
    const n1 = weight * (0.5 + x / rig.spacing);
    const spin = (rig.roller_speed_rpm * 2 * Math.PI) / 60;
    const state = {
      t: this.t,
      x,
      // The mock's plate moves as theory has it: its theory is its own motion.
      x_theory: x,
      z: rig.plate.h_c,
      pitch: 0.002 * Math.sin(rig.omega * this.t),
      vx: -rig.offset * rig.omega * Math.sin(rig.omega * this.t),
      roller_angles: [(spin * this.t) % (2 * Math.PI), (-spin * this.t) % (2 * Math.PI)],
      contacts: [
        { normal: n0, friction: rig.mu_k * n0 },
        { normal: n1, friction: -rig.mu_k * n1 },
      ],
      hall: this.hall,
      pulses: this.pulses,
      periods: this.periods,
      estimate: this.estimate(),
      regime: this.accepted.length > 0 ? "oscillates" : "starting",
      playing: this.playing,
      speed: this.speed,
    };
    this.hall = [];
    this.pulses = [];
    this.periods = [];
    return state;
  }
  /** The session's row of the class's table (GET /api/class). */
  classRow(id) {
    const e = this.estimate();
    const paperPeriod =
      this.table?.material === "LEGO blocks" && this.table.temperature === 300 ? 0.79 : null;
    return {
      session: id,
      name: this.name,
      scene: this.rig.scene,
      material: this.table?.material ?? null,
      temperature_k: this.table?.temperature ?? null,
      spacing: this.rig.spacing,
      h_c: this.rig.plate.h_c,
      state: this.done ? "done" : this.playing ? "playing" : "paused",
      t: this.t,
      period: e?.period ?? null,
      period_err: e?.period_se ?? null,
      period_from: e ? "sensor" : null,
      mu_k: e?.mu_k ?? null,
      mu_k_err: e?.mu_k_err ?? null,
      paper_period: paperPeriod,
      paper_mu_k: this.table?.paperMuK ?? null,
    };
  }
  summary() {
    const e = this.estimate();
    return {
      scene: this.rig.scene,
      regime: "oscillates",
      period_s: e?.period ?? null,
      period_std_s: e?.period_sd ?? null,
      period_std_error_s: e?.period_se ?? null,
      mu_k_recovered: e?.mu_k ?? null,
      mu_k_err_quadrature: e?.mu_k_err ?? null,
      periods_used: e?.periods_used ?? 0,
    };
  }
}

const CLASS_COLUMNS = [
  "session",
  "name",
  "scene",
  "material",
  "temperature_k",
  "spacing_mm",
  "h_c_mm",
  "state",
  "t_s",
  "period_s",
  "period_err_s",
  "period_from",
  "mu_k",
  "mu_k_err",
  "paper_period_s",
  "paper_mu_k",
];

function classCsv(rows) {
  const lines = [CLASS_COLUMNS.join(",")];
  for (const row of rows) {
    const mm = (metres) => (metres === null ? null : Number((metres * 1000).toFixed(6)));
    lines.push(
      [
        row.session,
        row.name,
        row.scene,
        row.material,
        row.temperature_k,
        mm(row.spacing),
        mm(row.h_c),
        row.state,
        row.t,
        row.period,
        row.period_err,
        row.period_from,
        row.mu_k,
        row.mu_k_err,
        row.paper_period,
        row.paper_mu_k,
      ]
        .map(csvCell)
        .join(","),
    );
  }
  return `${lines.join("\n")}\n`;
}

export function startMockServer({ port = 0, dist = resolve(here, "../dist") } = {}) {
  const sessions = new Map();
  const log = [];
  const rig = new FakeRig();
  const streams = new Map(); // every open stream's response, and its session's id
  const refusals = new Map(); // path -> how many more requests answer 429
  let rigOpened = false; // /api/class's rig: null until a port was opened
  let nextId = 1;

  const server = createServer(async (req, res) => {
    const url = new URL(req.url, "http://localhost");
    const path = url.pathname;
    try {
      if (path === "/__mock/log") return json(res, 200, log);
      if (path === "/__mock/rig") return json(res, 200, { periods: rig.periods, run: rig.run });
      if (path === "/__mock/rig-unplug") {
        rig.unplug();
        return json(res, 200, rig.status());
      }
      if (path === "/__mock/rig-shared") {
        rig.mayChoose = url.searchParams.has("off");
        return json(res, 200, rig.status());
      }
      if (path === "/__mock/refuse") {
        refusals.set(url.searchParams.get("path"), Number(url.searchParams.get("count") ?? 1));
        return json(res, 200, {});
      }
      if (path === "/__mock/close-streams") {
        const message = "the lab stopped (the mock was told to): reload the page when it is back";
        for (const stream of streams.keys()) {
          stream.write(`event: closed\ndata: ${JSON.stringify({ message })}\n\n`);
          stream.end();
        }
        return json(res, 200, { closed: streams.size });
      }
      if (path === "/__mock/streams") {
        const session = url.searchParams.get("session");
        const open = [...streams.values()].filter((id) => id === session).length;
        return json(res, 200, { open });
      }
      const refusing = [...refusals.keys()].find((p) => path.endsWith(p));
      const refused = refusals.get(refusing) ?? 0;
      if (refused > 0) {
        refusals.set(refusing, refused - 1);
        res.writeHead(429, { "Content-Type": "application/json", "Retry-After": "1" });
        res.end(
          JSON.stringify({
            error: "too many requests from 127.0.0.1 (at most 20 a second): try again in 1 s",
          }),
        );
        return;
      }
      if (path === "/api/rig" && req.method === "GET") return json(res, 200, rig.status());
      if (path === "/api/rig" && req.method === "POST") {
        const body = JSON.parse(await readBody(req));
        log.push({ rig: body });
        if (!rig.mayChoose) {
          return json(res, 403, { error: "this lab is shared: only its own computer chooses" });
        }
        if (typeof body.port === "string") {
          if (!rig.ports.includes(body.port)) {
            return json(res, 400, { error: `no port ${body.port}: GET /api/rig lists the ports` });
          }
          rig.open(body.port);
          rigOpened = true;
        } else if (body.action === "close") rig.close();
        else return json(res, 400, { error: 'expected {"port": ...} or {"action": "close"}' });
        return json(res, 200, rig.status());
      }
      if (path === "/api/rig/log" && req.method === "GET") {
        rig.advance();
        if (rig.lines === 0) return json(res, 404, { error: "no line came from the rig yet" });
        res.writeHead(200, {
          "Content-Type": "text/plain; charset=utf-8",
          "Content-Disposition": `attachment; filename="${rig.logName}"`,
        });
        res.end(`${rig.logLines.join("\n")}\n`);
        return;
      }
      if ((path === "/api/class" || path === "/api/class.csv") && req.method === "GET") {
        const rows = [...sessions].map(([id, run]) => run.classRow(id));
        if (path === "/api/class.csv") {
          res.writeHead(200, {
            "Content-Type": "text/csv; charset=utf-8",
            "Content-Disposition": 'attachment; filename="class.csv"',
          });
          res.end(classCsv(rows));
          return;
        }
        const { port, state, lines } = rig.status();
        return json(res, 200, { sessions: rows, rig: rigOpened ? { port, state, lines } : null });
      }
      if (path === "/api/lab" && req.method === "GET") {
        return json(res, 200, {
          scenes: SCENES,
          materials: MATERIALS.map(([key, name, , cold]) => ({
            key,
            name,
            temperatures_k: cold === null ? [300] : [300, 77],
          })),
          version: "frictionlab mock",
        });
      }
      if (path === "/api/sessions" && req.method === "POST") {
        const body = JSON.parse(await readBody(req));
        log.push({ create: body });
        if (!SCENES.some((s) => s.name === body.scene)) {
          return json(res, 400, {
            error: "the set-up has 1 problem",
            problems: [{ field: "scene", value: body.scene, message: `no scene "${body.scene}"` }],
          });
        }
        const { rig: made, problems, table } = makeRig(body.scene, body.set ?? []);
        const name = body.name ?? null;
        if (
          name !== null &&
          (typeof name !== "string" || name === "" || nameProblem(name) !== null)
        ) {
          problems.push({
            field: "name",
            value: String(name),
            message: "expected up to 40 letters, digits, spaces and . - _ '",
          });
        }
        if (problems.length > 0) {
          return json(res, 400, { error: `the set-up has ${problems.length} problem`, problems });
        }
        const id = String(nextId++);
        const run = new FakeRun(made, table, name);
        sessions.set(id, run);
        return json(res, 201, { id, key: run.key, rig: made });
      }
      const match = /^\/api\/sessions\/([^/]+)(\/.*)?$/.exec(path);
      if (match) {
        const [, id, rest = ""] = match;
        const run = sessions.get(id);
        if (!run) return json(res, 404, { error: `no session ${id}` });
        // As the lab: the session's id is public, its key is the page's that opened it, in a
        // header (in the address only for a GET: a stream, a download).
        const key =
          req.headers["x-session-key"] ??
          (req.method === "GET" ? url.searchParams.get("key") : undefined);
        if (key !== run.key) {
          log.push({ refused: id, path: rest, method: req.method });
          return json(res, 403, {
            error: `session ${id} is controlled only by the page that opened it: this request ${key ? "carries another key" : "carries no session key"}`,
            problems: [],
          });
        }
        if (rest === "" && req.method === "DELETE") {
          sessions.delete(id);
          log.push({ end: id });
          res.writeHead(204).end();
          return;
        }
        if (rest === "/control" && req.method === "POST") {
          const body = JSON.parse(await readBody(req));
          log.push({ control: id, body });
          run.catchUp(performance.now());
          if (body.action === "play") run.playing = !run.done;
          else if (body.action === "pause") run.playing = false;
          else if (body.action === "step") {
            if (!run.playing) run.advance(1 / 30);
          } else if (body.action === "reset") {
            run.reset();
            run.resets += 1;
          } else if ([1, 0.25, 0.0625].includes(body.speed)) run.speed = body.speed;
          else return json(res, 400, { error: "unknown control" });
          return json(res, 200, { t: run.t, playing: run.playing, speed: run.speed });
        }
        if (rest === "/stream" && req.method === "GET") {
          res.writeHead(200, {
            "Content-Type": "text/event-stream",
            "Cache-Control": "no-cache",
            Connection: "keep-alive",
          });
          let resetsSeen = run.resets;
          const rigCursor = {};
          streams.set(res, id);
          const tick = setInterval(() => {
            if (run.resets !== resetsSeen) {
              resetsSeen = run.resets;
              res.write("event: reset\ndata: {}\n\n");
            }
            run.catchUp(performance.now());
            res.write(`event: state\ndata: ${JSON.stringify(run.state())}\n\n`);
            if (run.done && !run.doneSent) {
              run.doneSent = true;
              res.write(`event: done\ndata: ${JSON.stringify(run.summary())}\n\n`);
            }
            const rigEvent = rig.eventFor(rigCursor, run.rig.spacing);
            if (rigEvent) res.write(`event: rig\ndata: ${JSON.stringify(rigEvent)}\n\n`);
          }, 1000 / 30);
          req.on("close", () => {
            clearInterval(tick);
            streams.delete(res);
          });
          return;
        }
        const file = /^\/files\/(.+)$/.exec(rest);
        if (file && req.method === "GET") {
          if (!run.done) return json(res, 404, { error: "the run is not done" });
          const name = decodeURIComponent(file[1]);
          if (name === "summary.json") return json(res, 200, run.summary());
          if (["trajectory.csv", "hall.csv", "periods.csv"].includes(name)) {
            res.writeHead(200, { "Content-Type": "text/csv" });
            res.end("t,value\n0,0\n");
            return;
          }
          return json(res, 404, { error: `no file ${name}` });
        }
        return json(res, 404, { error: "not found" });
      }
      // Static files: the parts, then the built page.
      const root = path.startsWith("/parts/") ? partsDir : dist;
      const relative = path.startsWith("/parts/") ? path.slice("/parts/".length) : path.slice(1);
      const file = normalize(join(root, relative === "" ? "index.html" : relative));
      if (!file.startsWith(root)) return json(res, 403, { error: "outside" });
      const data = await readFile(file).catch(() => null);
      if (!data) return json(res, 404, { error: `no ${path}` });
      res.writeHead(200, { "Content-Type": TYPES[extname(file)] ?? "application/octet-stream" });
      res.end(data);
    } catch (error) {
      json(res, 500, { error: String(error) });
    }
  });

  return new Promise((ready) => {
    server.listen(port, "127.0.0.1", () => {
      ready({
        port: server.address().port,
        close: () =>
          new Promise((done) => {
            server.closeAllConnections();
            server.close(() => done());
          }),
      });
    });
  });
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const args = process.argv.slice(2);
  const option = (name, fallback) => {
    const at = args.indexOf(name);
    return at >= 0 ? args[at + 1] : fallback;
  };
  const { port } = await startMockServer({
    port: Number(option("--port", "8765")),
    dist: resolve(option("--dist", resolve(here, "../dist"))),
  });
  console.log(`mock lab at http://127.0.0.1:${port}/`);
}
