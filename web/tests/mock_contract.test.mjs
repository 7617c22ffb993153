// The page's mock server (tests/mock_server.mjs) held to the lab's one declaration of its web API
// (src/api/api_fields.hpp, in the recording the mock plays), route by route, as
// tests/serve/server_contract_test.cpp holds the real server to it: the bodies it plays back (made
// by the lab) and those it makes itself (ids and keys, controls, the class's table, the fake
// board's port and events, refusals). The checker is first shown to find what it must.
//
//   FRICTIONLAB_MOCK_RECORDING=build/release/web/mock-recording.json node tests/mock_contract.test.mjs
import { get } from "node:http";
import { contractProblems } from "./api_contract.mjs";
import { FAKE_RIG_PORT, readRecording, startMockServer } from "./mock_server.mjs";

const recording = await readRecording();
const declaration = recording.declaration;
let checked = 0;
const failures = [];
function hold(body, type, what) {
  checked += 1;
  for (const problem of contractProblems(declaration, body, type, what)) failures.push(problem);
}
function expect(condition, message) {
  if (!condition) failures.push(message);
}

// The checker finds a missing key, an undeclared one, a null and a wrong type.
const broken = contractProblems(
  declaration,
  { normal: null, friction: "1", force: 2 },
  "ContactForce[]",
  "contacts",
);
expect(broken.length === 1, `the checker said ${JSON.stringify(broken)} of an object for an array`);
const named = contractProblems(declaration, { normal: null, force: 2 }, "ContactForce", "c");
expect(
  named.join("|") ===
    [
      "c.normal: null, but not declared nullable",
      "c.friction: declared, but not there",
      "c.force: not declared for ContactForce (src/api/api_fields.cpp)",
    ].join("|"),
  `the checker said ${JSON.stringify(named)}`,
);

// What the mock plays back, as the lab recorded it.
hold(recording.lab, "Lab", "lab");
for (const setup of recording.setups) {
  const what = `${setup.scene} ${JSON.stringify(setup.set)}`;
  if (setup.status !== 201) {
    hold(setup.body, "ErrorBody", what);
    continue;
  }
  hold(setup.body.rig, "Rig", `${what} rig`);
  setup.frames.forEach((frame, i) => {
    hold(frame.state, "LabState", `${what} state ${i}`);
    hold(frame.row, "ClassRow", `${what} row ${i}`);
  });
  hold(setup.summary, "RunSummaryJson", `${what} done`);
}
for (const reading of recording.board.readings) {
  for (const change of reading.changes) {
    hold(change.periods, "PeriodRow[]", "board periods");
    if (change.estimate !== null) hold(change.estimate, "Estimate", "board estimate");
    hold(change.geometry, "PulseGeometry", "board geometry");
  }
}

// What the mock answers, route by route.
const server = await startMockServer({ recording });
const base = `http://127.0.0.1:${server.port}`;
async function call(path, { method = "GET", body, key } = {}) {
  const headers = key ? { "X-Session-Key": key } : {};
  const res = await fetch(`${base}${path}`, {
    method,
    headers,
    body: body === undefined ? undefined : JSON.stringify(body),
  });
  const text = await res.text();
  return { status: res.status, body: text === "" ? null : JSON.parse(text) };
}

/** The stream's events until `enough` says so (or 60 s), as [name, data]. */
function streamUntil(path, enough) {
  return new Promise((resolve, reject) => {
    const events = [];
    const deadline = setTimeout(() => {
      request.destroy();
      resolve(events);
    }, 60000);
    const request = get(`${base}${path}`, (res) => {
      let buffer = "";
      res.on("data", (chunk) => {
        buffer += chunk;
        for (let end; (end = buffer.indexOf("\n\n")) >= 0;) {
          const block = buffer.slice(0, end);
          buffer = buffer.slice(end + 2);
          const [nameLine, dataLine] = block.split("\n");
          events.push([nameLine.slice("event: ".length), JSON.parse(dataLine.slice(6))]);
        }
        if (enough(events)) {
          clearTimeout(deadline);
          request.destroy();
          resolve(events);
        }
      });
    });
    request.on("error", (error) => (error.code === "ECONNRESET" ? null : reject(error)));
  });
}

