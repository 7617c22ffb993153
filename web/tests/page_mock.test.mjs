// Drives the built page against tests/mock_server.mjs in headless Chromium (software WebGL):
// no console errors, the period readout fills, a refused spacing shows its problem beside the
// spacing control, links open their set-up and play, the stopwatch runs, the live rig's panel
// connects the mock's fake port and shows its periods, estimate and log, the student's name
// reaches the class's table (class.html and class.csv), a 429 and the server's `closed` are
// shown as the lab's words, the session's key goes with every control and nowhere else; a
// screenshot at 1366x768 goes to $SHOT (default /tmp/web-shot.png).
//
// Nothing here depends on the machine's pace: a pace is judged against the simulated time the
// page received, with tolerances from the gaps between its events; a wait is for an event or a
// condition, with a generous deadline (WAIT_MS), never a sleep that hopes it is long enough.
//
//   node tests/page_mock.test.mjs        (builds the page into a temporary folder first)
import { readFileSync } from "node:fs";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { FAKE_RIG_PORT, startBuiltPage } from "./mock_server.mjs";
import {
  check,
  expect,
  finish,
  launchChromium,
  openWatchedPage,
  skipWithoutChromium,
  WAIT_MS,
} from "./browser_checks.mjs";

const web = resolve(dirname(fileURLToPath(import.meta.url)), "..");
const shot = process.env.SHOT ?? "/tmp/web-shot.png";
skipWithoutChromium();

const { base, stop } = await startBuiltPage();
const browser = await launchChromium();

/** Waits for `condition` (async) to hold, looking every 50 ms; fails after `deadlineMs`. */
async function waitUntil(condition, what, deadlineMs = WAIT_MS) {
  const until = Date.now() + deadlineMs;
  while (!(await condition())) {
    if (Date.now() > until) throw new Error(`waited ${deadlineMs} ms for ${what}`);
    await new Promise((done) => setTimeout(done, 50));
  }
}

/** Runs in each page before its own script: records the page's streams (every EventSource it
 * makes), each `state` event's arrival (the page's clock) with its t and speed, and each Space
 * press with the t of the last state the page had then. */
function recordStreams() {
  const lab = { sources: [], states: [], spaces: [] };
  window.__lab = lab;
  const PageEventSource = window.EventSource;
  window.EventSource = class extends PageEventSource {
    constructor(url, init) {
      super(url, init);
      lab.sources.push(this);
      this.addEventListener("state", (event) => {
        const { t, speed } = JSON.parse(event.data);
        lab.states.push({ at: performance.now(), t, speed });
      });
    }
  };
  window.addEventListener(
    "keydown",
    (event) => {
      if (event.code === "Space") {
        lab.spaces.push({ at: performance.now(), t: lab.states.at(-1)?.t ?? null });
      }
    },
    true,
  );
}

/** A page that records console errors and warnings, and its streams. */
function openPage(path, viewport = { width: 1366, height: 768 }) {
  return openWatchedPage(
    browser,
    `${base}${path}`,
    { viewport, acceptDownloads: true },
    recordStreams,
  );
}

/** A period as the lab's ± rule writes it: the value to the uncertainty's last digit. */
const periodText = /^T = \d+\.(\d+) ± \d+\.(\d+) s$/;
const isPeriodText = (text) => {
  const parts = periodText.exec(text);
  return parts !== null && parts[1].length === parts[2].length;
};

