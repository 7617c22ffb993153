// A stand-in for `frictionlab serve` for testing the page only (docs/web-api.md): serves a built
// page, the LEGO parts, and fakes the lab's API with a harmonic plate. Not the lab's physics.
//
//   node tests/mock_server.mjs [--port 8765] [--dist DIR]
import { createServer } from "node:http";
import { readFile } from "node:fs/promises";
import { dirname, extname, join, normalize, resolve } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const partsDir = resolve(here, "../../assets/lego");
const G = 9.81;
const DURATION = 4.0; // s: the mock's runs are short

const SCENES = [
  { name: "minimal", title: "The minimal rig: a plate on two counter-rotating rollers" },
  { name: "paper-rig", title: 'The paper\'s rig (Henaff et al., section "Experimental setup")' },
  { name: "stribeck-drop", title: "Stability catalogue: stribeck-drop" },
];

const MATERIALS = [
  ["lego", "LEGO blocks", 0.29, 0.2],
  ["paper", "Paper", 0.36, null],
  ["polished-wood", "Polished wood", 0.33, 0.113],
  ["construction-wood", "Construction wood", 0.31, 0.052],
  ["iron", "Iron", 0.42, null],
  ["plexiglas", "Plexiglas", 0.28, 0.111],
  ["brass", "Brass", 0.31, null],
  ["cardboard", "Cardboard", 0.2, null],
  ["rigid-foam", "Polyurethane rigid foam", 1.7, null],
  ["flexible-foam", "Polyurethane flexible foam", 10, 0.34],
];

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
    }
  }
  const material = MATERIALS.find((m) => m[0] === rig.plate.material);
  rig.mu_k = (temperature === 77 ? material[3] : material[2]) ?? material[2];
  rig.omega = Math.sqrt((2 * rig.mu_k * G) / rig.spacing);
  rig.period_thin = (2 * Math.PI) / rig.omega;
  rig.period_thick = rig.period_thin * 1.01;
  return { rig, problems };
}

class FakeRun {
  constructor(rig) {
    this.rig = rig;
    this.speed = 1;
    this.resets = 0;
    this.reset();
  }
  reset() {
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
    const to = Math.min(DURATION, from + dt);
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
    if (this.t >= DURATION) {
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

export function startMockServer({ port = 0, dist = resolve(here, "../dist") } = {}) {
  const sessions = new Map();
  const log = [];
  let nextId = 1;

  const server = createServer(async (req, res) => {
    const url = new URL(req.url, "http://localhost");
    const path = url.pathname;
    try {
      if (path === "/__mock/log") return json(res, 200, log);
      if (path === "/api/lab" && req.method === "GET") {
        return json(res, 200, {
          scenes: SCENES,
          materials: MATERIALS.map(([key, name, , cold]) => ({
            key,
            name,
            temperatures_K: cold === null ? [300] : [300, 77],
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
        const { rig, problems } = makeRig(body.scene, body.set ?? []);
        if (problems.length > 0) {
          return json(res, 400, { error: `the set-up has ${problems.length} problem`, problems });
        }
        const id = String(nextId++);
        sessions.set(id, new FakeRun(rig));
        return json(res, 201, { id, rig });
      }
      const match = /^\/api\/sessions\/([^/]+)(\/.*)?$/.exec(path);
      if (match) {
        const [, id, rest = ""] = match;
        const run = sessions.get(id);
        if (!run) return json(res, 404, { error: `no session ${id}` });
        if (rest === "" && req.method === "DELETE") {
          sessions.delete(id);
          log.push({ end: id });
          res.writeHead(204).end();
          return;
        }
        if (rest === "/control" && req.method === "POST") {
          const body = JSON.parse(await readBody(req));
          log.push({ control: id, body });
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
          const tick = setInterval(() => {
            if (run.resets !== resetsSeen) {
              resetsSeen = run.resets;
              res.write("event: reset\ndata: {}\n\n");
            }
            if (run.playing) run.advance(run.speed / 30);
            res.write(`event: state\ndata: ${JSON.stringify(run.state())}\n\n`);
            if (run.done && !run.doneSent) {
              run.doneSent = true;
              res.write(`event: done\ndata: ${JSON.stringify(run.summary())}\n\n`);
            }
          }, 1000 / 30);
          req.on("close", () => clearInterval(tick));
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
