// A stand-in for `frictionlab serve` for testing the page only (docs/web-api.md): serves a built
// page and the LEGO parts, and plays back what the lab's server answered, recorded by
// `frictionlab-api-recording` from web/tests/mock_recording.json (src/serve/api_recording.hpp):
// the scenes and Table I offered, each recorded set-up's rig or refusal, its run's states, class
// rows and summary, and a fake board on a fake serial port sending a simulated run's Hall lines
// with what the rig's estimator judged in them. It holds no physics and no table of its own: what
// it adds is bookkeeping (ids, keys, the wall clock, a session's playback and the port's state),
// and its replies are held to the lab's declaration of the API (tests/mock_contract.test.mjs). As
// the lab, it runs a session on the wall clock (simulated time = wall time x speed, however often
// its stream ticks) and obeys only requests that carry the session's key. A set-up it has no
// recording of is refused, saying where to add it.
//
//   node tests/mock_server.mjs --recording FILE [--port 8765] [--dist DIR]
//   (FILE: the build's web/mock-recording.json; or the environment's FRICTIONLAB_MOCK_RECORDING)
//
// For the tests, beside the API: GET /__mock/log (the requests it was sent), /__mock/rig (the
// fake board's periods shown so far, as the lab's estimator judged them), /__mock/rig-unplug (the
// fake board goes away), /__mock/rig-shared (may_choose false from now on, until
// /__mock/rig-shared?off), /__mock/refuse?path=P&count=N (the next N requests to a path ending in
// P answer 429), /__mock/close-streams (every stream gets `event: closed`, as when the server
// stops) and /__mock/streams?session=ID (how many streams of that session are open).
import { execFileSync } from "node:child_process";
import { randomBytes } from "node:crypto";
import { mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { createServer } from "node:http";
import { readFile } from "node:fs/promises";
import { dirname, extname, join, normalize, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { importTs } from "./import_ts.mjs";

const here = dirname(fileURLToPath(import.meta.url));
const partsDir = resolve(here, "../../assets/lego");

/** A name for the class's table: the server's rule, as the page keeps it (web/src/student_name.ts). */
const { problemOf: nameProblem } = await importTs(resolve(here, "../src/student_name.ts"));

/** The recording the mock plays (src/serve/api_recording.hpp says what it holds). */
export async function readRecording(path = process.env.FRICTIONLAB_MOCK_RECORDING) {
  if (!path) {
    throw new Error(
      "mock_server: no recording: give --recording FILE or FRICTIONLAB_MOCK_RECORDING (the " +
        "build writes web/mock-recording.json; `cmake --build build/release --target " +
        "web-mock-recording` makes it)",
    );
  }
  return JSON.parse(await readFile(path, "utf8"));
}

// The fake board: a stand-in for the rig's Arduino on a serial port. Once its port is opened (and
// the 0.3 s an Uno takes to reset), it sends the recorded Hall lines as wall-clock time passes;
// each page's `rig` events carry them with what the lab's estimator judged in them by then, with
// the page's spacing (the recording has a reading for each spacing of its set-ups).
export const FAKE_RIG_PORT = "/dev/ttyFAKE0";
const FAKE_RIG_BOOT_S = 0.3; // an Uno resets when its port opens: nothing comes for this long

class FakeBoard {
  constructor(board) {
    this.board = board;
    this.ports = [FAKE_RIG_PORT];
    this.mayChoose = true;
    this.port = null;
    this.state = "closed";
    this.message = null;
    this.said = null;
    this.run = 0;
    this.logName = null;
    this.openedAt = 0;
    this.sampleCount = 0; // the samples sent since the port opened
  }
  open(port) {
    this.port = port;
    this.state = "waiting";
    this.message = null;
    this.said = null;
    this.run = 0;
    this.logName = null;
    this.openedAt = Date.now();
    this.sampleCount = 0;
  }
  close() {
    this.advance();
    if (this.state !== "waiting" && this.state !== "receiving") return; // as the server does
    this.state = "closed";
    this.message = null;
    this.said = null;
  }
  unplug() {
    this.advance();
    this.state = "unplugged";
    // As the lab says it (src/serve/board_feed.cpp): in English, and as the catalogues' message.
    const time = new Date().toTimeString().slice(0, 8);
    this.message =
      `${this.port} went away at ${time} (the board unplugged?): the ${this.lines} lines ` +
      "received are kept, download them below; plug the board in and connect again";
    this.said = {
      id: "port-unplugged",
      args: [
        { name: "port", text: this.port },
        { name: "time", text: time },
        { name: "lines", number: this.lines },
      ],
    };
  }
  /** Sends the samples due by now (none once the recording's end is reached). */
  advance() {
    if (this.state !== "waiting" && this.state !== "receiving") return;
    const now = (Date.now() - this.openedAt) / 1000 - FAKE_RIG_BOOT_S;
    if (now < 0) return;
    if (this.logName === null) {
      this.logName = `rig-fake-${new Date(this.openedAt).toISOString().replace(/[-:]|\..*/g, "")}.log`;
      this.state = "receiving";
    }
    const { t_us: tUs } = this.board;
    while (this.sampleCount < tUs.length && (tUs[this.sampleCount] - tUs[0]) * 1e-6 <= now) {
      this.sampleCount += 1;
    }
  }
  get lines() {
    return this.logName === null ? 0 : 2 + this.sampleCount;
  }
  /** The raw log as the board sent it. */
  log() {
    const lines = [this.board.header, "t_us,adc"];
    for (let i = 0; i < this.sampleCount; i++) {
      lines.push(`${this.board.t_us[i]},${this.board.adc[i]}`);
    }
    return `${lines.join("\n")}\n`;
  }
  /** The estimator's changes with l = `spacing` up to the samples sent. */
  changes(spacing) {
    const reading = this.board.readings.find((r) => r.spacing === spacing);
    if (!reading)
      throw new Error(`the recording has no reading of the board with l = ${spacing} m`);
    return reading.changes.filter((c) => c.samples <= this.sampleCount);
  }
  /** Every period judged so far (with the first set-up's spacing: periods do not depend on it). */
  periods() {
    if (this.port === null) return [];
    this.advance();
    return this.changes(this.board.readings[0].spacing).flatMap((c) => c.periods);
  }
  status() {
    this.advance();
    return {
      ports: this.mayChoose ? this.ports : [], // a shared server lists none
      may_choose: this.mayChoose,
      port: this.port,
      baud: this.port === null ? null : this.board.baud, // the firmware's, as recorded
      state: this.state,
      message: this.message,
      said: this.said,
      lines: this.lines,
      log_name: this.logName,
    };
  }
  /** A stream's next rig event from its cursor (null: nothing changed), with its spacing. */
  eventFor(cursor, spacing) {
    if (this.port === null) return null;
    this.advance();
    const { t_us: tUs, adc } = this.board;
    if (cursor.run !== this.run || cursor.opened !== this.openedAt) {
      // A new stream, or a new port or board run: the last 10 s and every period of the run.
      Object.assign(cursor, { run: this.run, opened: this.openedAt, sample: 0, change: 0 });
    }
    const last = this.sampleCount > 0 ? (tUs[this.sampleCount - 1] - tUs[0]) * 1e-6 : 0;
    let first = cursor.sample;
    while (first < this.sampleCount && (tUs[first] - tUs[0]) * 1e-6 < last - this.board.shown_s)
      first++;
    const hall = [];
    for (let i = first; i < this.sampleCount; i++) hall.push([(tUs[i] - tUs[0]) * 1e-6, adc[i]]);
    const changes = this.changes(spacing);
    const fresh = changes.slice(cursor.change);
    const key = `${this.state}|${this.message}|${this.lines}`;
    if (hall.length === 0 && fresh.length === 0 && key === cursor.key) return null;
    cursor.sample = this.sampleCount;
    cursor.change = changes.length;
    cursor.key = key;
    const now = changes.at(-1);
    return {
      port: this.port,
      state: this.state,
      message: this.message,
      said: this.said,
      lines: this.lines,
      run: this.run,
      hall,
      periods: fresh.flatMap((c) => c.periods),
      estimate: now?.estimate ?? null,
      geometry: now?.geometry ?? "unknown",
      spacing,
    };
  }
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

/** A 4xx's body as the lab's: the error and its problems by field (none for the API's own). */
function errorBody(error, problems = []) {
  return { error, problems };
}

async function readBody(req) {
  const chunks = [];
  for await (const chunk of req) chunks.push(chunk);
  return Buffer.concat(chunks).toString("utf8");
}

/** A recorded set-up's key: its scene and its set entries, in any order. */
function setUpKey(scene, set) {
  return JSON.stringify([scene, [...set].sort()]);
}

/** A number as C's %.10g writes it (the lab's class.csv). */
function g10(value) {
  const exponent = Number(value.toExponential(9).split("e")[1]);
  const strip = (digits) => (digits.includes(".") ? digits.replace(/\.?0+$/, "") : digits);
  if (exponent < -4 || exponent >= 10) {
    const [mantissa] = value.toExponential(9).split("e");
    const sign = exponent < 0 ? "-" : "+";
    return `${strip(mantissa)}e${sign}${String(Math.abs(exponent)).padStart(2, "0")}`;
  }
  return strip(value.toFixed(9 - exponent));
}

/** `values` as CSV cells, as the lab writes them (an empty cell for null). */
function csvLine(values) {
  return values
    .map((value) => {
      if (value === null || value === undefined) return "";
      const text = typeof value === "number" ? g10(value) : String(value);
      return /[",\n]/.test(text) ? `"${text.replaceAll('"', '""')}"` : text;
    })
    .join(",");
}

/** Arrays of events that carry what came since the last one: merged by joining them. */
const SINCE_LAST = ["hall", "pulses", "periods"];

// A session: a recorded run played on the wall clock. Its frames are the lab's states a frame
// interval apart; a stream sends, at each tick, the frames reached since its last one as one state
// (their samples, pulses and periods joined; the rest as of the last).
class Playback {
  constructor(setup, interval, name = null) {
    this.setup = setup;
    this.frames = setup.frames;
    this.interval = interval;
    this.name = name;
    this.key = randomBytes(16).toString("hex"); // only requests that carry it control the run
    this.speed = 1;
    this.resets = 0;
    this.reset();
  }
  get rig() {
    return this.setup.body.rig;
  }
  reset() {
    this.wallAt = performance.now();
    this.time = 0; // s of simulated time reached
    this.index = 0; // the frame reached
    this.sent = 0; // the frames whose increments were sent
    this.playing = false;
    this.done = false;
    this.doneSent = false;
  }
  /** The frame reached at simulated time `time`. */
  reach(time) {
    const last = this.frames.length - 1;
    this.time = time;
    this.index = Math.min(last, Math.floor(time / this.interval + 1e-9));
    if (this.index === last) {
      this.done = true;
      this.playing = false;
    }
  }
  /** Advances a playing run to the wall clock's `now` [ms], at its speed. */
  catchUp(now) {
    if (this.playing) this.reach(this.time + (this.speed * (now - this.wallAt)) / 1000);
    this.wallAt = now;
  }
  step() {
    if (!this.playing && !this.done) this.reach((this.index + 1) * this.interval);
  }
  get t() {
    return this.frames[this.index].state.t;
  }
  /** The next `state` event: the frames since the last one, merged. */
  state() {
    const state = { ...this.frames[this.index].state };
    for (const key of SINCE_LAST) {
      state[key] = this.frames.slice(this.sent + 1, this.index + 1).flatMap((f) => f.state[key]);
    }
    this.sent = Math.max(this.sent, this.index);
    state.playing = this.playing;
    state.speed = this.speed;
    return state;
  }
  /** The session's row of the class's table (GET /api/class). */
  classRow(id) {
    const state = this.done && this.doneSent ? "done" : this.playing ? "playing" : "paused";
    return { ...this.frames[this.index].row, session: id, name: this.name, state };
  }
  summary() {
    return this.setup.summary;
  }
}

/** The page built (web/build.mjs) into a temporary folder and served by the mock: its address,
 * the server, and how to stop both (the folder removed). */
export async function startBuiltPage() {
  const dist = mkdtempSync(join(tmpdir(), "frictionlab-web-"));
  execFileSync(process.execPath, [resolve(here, "../build.mjs"), dist], { stdio: "inherit" });
  const server = await startMockServer({ dist });
  return {
    base: `http://127.0.0.1:${server.port}`,
    server,
    stop: async () => {
      await server.close();
      rmSync(dist, { recursive: true, force: true });
    },
  };
}

export async function startMockServer({
  port = 0,
  dist = resolve(here, "../dist"),
  recording = process.env.FRICTIONLAB_MOCK_RECORDING,
} = {}) {
  const recorded = typeof recording === "object" ? recording : await readRecording(recording);
  const setUps = new Map(recorded.setups.map((s) => [setUpKey(s.scene, s.set), s]));
  const classColumns = recorded.declaration.objects.ClassRow.filter((k) => k.csv);
  const sessions = new Map();
  const log = [];
  const rig = new FakeBoard(recorded.board);
  const streams = new Map(); // every open stream's response, and its session's id
  const refusals = new Map(); // path -> how many more requests answer 429
  let rigOpened = false; // /api/class's rig: null until a port was opened
  let nextId = 1;

  const server = createServer(async (req, res) => {
    const url = new URL(req.url, "http://localhost");
    const path = url.pathname;
    try {
      if (path === "/__mock/log") return json(res, 200, log);
      if (path === "/__mock/rig") return json(res, 200, { periods: rig.periods(), run: rig.run });
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
        // As the lab says it (src/serve/lab_server.cpp): in English, and as the catalogues' message.
        const said = {
          id: "server-too-many",
          args: [
            { name: "address", text: "127.0.0.1" },
            { name: "per_second", number: 20 },
            { name: "wait_s", number: 1 },
          ],
        };
        const error = "too many requests from 127.0.0.1: at most 20 a second; wait 1 s";
        res.end(JSON.stringify({ ...errorBody(error), said }));
        return;
      }
      if (path === "/api/rig" && req.method === "GET") return json(res, 200, rig.status());
      if (path === "/api/rig" && req.method === "POST") {
        const body = JSON.parse(await readBody(req));
        log.push({ rig: body });
        if (!rig.mayChoose) {
          return json(res, 403, errorBody("this lab is shared: only its own computer chooses"));
        }
        if (typeof body.port === "string") {
          if (!rig.ports.includes(body.port)) {
            return json(res, 400, errorBody(`no port ${body.port}: GET /api/rig lists the ports`));
          }
          rig.open(body.port);
          rigOpened = true;
        } else if (body.action === "close") rig.close();
        else return json(res, 400, errorBody('expected {"port": ...} or {"action": "close"}'));
        return json(res, 200, rig.status());
      }
      if (path === "/api/rig/log" && req.method === "GET") {
        rig.advance();
        if (rig.lines === 0) return json(res, 404, errorBody("no line came from the rig yet"));
        res.writeHead(200, {
          "Content-Type": "text/plain; charset=utf-8",
          "Content-Disposition": `attachment; filename="${rig.logName}"`,
        });
        res.end(rig.log());
        return;
      }
      if ((path === "/api/class" || path === "/api/class.csv") && req.method === "GET") {
        const rows = [...sessions].map(([id, run]) => run.classRow(id));
        if (path === "/api/class.csv") {
          res.writeHead(200, {
            "Content-Type": "text/csv; charset=utf-8",
            "Content-Disposition": 'attachment; filename="class.csv"',
          });
          const lines = [csvLine(classColumns.map((k) => k.csv))];
          for (const row of rows) {
            lines.push(
              csvLine(
                classColumns.map((k) => {
                  const value = row[k.name];
                  return typeof value === "number" ? value * k.csv_scale : value;
                }),
              ),
            );
          }
          res.end(`${lines.join("\n")}\n`);
          return;
        }
        const { port, state, lines } = rig.status();
        return json(res, 200, { sessions: rows, rig: rigOpened ? { port, state, lines } : null });
      }
      if (path === "/api/lab" && req.method === "GET") return json(res, 200, recorded.lab);
      if (path === "/api/sessions" && req.method === "POST") {
        const body = JSON.parse(await readBody(req));
        log.push({ create: body });
        const setup = setUps.get(setUpKey(body.scene, body.set ?? []));
        if (!setup) {
          const problem = {
            field: "set",
            value: null,
            message:
              `the mock has no recording of the set-up ${JSON.stringify(body)}: add it to ` +
              "web/tests/mock_recording.json's set-ups and build again",
            said: null,
          };
          return json(res, 400, errorBody("the set-up has 1 problem", [problem]));
        }
        const name = body.name ?? null;
        const problems = setup.status === 201 ? [] : [...setup.body.problems];
        if (
          name !== null &&
          (typeof name !== "string" || name === "" || nameProblem(name) !== null)
        ) {
          problems.push({
            field: "name",
            value: String(name),
            message: "expected up to 40 letters, digits, spaces and . - _ ' , ( )",
            said: null,
          });
        }
        if (problems.length > 0) {
          const count = `${problems.length} problem${problems.length === 1 ? "" : "s"}`;
          return json(res, 400, errorBody(`the set-up has ${count}`, problems));
        }
        const id = String(nextId++);
        const run = new Playback(setup, recorded.frame_interval_s, name);
        sessions.set(id, run);
        return json(res, 201, { id, key: run.key, rig: run.rig });
      }
      const match = /^\/api\/sessions\/([^/]+)(\/.*)?$/.exec(path);
      if (match) {
        const [, id, rest = ""] = match;
        const run = sessions.get(id);
        if (!run) return json(res, 404, errorBody(`no session ${id}`));
        // As the lab: the session's id is public, its key is the page's that opened it, in a
        // header (in the address only for a GET: a stream, a download).
        const key =
          req.headers["x-session-key"] ??
          (req.method === "GET" ? url.searchParams.get("key") : undefined);
        if (key !== run.key) {
          log.push({ refused: id, path: rest, method: req.method });
          return json(
            res,
            403,
            errorBody(
              `session ${id} is controlled only by the page that opened it: this request ${key ? "carries another key" : "carries no session key"}`,
            ),
          );
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
          else if (body.action === "step") run.step();
          else if (body.action === "reset") {
            run.reset();
            run.resets += 1;
          } else if ([1, 0.25, 0.0625].includes(body.speed)) run.speed = body.speed;
          else if ("name" in body) {
            // A student named after the session began (the lab's rule; "" takes it away).
            if (typeof body.name !== "string" || (body.name !== "" && nameProblem(body.name))) {
              const message =
                "expected a name of up to 40 letters, digits, spaces and . - _ ' , ( )";
              return json(res, 400, errorBody(message, [{ field: "name", value: null, message }]));
            }
            run.name = body.name === "" ? null : body.name;
          } else return json(res, 400, errorBody("unknown control"));
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
              const summary = run.summary();
              if (summary.failure !== null) {
                res.write(
                  `event: failed\ndata: ${JSON.stringify({ message: summary.failure })}\n\n`,
                );
              }
              res.write(`event: done\ndata: ${JSON.stringify(summary)}\n\n`);
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
          if (!run.done) return json(res, 404, errorBody("the run is not done"));
          const name = decodeURIComponent(file[1]);
          if (name === "summary.json") return json(res, 200, run.summary());
          if (["trajectory.csv", "hall.csv", "periods.csv"].includes(name)) {
            res.writeHead(200, { "Content-Type": "text/csv" });
            res.end("t,value\n0,0\n");
            return;
          }
          return json(res, 404, errorBody(`no file ${name}`));
        }
        return json(res, 404, errorBody("not found"));
      }
      // Static files: the parts, then the built page.
      const root = path.startsWith("/parts/") ? partsDir : dist;
      const relative = path.startsWith("/parts/") ? path.slice("/parts/".length) : path.slice(1);
      const file = normalize(join(root, relative === "" ? "index.html" : relative));
      if (!file.startsWith(root)) return json(res, 403, errorBody("outside"));
      const data = await readFile(file).catch(() => null);
      if (!data) return json(res, 404, errorBody(`no ${path}`));
      res.writeHead(200, { "Content-Type": TYPES[extname(file)] ?? "application/octet-stream" });
      res.end(data);
    } catch (error) {
      json(res, 500, errorBody(String(error)));
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
    recording: option("--recording", process.env.FRICTIONLAB_MOCK_RECORDING),
  });
  console.log(`mock lab at http://127.0.0.1:${port}/`);
}