await check("the default scene loads paused, plays, fills the period and ends done", async () => {
  const { page, context, complaints } = await openPage("/");
  await page.getByTestId("spacing").filter({ hasText: "89 mm" }).waitFor();
  expect((await page.locator("#scene").inputValue()) === "paper-rig", "paper-rig is not chosen");
  expect((await page.getByTestId("status").textContent()) === "paused", "not paused at first");
  expect((await page.getByTestId("play").textContent()) === "Play", "play button label");
  // the LEGO parts arrive
  await page.waitForFunction(() =>
    performance
      .getEntriesByType("resource")
      .some((entry) => entry.name.endsWith("/parts/technic-brick-1x16.glb")),
  );
  await page.getByTestId("play").click();
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  await page.waitForFunction(() =>
    /T = \d.* ± /.test(document.querySelector('[data-testid="period"]').textContent),
  );
  const running = await page.getByTestId("period").textContent();
  expect(isPeriodText(running), `period readout reads "${running}"`);
  // The standard error in two significant digits (the paper's rig: a few 1e-5 s), never 0.0000,
  // and what it is; the regime, and what it means.
  const detail = await page.getByTestId("period-detail").textContent();
  const se = /σ\/√N, ([\d.]+) s/.exec(detail);
  expect(se && Number(se[1]) > 0 && /[1-9]\d?$/.test(se[1]), `the standard error: "${detail}"`);
  await page.getByTestId("regime-help").filter({ hasText: "Both rollers slip" }).waitFor();
  await page
    .getByTestId("status")
    .filter({ hasText: /^done$/ })
    .waitFor();
  await page.getByTestId("period-detail").filter({ hasText: "the run's result" }).waitFor();
  const final = await page.getByTestId("period").textContent();
  expect(isPeriodText(final), `done period readout reads "${final}"`);
  expect(/μₖ = \d/.test(await page.getByTestId("mu-k").textContent()), "mu_k readout empty");
  const rows = await page.locator("#periods-body tr").count();
  expect(rows >= 2, `${rows} period rows`);
  // A download is an address: it carries the session's key (?key=), the page's only.
  const href = await page.getByTestId("file-summary").getAttribute("href");
  expect(
    /\/api\/sessions\/\d+\/files\/summary\.json\?key=[0-9a-f]{32}$/.test(href ?? ""),
    `summary link ${href}`,
  );
  const summary = await fetch(new URL(href, base));
  expect(summary.status === 200, `the summary link answers ${summary.status}`);
  const keyless = await fetch(new URL(href.replace(/\?key=.*/, ""), base));
  expect(keyless.status === 403, `the summary without the key answers ${keyless.status}`);
  expect((await page.getByTestId("play").textContent()) === "Play again", "play after done");
  await page.screenshot({ path: shot });
  const [download] = await Promise.all([page.waitForEvent("download"), page.click("#png")]);
  expect(download.suggestedFilename() === "frictionlab-view.png", "PNG name");
  // "Play again" runs the same set-up from t = 0
  await page.getByTestId("play").click();
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  await page.getByTestId("period").filter({ hasText: "T = — s" }).waitFor();
  expect(
    await page.getByTestId("file-summary").getAttribute("aria-disabled"),
    "files stay enabled",
  );
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("a refused spacing shows its message beside the spacing control", async () => {
  const { page, context, complaints } = await openPage("/?scene=minimal");
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  const creates = async () =>
    (await (await fetch(`${base}/__mock/log`)).json()).filter((e) => e.create).length;
  // A decimal comma on an English page: refused at the control, never read as 705, never sent.
  const before = await creates();
  await page.fill("#spacing-mm", "70,5");
  await page.press("#spacing-mm", "Enter");
  const problem = page.getByTestId("problem-spacing");
  await problem.filter({ hasText: "decimal point" }).waitFor();
  expect((await page.locator("#spacing-mm").inputValue()) === "89", "the comma's value stays");
  expect((await creates()) === before, "a value the page cannot read was sent");
  // Beyond what the set-up accepts (the rig's `accepts`, the lab's own checks): said here, in
  // the page's words, never sent.
  await page.fill("#spacing-mm", "-5");
  await page.press("#spacing-mm", "Enter");
  await problem.filter({ hasText: "-5 mm is beyond what this set-up accepts, 20.1 to" }).waitFor();
  expect((await creates()) === before, "a value beyond the accepted range was sent");
  expect((await problem.getAttribute("role")) === "alert", "problem is not an alert");
  const field = page.locator(".field", { has: page.locator("#spacing-mm") });
  expect((await field.getByTestId("problem-spacing").count()) === 1, "problem not beside spacing");
  expect((await page.locator("#spacing-mm").inputValue()) === "89", "the control left at -5");
  // What the lab refuses, beside its control: the control shows what the lab runs again.
  await page.fill("#runout-mm", "-1");
  await page.press("#runout-mm", "Enter");
  const runout = page.getByTestId("problem-runout");
  await runout.filter({ hasText: "must be >= 0" }).waitFor();
  expect(
    (await page.locator("#runout-mm").inputValue()) === "",
    `the run-out control shows ${await page.locator("#runout-mm").inputValue()}, the lab runs the scene's`,
  );
  expect((await page.getByTestId("spacing").textContent()).includes("89 mm"), "rig changed");
  // the page stays usable: the running session goes on, another control starts a new one, and a
  // good value starts a new one
  await page.fill("#duration-s", "5");
  await page.press("#duration-s", "Enter");
  await page.waitForFunction(() =>
    new URL(document.querySelector('[data-testid="setup-link"]').value).search.includes(
      "world.duration",
    ),
  );
  await page.fill("#spacing-mm", "70");
  await page.press("#spacing-mm", "Enter");
  await page.getByTestId("spacing").filter({ hasText: "70 mm" }).waitFor();
  expect((await problem.textContent()) === "", "problem stays after a good value");
  expect((await runout.textContent()) === "", "the run-out's problem stays after a good set-up");
  const link = await page.getByTestId("setup-link").inputValue();
  expect(
    link.endsWith("/?scene=minimal&set=rollers.spacing%3D70mm&set=world.duration%3D5s"),
    `link ${link}`,
  );
  const keeps = complaints.filter((c) => !c.includes("400 (Bad Request)"));
  expect(keeps.length === 0, `console: ${keeps.join("\n")}`);
  await context.close();
});

await check("each slider offers only what the set-up accepts", async () => {
  const { page, context } = await openPage("/?scene=paper-rig");
  await page.getByTestId("spacing").filter({ hasText: "89 mm" }).waitFor();
  // The drive's LEGO gears (1 mm module: 24-40-40-24 teeth) span 40 to 104 mm.
  const slider = page.locator("#spacing-mm-range");
  expect((await slider.getAttribute("min")) === "40", `min ${await slider.getAttribute("min")}`);
  expect((await slider.getAttribute("max")) === "104", `max ${await slider.getAttribute("max")}`);
  const hint = await page.getByTestId("accepts-spacing-mm").textContent();
  expect(hint.includes("40 to 104 mm"), `hint: ${hint}`);
  // Pressed to its end, the slider gives a set-up the lab takes.
  await slider.focus();
  await page.keyboard.press("End");
  await page.getByTestId("spacing").filter({ hasText: "104 mm" }).waitFor();
  expect((await page.getByTestId("problem-spacing").textContent()) === "", "104 mm refused");
  await context.close();
});

await check("a link opens its set-up and plays it; unchanged controls send nothing", async () => {
  const { page, context, complaints } = await openPage(
    "/?scene=minimal&set=rollers.spacing%3D60mm&set=plate.material%3Diron&set=world.duration%3D5s",
  );
  await page.getByTestId("spacing").filter({ hasText: "60 mm" }).waitFor();
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  expect((await page.locator("#spacing-mm").inputValue()) === "60", "spacing control");
  expect((await page.locator("#material").inputValue()) === "iron@300", "material control");
  const log = await (await fetch(`${base}/__mock/log`)).json();
  const creates = log.filter((e) => e.create).map((e) => e.create);
  const last = creates.at(-1);
  expect(
    JSON.stringify(last) ===
      JSON.stringify({
        scene: "minimal",
        set: ["plate.material=iron", "rollers.spacing=60mm", "world.duration=5s"],
      }),
    `created ${JSON.stringify(last)}`,
  );
  const first = creates.find((c) => c.scene === "paper-rig");
  expect(first && first.set.length === 0, "the default scene was sent with set entries");
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("a new scene or material starts a new session with only what changed", async () => {
  const { page, context, complaints } = await openPage("/");
  await page.getByTestId("spacing").filter({ hasText: "89 mm" }).waitFor();
  await page.selectOption("#material", "lego@77");
  await page.getByTestId("theory").filter({ hasText: "μₖ = 0.200" }).waitFor();
  let log = await (await fetch(`${base}/__mock/log`)).json();
  let last = log.filter((e) => e.create).at(-1).create;
  expect(
    JSON.stringify(last) ===
      JSON.stringify({ scene: "paper-rig", set: ["friction.temperature=77K"] }),
    `created ${JSON.stringify(last)}`,
  );
  await page.selectOption("#scene", "stribeck-drop");
  await page.getByTestId("speed").filter({ hasText: "200 rpm" }).waitFor();
  expect(await page.locator("#hall-note").isVisible(), "no note for a rig without sensor");
  expect(await page.locator("#speed-rpm").isVisible(), "no speed control for a rig without drive");
  expect(!(await page.locator("#duty-pct").isVisible()), "duty control for a rig without drive");
  log = await (await fetch(`${base}/__mock/log`)).json();
  last = log.filter((e) => e.create).at(-1).create;
  expect(
    last.scene === "stribeck-drop" && last.set.length === 0,
    `created ${JSON.stringify(last)}`,
  );
  expect(
    log.some((e) => e.end),
    "the old session was not ended",
  );
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("slow motion, step, reset and the stopwatch with Space", async () => {
  // A run long enough that a slow machine does not see it end while the stopwatch runs.
  const { page, context, complaints } = await openPage("/?scene=minimal&set=world.duration%3D60s");
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  await page.selectOption("#slow-motion", "0.25");
  // The lab's events say the new speed: the run goes at a quarter from now on.
  await page.waitForFunction(() => window.__lab.states.at(-1)?.speed === 0.25);
  await page.locator("body").click({ position: { x: 5, y: 760 } });
  await page.keyboard.press("Space");
  // The time the stopwatch runs: whatever it is on this machine, the readings are judged below
  // against the page's own clocks at the two presses.
  await page.waitForTimeout(1200);
  await page.keyboard.press("Space");
  const wall = await page.getByTestId("stopwatch-wall").textContent();
  const sim = await page.getByTestId("stopwatch-sim").textContent();
  const wallS = Number(/^([\d.]+) s/.exec(wall)?.[1]);
  const simS = Number(/^([\d.]+) s/.exec(sim)?.[1]);
  // An event after the second press, so that the gap around it is known.
  await page.waitForFunction(() => window.__lab.states.at(-1).at > window.__lab.spaces.at(-1).at);
  const { states, spaces } = await page.evaluate(() => window.__lab);
  const [start, stop] = spaces.slice(-2);
  // The stopwatch shows the wall time between the presses and the simulated time between the
  // states the page had at them (to the display's 0.01 s and 0.001 s).
  const wallBetween = (stop.at - start.at) / 1000;
  expect(
    Math.abs(wallS - wallBetween) <= 0.006,
    `wall ${wall}, the presses ${wallBetween} s apart`,
  );
  expect(
    Math.abs(simS - (stop.t - start.t)) <= 0.0006,
    `simulated ${sim}, the states at the presses ${start.t} and ${stop.t}`,
  );
  // The run went at a quarter of the wall time. The simulated time at a press is the last
  // event's, which lags the press by up to one gap between events plus that event's delivery
  // (bounded by another gap): at most four of the largest gap over both presses, at a quarter,
  // and the display's rounding. On a quiet machine a gap is 1/30 s: 0.043 s.
  const around = states.filter((s) => s.at >= start.at - 1000 && s.at <= stop.at + 1000);
  const gapS = Math.max(...around.slice(1).map((s, i) => (s.at - around[i].at) / 1000));
  const tolerance = 0.25 * 4 * gapS + 0.01;
  expect(
    Math.abs(simS - wallS / 4) <= tolerance,
    `simulated ${sim} at 1/4 speed over ${wall}: more than ${tolerance.toFixed(3)} s off (events up to ${gapS.toFixed(3)} s apart)`,
  );
  await page.getByTestId("play").click(); // pause
  await page.getByTestId("status").filter({ hasText: "paused" }).waitFor();
  const before = Number(/t = ([\d.]+)/.exec(await page.getByTestId("time").textContent())[1]);
  await page.click("#step");
  await page.waitForFunction(
    (t0) =>
      Number(/t = ([\d.]+)/.exec(document.querySelector('[data-testid="time"]').textContent)[1]) >
      t0,
    before,
  );
  await page.click("#reset");
  await page.getByTestId("time").filter({ hasText: "t = 0.000 s" }).waitFor();
  expect((await page.getByTestId("period").textContent()) === "T = — s", "reset keeps T");
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("Space after clicking Play times the run and never pauses it", async () => {
  const { page, context, complaints } = await openPage("/?scene=minimal&set=world.duration%3D60s");
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  await page.getByTestId("play").click(); // pause
  await page.getByTestId("status").filter({ hasText: "paused" }).waitFor();
  await page.getByTestId("play").click(); // play: the button keeps the focus
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  await page.keyboard.press("Space");
  const toggle = page.locator("#stopwatch-toggle");
  await toggle.filter({ hasText: "Stop" }).waitFor();
  await page.waitForTimeout(500);
  await page.keyboard.press("Space");
  await toggle.filter({ hasText: "Start" }).waitFor();
  expect(
    (await page.getByTestId("status").textContent()) === "playing",
    `the run was paused: ${await page.getByTestId("status").textContent()}`,
  );
  expect((await page.getByTestId("play").textContent()) === "Pause", "Play was pressed");
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("the run's length is a control: a longer run is a new session", async () => {
  const { page, context, complaints } = await openPage("/?scene=minimal");
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  const duration = page.getByTestId("duration");
  expect(
    (await duration.inputValue()) === "8",
    `the scene's duration: ${await duration.inputValue()}`,
  );
  await duration.fill("60");
  await duration.press("Enter");
  await waitUntil(
    async () =>
      (await mockLog())
        .filter((e) => e.create)
        .at(-1)
        ?.create.set.includes("world.duration=60s"),
    "a session of 60 s",
  );
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  expect((await duration.inputValue()) === "60", "the control does not show the run's length");
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("the stopwatch stops when the run ends", async () => {
  // A recorded 5 s run (tests/mock_recording.json).
  const set = ["world.duration=5s", "plate.material=iron", "rollers.spacing=60mm"];
  const { page, context, complaints } = await openPage(
    `/?scene=minimal&${set.map((s) => `set=${encodeURIComponent(s)}`).join("&")}`,
  );
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  await page.locator("#stopwatch-toggle").click();
  await page.getByTestId("status").filter({ hasText: "done" }).waitFor();
  await page.locator("#stopwatch-toggle").filter({ hasText: "Start" }).waitFor();
  const wall = await page.locator("#stopwatch-wall").textContent();
  await page.waitForTimeout(300);
  expect(
    (await page.locator("#stopwatch-wall").textContent()) === wall,
    "the stopwatch counted on after the run's end",
  );
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("the layout fits 1920x1080 and every control has a label", async () => {
  const { page, context, complaints } = await openPage("/", { width: 1920, height: 1080 });
  await page.getByTestId("spacing").filter({ hasText: "89 mm" }).waitFor();
  const unlabelled = await page.evaluate(() =>
    Array.from(document.querySelectorAll("input, select, button"))
      .filter((el) => {
        if (el.closest("[hidden]")) return false;
        const labelled =
          el.getAttribute("aria-label") ||
          (el.labels && el.labels.length > 0) ||
          (el.tagName === "BUTTON" && el.textContent.trim());
        return !labelled;
      })
      .map((el) => el.outerHTML.slice(0, 80)),
  );
  expect(unlabelled.length === 0, `unlabelled: ${unlabelled.join(", ")}`);
  const overflow = await page.evaluate(() => document.documentElement.scrollWidth > innerWidth);
  expect(!overflow, "the page scrolls sideways");
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

/** The requests the mock was sent. */
async function mockLog() {
  return (await fetch(`${base}/__mock/log`)).json();
}

await check(
  "the live rig: its port, its periods and estimate, its log, beside the simulation",
  async () => {
    const { page, context, complaints } = await openPage("/?scene=minimal");
    await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
    const port = page.getByTestId("rig-port");
    await port.locator("option", { hasText: FAKE_RIG_PORT }).waitFor({ state: "attached" });
    expect((await port.inputValue()) === FAKE_RIG_PORT, "the fake port is not chosen");
    expect(await port.isVisible(), "the panel did not open for a port");
    expect(await page.getByTestId("rig-log").isHidden(), "a log link before any line");
    expect((await page.getByTestId("rig-estimate").textContent()) === "—", "estimate before any");
    await page.getByTestId("rig-connect").click();
    await page
      .getByTestId("rig-state")
      .filter({ hasText: `receiving from ${FAKE_RIG_PORT}, ` })
      .waitFor();
    // Connecting runs the simulation of the same set-up from t = 0 at 1x beside the rig.
    await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
    const log = await mockLog();
    const opened = log.findLastIndex((e) => e.rig?.port === FAKE_RIG_PORT);
    const after = log.slice(opened + 1).map((e) => JSON.stringify(e.body ?? e));
    const asked = ['{"speed":1}', '{"action":"reset"}', '{"action":"play"}'];
    expect(
      asked.every(
        (a, i) =>
          after.indexOf(a) >= 0 && (i === 0 || after.indexOf(a) > after.indexOf(asked[i - 1])),
      ),
      `after connecting: ${after.join(" ")}`,
    );
    expect((await page.locator("#slow-motion").inputValue()) === "1", "not at 1x");
    // Three periods judged: the board sends a simulated run of the paper's rig, whose periods
    // the lab's estimator judges from about 5 s on.
    await page.waitForFunction(
      () => document.querySelectorAll('[data-testid="rig-period"]').length >= 3,
    );
    const { rows, estimate } = await page.evaluate(() => ({
      rows: Array.from(document.querySelectorAll('[data-testid="rig-periods"] tr'), (tr) =>
        Array.from(tr.cells, (td) => td.textContent),
      ),
      estimate: document.querySelector('[data-testid="rig-estimate"]').textContent,
    }));
    // Newest first; each period and its verdict the lab's estimator's, to 6 decimals (asked after
    // the page was read: the mock's periods so far are at least the page's).
    const judged = (await (await fetch(`${base}/__mock/rig`)).json()).periods;
    const numbers = rows.map((r) => Number(r[0]));
    expect(
      numbers.every((n, i) => i === 0 || n === numbers[i - 1] - 1),
      `rows ${numbers}`,
    );
    for (const [n, , period, status] of rows) {
      const [, , seconds, accepted] = judged[Number(n) - 1];
      const expected = seconds.toFixed(6);
      expect(period === expected, `period #${n} reads "${period}", the estimator's is ${expected}`);
      expect(status === (accepted ? "accepted" : "rejected"), `period #${n} is ${status}`);
    }
    const accepted = rows.filter((r) => r[3] === "accepted").map((r) => Number(r[2]));
    const mean = accepted.reduce((a, b) => a + b, 0) / accepted.length;
    const shown = /T = (\d\.\d+) ± \d\.\d+ s/.exec(estimate);
    expect(
      shown && Math.abs(Number(shown[1]) - mean) < 1e-4,
      `estimate "${estimate}", mean ${mean}`,
    );
    expect(/μₖ = \d\.\d+ ± \d\.\d+/.test(estimate), `estimate "${estimate}" has no μₖ`);
    expect(estimate.includes(`N = ${accepted.length} periods`), `estimate "${estimate}": N`);
    expect(estimate.includes("l = 89 mm"), `estimate "${estimate}": the spacing`);
    expect((await page.locator('[data-testid="rig-plot"] canvas').count()) > 0, "no rig plot");
    // The raw log downloads under its name, as the fake board sent it.
    const logLink = page.getByTestId("rig-log");
    await logLink.waitFor();
    const [download] = await Promise.all([page.waitForEvent("download"), logLink.click()]);
    expect(/^rig-fake-.*\.log$/.test(download.suggestedFilename()), download.suggestedFilename());
    const lines = readFileSync(await download.path(), "utf8")
      .trim()
      .split("\n");
    expect(lines[0].startsWith("# frictionlab rig firmware"), `log starts "${lines[0]}"`);
    expect(lines[1] === "t_us,adc" && lines.length > 1000, `log: ${lines.length} lines`);
    await page.getByTestId("rig-close").click();
    await page
      .getByTestId("rig-state")
      .filter({ hasText: /^closed/ })
      .waitFor();
    expect(await page.getByTestId("rig-close").isDisabled(), "close stays enabled when closed");
    // Connected again, then unplugged: the server's message says the log is kept; the link stays.
    await page.getByTestId("rig-connect").click();
    await page.getByTestId("rig-state").filter({ hasText: "receiving from" }).waitFor();
    await fetch(`${base}/__mock/rig-unplug`);
    await page.getByTestId("rig-state").filter({ hasText: "lines received are kept" }).waitFor();
    expect(await logLink.isVisible(), "the log link went with the board");
    expect(await page.getByTestId("rig-close").isDisabled(), "close enabled for a port gone");
    expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
    await context.close();
  },
);

await check("a shared lab's port is not the page's to choose", async () => {
  await fetch(`${base}/__mock/rig-shared`);
  try {
    const { page, context, complaints } = await openPage("/");
    await page.locator("#rig-choose-note").waitFor();
    expect(await page.getByTestId("rig-port").isDisabled(), "the port list is enabled");
    expect(await page.getByTestId("rig-connect").isDisabled(), "connect is enabled");
    expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
    await context.close();
  } finally {
    await fetch(`${base}/__mock/rig-shared?off`);
  }
});

await check("a name typed before Play reaches the class's table at once", async () => {
  const { page, context, complaints } = await openPage("/");
  await page.getByTestId("status").filter({ hasText: "paused" }).waitFor();
  await page.getByTestId("student-name").fill("Curie, M. (2B)");
  const named = async () => {
    const table = await (await fetch(`${base}/api/class`)).json();
    return table.sessions.some((s) => s.name === "Curie, M. (2B)");
  };
  await waitUntil(named, "the name in the class's table");
  // No new session: the run the student sees is the one named.
  const created = (await mockLog()).filter((e) => e.create);
  expect(!created.some((e) => e.create.name === "Curie, M. (2B)"), "a session was started");
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("the student's name reaches the class's table, class.html and class.csv", async () => {
  const name = "Ada O'Neil-2";
  const { page, context, complaints } = await openPage("/?scene=minimal");
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  await page.getByTestId("student-name").fill(name);
  // The name goes with the next session: a new spacing starts one.
  await page.fill("#spacing-mm", "70");
  await page.press("#spacing-mm", "Enter");
  await page.getByTestId("spacing").filter({ hasText: "70 mm" }).waitFor();
  const created = (await mockLog()).filter((e) => e.create).at(-1).create;
  expect(created.name === name, `created ${JSON.stringify(created)}`);
  const tableResponse = await fetch(`${base}/api/class`);
  const tableText = await tableResponse.text();
  const table = JSON.parse(tableText);
  const row = table.sessions.find((s) => s.name === name);
  expect(row && row.spacing === 0.07 && row.scene === "minimal", tableText);
  // The class's table lists every session's id, never its key: an id alone controls nothing.
  const pageKey = await page.evaluate(() =>
    new URL(window.__lab.sources.at(-1).url, location.href).searchParams.get("key"),
  );
  expect(/^[0-9a-f]{32}$/.test(pageKey ?? ""), `the page's stream carries the key ${pageKey}`);
  expect(!tableText.includes(pageKey), `the class's table shows a key: ${tableText}`);
  for (const [method, path, body] of [
    ["POST", "/control", { action: "reset" }],
    ["DELETE", "", null],
  ]) {
    const refused = await fetch(`${base}/api/sessions/${row.session}${path}`, {
      method,
      headers: { "Content-Type": "application/json" },
      body: body === null ? undefined : JSON.stringify(body),
    });
    expect(refused.status === 403, `${method} ${path} without the key answers ${refused.status}`);
  }
  // Kept in this browser: a reload finds it again, and sends it with its session (89 mm).
  await page.reload();
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  expect((await page.getByTestId("student-name").inputValue()) === name, "the name was lost");
  const again = (await mockLog()).filter((e) => e.create).at(-1).create;
  expect(again.name === name && again.set.length === 0, `created ${JSON.stringify(again)}`);
  // A name the lab would refuse is not sent, and the page says so beside it.
  await page.getByTestId("student-name").fill("=SUM(A1)");
  await page.locator("#student-name-problem").filter({ hasText: "Not sent" }).waitFor();
  await page.getByTestId("student-name").fill(name);

  const teacher = await context.newPage();
  teacher.on("pageerror", (error) => complaints.push(`pageerror: ${error.message}`));
  await teacher.goto(`${base}/class.html`);
  const mine = teacher.getByTestId("class-table").locator("tbody tr", { hasText: name });
  await mine.first().waitFor();
  // The row fills as the session runs (the mock's runs last 4 s; the table asks every 2 s).
  await teacher.waitForFunction(
    (who) =>
      Array.from(document.querySelectorAll('[data-testid="class-table"] tbody tr')).some(
        (tr) => tr.cells[0].textContent === who && / ± /.test(tr.cells[7].textContent),
      ),
    name,
  );
  const cells = await mine.first().locator("td").allTextContents();
  expect(cells.length === 11, `${cells.length} cells`);
  const [, scene, material, kelvin, spacing, , , period, muK, paperMuK, hide] = cells;
  expect(hide === "Hide", `the last cell: ${hide}`);
  expect(scene === "minimal" && material === "LEGO blocks" && kelvin === "300", cells.join("|"));
  expect(spacing === "89" && paperMuK === "0.29", cells.join("|"));
  expect(/^\d\.\d+ ± \d\.\d+$/.test(period) && / ± /.test(muK), cells.join("|"));
  await teacher.getByTestId("class-rig").filter({ hasText: FAKE_RIG_PORT }).waitFor();
  expect(
    (await teacher.getByTestId("lab-link").getAttribute("href")) === "/",
    "no link back to the lab",
  );
  expect(
    (await page.getByTestId("class-link").getAttribute("href")) === "/class.html",
    "no link to the class's table",
  );
  // Sorted by a column's heading, both ways; a row hidden stays hidden on a reload, and comes back.
  const names = () =>
    teacher.evaluate(() =>
      Array.from(document.querySelectorAll('[data-testid="class-table"] tbody tr')).map(
        (tr) => tr.cells[0].textContent,
      ),
    );
  // Named rows sorted; the unnamed (—) last either way.
  const byName = (list, down = false) => {
    const named = list.filter((n) => n !== "—");
    named.sort((a, b) => a.localeCompare(b, undefined, { numeric: true }));
    if (down) named.reverse();
    return [...named, ...list.filter((n) => n === "—")];
  };
  // A second student, in a browser of their own.
  const second = await openPage("/");
  await second.page.getByTestId("student-name").fill("Bea (2B)");
  await teacher
    .getByTestId("class-table")
    .locator("tbody tr", { hasText: "Bea (2B)" })
    .first()
    .waitFor();
  await teacher.locator(`th button[data-sort="name"]`).click();
  const up = await names();
  expect(up.length >= 2 && JSON.stringify(up) === JSON.stringify(byName(up)), up.join("|"));
  await teacher.locator(`th button[data-sort="name"]`).click();
  const down = await names();
  expect(JSON.stringify(down) === JSON.stringify(byName(down, true)), down.join("|"));
  const before = (await names()).length;
  await mine
    .first()
    .getByRole("button", { name: /^Hide / })
    .click();
  await teacher
    .getByTestId("class-show-hidden")
    .filter({ hasText: "Show the 1 hidden row" })
    .waitFor();
  expect((await names()).length === before - 1 && !(await names()).includes(name), "not hidden");
  await teacher.reload();
  await teacher.getByTestId("class-show-hidden").filter({ hasText: "1 hidden" }).waitFor();
  expect(!(await names()).includes(name), "a hidden row came back on a reload");
  await teacher.getByTestId("class-show-hidden").click();
  await mine.first().waitFor();
  await second.context.close();

  const [download] = await Promise.all([
    teacher.waitForEvent("download"),
    teacher.getByTestId("class-csv").click(),
  ]);
  expect(download.suggestedFilename() === "class.csv", download.suggestedFilename());
  const csv = readFileSync(await download.path(), "utf8")
    .trim()
    .split("\n");
  const api = readFileSync(join(web, "../docs/web-api.md"), "utf8");
  const columns = /a download named `class\.csv`\):\s*`([^`]+)`/.exec(api)[1].split(/,\s*/);
  expect(csv[0] === columns.join(","), `class.csv's header "${csv[0]}", the API's ${columns}`);
  expect(
    csv.some((line) => line.includes(`,${name},minimal,`)),
    `no row of ${name}: ${csv.join(" / ")}`,
  );
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("a 429 shows the lab's message, and the page and its stream go on", async () => {
  const { page, context, complaints } = await openPage("/?scene=minimal");
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  await fetch(`${base}/__mock/refuse?path=/api/sessions&count=1`);
  await page.fill("#spacing-mm", "75");
  await page.press("#spacing-mm", "Enter");
  await page
    .locator("#page-problem")
    .filter({ hasText: /^too many requests/ })
    .waitFor();
  await page.fill("#spacing-mm", "76");
  await page.press("#spacing-mm", "Enter");
  await page.getByTestId("spacing").filter({ hasText: "76 mm" }).waitFor();
  expect((await page.locator("#page-problem").textContent()) === "", "the message stays");
  // A stream refused once (EventSource does not retry a 429 by itself) is opened again.
  await fetch(`${base}/__mock/refuse?path=/stream&count=1`);
  await page.fill("#spacing-mm", "77");
  await page.press("#spacing-mm", "Enter");
  await page.getByTestId("spacing").filter({ hasText: "77 mm" }).waitFor();
  await page.waitForFunction(() =>
    /t = [1-9]/.test(document.querySelector('[data-testid="time"]').textContent),
  );
  const others = complaints.filter((c) => !c.includes("429 (Too Many Requests)"));
  expect(others.length === 0, `console: ${others.join("\n")}`);
  await context.close();
});

await check("the server's `closed` is shown and the page stops streaming", async () => {
  const { page, context, complaints } = await openPage("/?scene=minimal");
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  // A state event has come: the page's stream is open (on a loaded machine it may open after the
  // play button shows "playing").
  await page.waitForFunction(() => window.__lab.states.some((s) => s.t > 0));
  const session = await page.evaluate(
    () => /\/api\/sessions\/([^/]+)\/stream/.exec(window.__lab.sources.at(-1).url)[1],
  );
  const openStreams = async () =>
    (await (await fetch(`${base}/__mock/streams?session=${session}`)).json()).open;
  await fetch(`${base}/__mock/close-streams`);
  await page.locator("#page-problem").filter({ hasText: "the lab stopped" }).waitFor();
  await page.getByTestId("status").filter({ hasText: "no session" }).waitFor();
  expect(await page.getByTestId("play").isDisabled(), "play stays enabled");
  // The page closed its streams (a closed EventSource never reconnects) and the mock has none
  // of its session open.
  await page.waitForFunction(() =>
    window.__lab.sources.every((source) => source.readyState === EventSource.CLOSED),
  );
  await waitUntil(async () => (await openStreams()) === 0, "the page's stream to end");
  const made = await page.evaluate(() => window.__lab.sources.length);
  // Nor does it open another: watched for longer than EventSource's 3 s and the page's own 2 s
  // retry (a busy machine can only make an unwanted reconnection later, never a false alarm).
  await page.waitForTimeout(3500);
  const again = await page.evaluate(() => window.__lab.sources.length);
  expect(again === made, `${again - made} stream(s) opened again`);
  expect((await openStreams()) === 0, "a stream of the page's session is open again");
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await browser.close();
await stop();
finish();