try {
  hold((await call("/api/lab")).body, "Lab", "GET /api/lab");
  hold((await call("/api/rig")).body, "LiveRig", "GET /api/rig");
  const opened = await call("/api/rig", { method: "POST", body: { port: FAKE_RIG_PORT } });
  hold(opened.body, "LiveRig", "POST /api/rig");
  const wrongPort = await call("/api/rig", { method: "POST", body: { port: "/dev/none" } });
  expect(wrongPort.status === 400, `a port not listed: ${wrongPort.status}`);
  hold(wrongPort.body, "ErrorBody", "POST /api/rig, a port not listed");

  const set = ["world.duration=5s", "plate.material=iron", "rollers.spacing=60mm"];
  const created = await call("/api/sessions", {
    method: "POST",
    body: { scene: "minimal", set, name: "Ada" },
  });
  expect(created.status === 201, `created: ${created.status}`);
  hold(created.body, "Session", "POST /api/sessions");
  const { id, key } = created.body;
  for (const [body, what] of [
    [{ scene: "minimal", set: ["rollers.runout=-1mm"] }, "a refused set-up"],
    [{ scene: "minimal", set: ["rollers.spacing=1mm"] }, "a set-up not recorded"],
    [{ scene: "minimal", set: [], name: "=1+1" }, "a name that is not one"],
  ]) {
    const refused = await call("/api/sessions", { method: "POST", body });
    expect(refused.status === 400, `${what}: ${refused.status}`);
    hold(refused.body, "ErrorBody", what);
  }
  const control = `/api/sessions/${id}/control`;
  for (const body of [{ speed: 0.25 }, { action: "step" }, { action: "reset" }, { speed: 1 }]) {
    hold((await call(control, { method: "POST", body, key })).body, "ControlReply", control);
  }
  const foreign = await call(control, { method: "POST", body: { action: "play" }, key: "0" });
  expect(foreign.status === 403, `another key: ${foreign.status}`);
  hold(foreign.body, "ErrorBody", "a control with another key");
  const unknown = await call(control, { method: "POST", body: { action: "fly" }, key });
  hold(unknown.body, "ErrorBody", "an unknown control");
  hold(
    (await call(control, { method: "POST", body: { action: "play" }, key })).body,
    "ControlReply",
    control,
  );

  // The run to its end and the board to its first estimate.
  const events = await streamUntil(
    `/api/sessions/${id}/stream?key=${key}`,
    (seen) =>
      seen.some(([name]) => name === "done") &&
      seen.some(([name, data]) => name === "rig" && data.estimate !== null),
  );
  const types = {
    state: "LabState",
    done: "RunSummaryJson",
    failed: "Failure",
    rig: "LiveRigEvent",
  };
  for (const [name, data] of events) {
    if (name in types) hold(data, types[name], `event: ${name}`);
    else expect(name === "reset", `an event the API has not: ${name}`);
  }
  expect(
    events.some(([name]) => name === "done"),
    "the run did not end",
  );
  expect(
    events.some(([name, data]) => name === "rig" && data.estimate !== null),
    "the board's estimate did not come",
  );
  expect(
    events.some(([name, data]) => name === "state" && data.estimate !== null),
    "the run's estimate did not come",
  );

  const table = await call("/api/class");
  hold(table.body, "ClassTable", "GET /api/class");
  const csv = await (await fetch(`${base}/api/class.csv`)).text();
  const columns = declaration.objects.ClassRow.filter((k) => k.csv).map((k) => k.csv);
  expect(csv.split("\n")[0] === columns.join(","), `class.csv's header: ${csv.split("\n")[0]}`);
  const summary = await call(`/api/sessions/${id}/files/summary.json?key=${key}`);
  hold(summary.body, "RunSummaryJson", "files/summary.json");
  hold((await call(`/api/sessions/${id}/files/none.csv?key=${key}`)).body, "ErrorBody", "no file");
  hold(
    (await call("/api/sessions/999/control", { method: "POST", body: {} })).body,
    "ErrorBody",
    "no session",
  );
  await fetch(`${base}/__mock/refuse?path=/api/lab&count=1`);
  const busy = await call("/api/lab");
  expect(busy.status === 429, `refused: ${busy.status}`);
  hold(busy.body, "ErrorBody", "429");
} finally {
  await server.close();
}

for (const failure of failures) console.error(failure);
console.log(
  `mock contract: ${checked} bodies held to the declaration, ${failures.length} problems`,
);
process.exit(failures.length === 0 ? 0 : 1);
