// The page for everyone, against tests/mock_server.mjs in headless Chromium (software WebGL):
// axe-core finds no WCAG 2.1 A or AA violation on the lab's page and the class's table, before
// and during a run; a phone (390x844) and a tablet (820x1180) held upright, and 1366x768 and
// 1920x1080, show the 3D view, the period and μk and the position plot in the first screen,
// without scrolling sideways; a finger's targets are 44 CSS px at least; the 3D view takes the
// focus by Tab, shows it, zooms, orbits and goes back with its keys and "Reset view", and draws
// nothing while the run is paused; the live description says where the plate is, which roller
// carries more of its weight and the period, at most every 5 s; each plot's table holds the
// samples it plots once the run pauses; reduced motion turns the transitions off; the forces'
// colours are told apart under protanopia and deuteranopia. Screenshots go to $SHOTS (default
// /tmp/shots).
//
// Nothing here depends on the machine's pace: a wait is for a condition, with a generous
// deadline (WAIT_MS), never a sleep that hopes it is long enough; where a check watches for
// something that must not happen (a frame drawn while paused), a slower machine can only make it
// pass by watching less, never fail it.
//
//   FRICTIONLAB_MOCK_RECORDING=FILE node tests/page_access.test.mjs
import { mkdirSync } from "node:fs";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { startBuiltPage } from "./mock_server.mjs";
import {
  check,
  expect,
  expectNoViolations,
  finish,
  launchChromium,
  openWatchedPage,
  skipWithoutChromium,
  WAIT_MS,
} from "./browser_checks.mjs";
import { importTs } from "./import_ts.mjs";

const web = resolve(dirname(fileURLToPath(import.meta.url)), "..");
const shots = process.env.SHOTS ?? "/tmp/shots";
skipWithoutChromium();
mkdirSync(shots, { recursive: true });

const { base, stop } = await startBuiltPage();
const browser = await launchChromium();

const PHONE = {
  viewport: { width: 390, height: 844 },
  isMobile: true,
  hasTouch: true,
  deviceScaleFactor: 2,
};
const TABLET = { viewport: { width: 820, height: 1180 }, isMobile: true, hasTouch: true };
const LAPTOP = { viewport: { width: 1366, height: 768 } };
const DESKTOP = { viewport: { width: 1920, height: 1080 } };

/** Runs in each page before its own script: records each `state` event the page receives (its
 * time on the page's clock, t, x, vx, the rollers' normal forces, whether the run plays), every
 * Hall sample, and each text the live description takes, with the state and the period readout
 * of that moment. */
function recordPage() {
  const lab = { states: [], hall: [], said: [] };
  window.__access = lab;
  const PageEventSource = window.EventSource;
  window.EventSource = class extends PageEventSource {
    constructor(url, init) {
      super(url, init);
      this.addEventListener("state", (event) => {
        const s = JSON.parse(event.data);
        const normals = s.contacts.map((c) => c.normal);
        const { t, x, vx, playing } = s;
        lab.states.push({ at: performance.now(), t, x, vx, normals, playing });
        for (const sample of s.hall) lab.hall.push(sample);
      });
    }
  };
  document.addEventListener("DOMContentLoaded", () => {
    const region = document.getElementById("rig-now");
    const period = document.querySelector('[data-testid="period"]');
    if (!region) return; // the class's table
    new MutationObserver(() => {
      lab.said.push({
        at: performance.now(),
        text: region.textContent,
        state: lab.states.at(-1) ?? null,
        period: period.textContent,
      });
    }).observe(region, { childList: true, characterData: true, subtree: true });
  });
}

/** A page in a context of its own, recording console errors and what it announced. */
function openPage(path, options = LAPTOP) {
  return openWatchedPage(browser, `${base}${path}`, options, recordPage);
}

/** The lab's page with its set-up shown and (`parts`) its LEGO parts loaded. */
async function labReady(page, parts = true) {
  await page.getByTestId("spacing").filter({ hasText: "89 mm" }).waitFor();
  if (!parts) return;
  await page.waitForFunction(() =>
    performance
      .getEntriesByType("resource")
      .some((entry) => entry.name.endsWith("/parts/technic-brick-1x16.glb")),
  );
}

/** The simulated time the page shows. */
async function shownTime(page) {
  const text = await page.getByTestId("time").textContent();
  return Number(/t = ([\d.]+) s/.exec(text)[1]);
}

/** Waits until the page shows a simulated time past `t` (s). */
async function runPast(page, t) {
  await page.waitForFunction(
    (after) =>
      Number(/t = ([\d.]+)/.exec(document.querySelector('[data-testid="time"]').textContent)[1]) >
      after,
    t,
  );
}

/** The first screen at scroll 0: the boxes of the 3D view, the period and μk, the position plot. */
async function firstScreen(page) {
  await page.evaluate(() => window.scrollTo(0, 0));
  return page.evaluate(() => {
    const box = (selector) => {
      const r = document.querySelector(selector).getBoundingClientRect();
      return { top: r.top, bottom: r.bottom, left: r.left, right: r.right };
    };
    return {
      scrollY: window.scrollY,
      scrollWidth: document.documentElement.scrollWidth,
      // The side panel scrolls down only: a control wider than it (a long scene's name, a unit
      // pushed out) is cut off there, not scrolled to.
      panelSideways: (() => {
        const panel = document.querySelector("#panel");
        return panel.scrollWidth - panel.clientWidth;
      })(),
      width: innerWidth,
      height: innerHeight,
      canvas: box("#view canvas"),
      period: box('[data-testid="period"]'),
      muK: box('[data-testid="mu-k"]'),
      plot: box("#plot-x"),
    };
  });
}

/** The view, the numbers and the position plot together in the first screen, nothing sideways. */
function expectFirstScreen(screen, name) {
  const { width, height, canvas, period, muK, plot } = screen;
  const boxes = JSON.stringify(screen);
  expect(screen.scrollY === 0, `${name}: not at the top`);
  expect(screen.scrollWidth <= width, `${name}: scrolls sideways: ${boxes}`);
  expect(screen.panelSideways <= 0, `${name}: the panel is ${screen.panelSideways} px too wide`);
  const seen = (box) => Math.min(box.bottom, height) - Math.max(box.top, 0);
  expect(canvas.top >= 0 && seen(canvas) >= 100, `${name}: the 3D view is not in sight: ${boxes}`);
  for (const [what, box] of [
    ["the period", period],
    ["μk", muK],
  ]) {
    const whole = box.top >= 0 && box.bottom <= height && box.left >= 0 && box.right <= width;
    expect(whole, `${name}: ${what} is not wholly in the first screen: ${boxes}`);
  }
  expect(seen(plot) >= 120, `${name}: less than 120 px of the position plot in sight: ${boxes}`);
}

/** Visible buttons, selects, inputs and summaries smaller than 44x44 CSS px (a checkbox: its
 * label, which a finger presses). */
async function smallTargets(page) {
  return page.evaluate(() =>
    Array.from(document.querySelectorAll("button, select, input, summary"))
      .filter((el) => el.checkVisibility({ checkOpacity: true, checkVisibilityCSS: true }))
      .map((el) => {
        const target = ["checkbox", "radio"].includes(el.type) ? (el.closest("label") ?? el) : el;
        const r = target.getBoundingClientRect();
        return { what: target.outerHTML.slice(0, 70), width: r.width, height: r.height };
      })
      .filter((t) => t.width < 44 || t.height < 44)
      .map((t) => `${t.what} (${t.width.toFixed(1)}x${t.height.toFixed(1)})`),
  );
}

await check("axe: the lab's page, before and during a run, its tables open", async () => {
  const { page, context, complaints } = await openPage("/");
  await labReady(page);
  await expectNoViolations(page, "before the run");
  await page.getByTestId("play").click();
  await runPast(page, 1);
  await expectNoViolations(page, "during the run");
  await page.getByTestId("play").click(); // pause
  await page.getByTestId("status").filter({ hasText: "paused" }).waitFor();
  await page.locator("#table-x > summary").click();
  await page.locator("#table-hall > summary").click();
  await page.locator('[data-testid="table-x"] tr').first().waitFor();
  await expectNoViolations(page, "paused, the plots' tables open");
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("axe: a lab with no rig's port (the live rig's panel quiet), and a phone", async () => {
  await fetch(`${base}/__mock/rig-shared`);
  try {
    const { page, context, complaints } = await openPage("/");
    await labReady(page);
    await page.locator('[data-testid="rig-panel"].quiet').waitFor();
    await expectNoViolations(page, "with no port");
    await context.close();
    const phone = await openPage("/", PHONE);
    await labReady(phone.page);
    await expectNoViolations(phone.page, "on a phone");
    await phone.page.getByTestId("play").click();
    await runPast(phone.page, 1);
    await expectNoViolations(phone.page, "on a phone, during the run");
    const all = [...complaints, ...phone.complaints];
    expect(all.length === 0, `console: ${all.join("\n")}`);
    await phone.context.close();
  } finally {
    await fetch(`${base}/__mock/rig-shared?off`);
  }
});

await check("axe: the class's table, a session paused and playing", async () => {
  const lab = await openPage("/?scene=minimal");
  await labReady(lab.page, false);
  await lab.page.getByTestId("student-name").fill("Noether, E.");
  const { page, context, complaints } = await openPage("/class.html");
  const row = page.getByTestId("class-table").locator("tbody tr", { hasText: "Noether, E." });
  await row.first().waitFor();
  await expectNoViolations(page, "on the class's table, the session paused");
  await lab.page.getByTestId("play").click();
  await page.waitForFunction(() =>
    Array.from(document.querySelectorAll('[data-testid="class-table"] tbody tr')).some(
      (tr) => tr.cells[0].textContent === "Noether, E." && tr.cells[5].textContent === "playing",
    ),
  );
  await expectNoViolations(page, "on the class's table, the session playing");
  await page.setViewportSize(PHONE.viewport);
  const sideways = await page.evaluate(() => document.documentElement.scrollWidth > innerWidth);
  expect(!sideways, "the class's page scrolls sideways at 390 px");
  const all = [...complaints, ...lab.complaints];
  expect(all.length === 0, `console: ${all.join("\n")}`);
  await context.close();
  await lab.context.close();
});

for (const [name, options] of [
  ["phone 390x844", PHONE],
  ["tablet 820x1180", TABLET],
]) {
  await check(
    `${name}: the view, the numbers and the position plot in the first screen`,
    async () => {
      const { page, context, complaints } = await openPage("/", options);
      await labReady(page);
      expectFirstScreen(await firstScreen(page), name);
      const small = await smallTargets(page);
      expect(small.length === 0, `targets under 44x44 px: ${small.join("; ")}`);
      // A finger's hint, not the mouse's.
      expect(await page.getByText("pinch to zoom").isVisible(), "no touch hint");
      expect(!(await page.getByText("scroll to zoom").isVisible()), "the mouse's hint on a phone");
      await page.getByTestId("play").click();
      await runPast(page, 2);
      expectFirstScreen(await firstScreen(page), `${name}, playing`);
      await page.screenshot({ path: join(shots, `${name.split(" ")[0]}.png`) });
      await page.screenshot({
        path: join(shots, `${name.split(" ")[0]}-full.png`),
        fullPage: true,
      });
      expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
      await context.close();
    },
  );
}

for (const [name, options] of [
  ["1366x768", LAPTOP],
  ["1920x1080", DESKTOP],
]) {
  await check(
    `${name}: the view, the numbers and the position plot in the first screen`,
    async () => {
      const { page, context, complaints } = await openPage("/", options);
      await labReady(page);
      expect(await page.getByText("scroll to zoom").isVisible(), "no mouse hint");
      expect(!(await page.getByText("pinch to zoom").isVisible()), "the touch hint with a mouse");
      await page.getByTestId("play").click();
      await runPast(page, 2);
      expectFirstScreen(await firstScreen(page), name);
      await page.screenshot({ path: join(shots, `${name}.png`) });
      expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
      await context.close();
    },
  );
}

/** The 3D view's canvas: its camera (data- attributes the view sets on each frame). */
async function camera(page) {
  return page.locator("#view canvas").evaluate((canvas) => ({
    distance: Number(canvas.dataset.cameraDistanceMm),
    around: Number(canvas.dataset.cameraAroundDeg),
    frames: Number(canvas.dataset.frames),
  }));
}

await check("the 3D view: Tab focuses it, its outline shows; keys zoom and orbit", async () => {
  const { page, context, complaints } = await openPage("/");
  await labReady(page);
  const canvas = page.locator("#view canvas");
  // Tab from the page's start reaches the view after the skip link.
  await page.evaluate(() => document.activeElement?.blur());
  for (let i = 0; i < 5 && !(await canvas.evaluate((c) => c === document.activeElement)); i++) {
    await page.keyboard.press("Tab");
  }
  expect(await canvas.evaluate((c) => c === document.activeElement), "Tab does not reach it");
  const outline = await canvas.evaluate((c) => {
    const style = getComputedStyle(c);
    const width = parseFloat(style.outlineWidth);
    const offset = parseFloat(style.outlineOffset);
    // The outline's outer edge, and every ancestor that clips its content.
    const r = c.getBoundingClientRect();
    const reach = Math.max(0, width + offset);
    const clipped = [];
    for (let el = c.parentElement; el; el = el.parentElement) {
      const s = getComputedStyle(el);
      if (s.overflowX === "visible" && s.overflowY === "visible") continue;
      const a = el.getBoundingClientRect();
      if (
        r.left - reach < a.left ||
        r.top - reach < a.top ||
        r.right + reach > a.right ||
        r.bottom + reach > a.bottom
      ) {
        clipped.push(el.className || el.tagName);
      }
    }
    return {
      style: style.outlineStyle,
      width,
      offset,
      clipped,
      visible: c.matches(":focus-visible"),
    };
  });
  expect(outline.visible, "the view is focused but not :focus-visible");
  expect(outline.style !== "none" && outline.width >= 2, `outline ${JSON.stringify(outline)}`);
  expect(outline.clipped.length === 0, `the outline is clipped by ${outline.clipped.join(", ")}`);

  const home = await camera(page);
  expect(home.distance > 0 && home.frames > 0, `the view's camera: ${JSON.stringify(home)}`);
  await page.keyboard.press("+");
  await page.waitForFunction(
    (d) => Number(document.querySelector("#view canvas").dataset.cameraDistanceMm) < d,
    home.distance,
  );
  const nearer = await camera(page);
  expect(Math.abs(nearer.around - home.around) < 0.05, "+ turned the camera");
  await page.keyboard.press("PageDown");
  await page.keyboard.press("PageDown");
  await page.waitForFunction(
    (d) => Number(document.querySelector("#view canvas").dataset.cameraDistanceMm) > d,
    home.distance,
  );
  await page.keyboard.press("ArrowLeft");
  await page.waitForFunction(
    (a) => Math.abs(Number(document.querySelector("#view canvas").dataset.cameraAroundDeg) - a) > 1,
    home.around,
  );
  const turned = await camera(page);
  // An orbit keeps the distance (to the display's 0.1 mm).
  const zoomedOut = home.distance * 1.15; // in once, out twice
  expect(
    Math.abs(turned.distance - zoomedOut) < 0.2,
    `orbiting changed the distance: ${turned.distance} mm, ${zoomedOut.toFixed(1)} before`,
  );
  // The arrows orbit: the page does not scroll under them.
  expect((await page.evaluate(() => window.scrollY)) === 0, "the arrow scrolled the page");
  await page.getByTestId("reset-view").click();
  await page.waitForFunction(
    ({ distance, around }) => {
      const data = document.querySelector("#view canvas").dataset;
      return Number(data.cameraDistanceMm) === distance && Number(data.cameraAroundDeg) === around;
    },
    { distance: home.distance, around: home.around },
  );
  // Home does the same from the keyboard.
  await canvas.focus();
  await page.keyboard.press("Shift+ArrowUp");
  await page.keyboard.press("-");
  await page.waitForFunction(
    (d) => Number(document.querySelector("#view canvas").dataset.cameraDistanceMm) !== d,
    home.distance,
  );
  await page.keyboard.press("Home");
  await page.waitForFunction(
    (d) => Number(document.querySelector("#view canvas").dataset.cameraDistanceMm) === d,
    home.distance,
  );
  expect((await page.locator("#view-keys").textContent()).includes("arrows orbit"), "no keys");
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("the 3D view draws while the plate moves, and nothing while paused", async () => {
  const { page, context, complaints } = await openPage("/?scene=minimal&set=world.duration%3D60s");
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  await runPast(page, 1);
  const playing = await camera(page);
  await runPast(page, 1.5);
  expect((await camera(page)).frames > playing.frames, "no frame drawn while the plate moved");
  await page.getByTestId("play").click();
  await page.getByTestId("status").filter({ hasText: "paused" }).waitFor();
  // The paused run's states keep coming (the stream sends one each tick): wait for ten after the
  // pause took, then watch a second more of them draw nothing.
  const count = () => page.evaluate(() => window.__access.states.length);
  const since = await count();
  await page.waitForFunction((n) => window.__access.states.length >= n + 10, since);
  const paused = await camera(page);
  const statesThen = await count();
  await page.waitForTimeout(1000);
  const after = await camera(page);
  const states = (await count()) - statesThen;
  expect(states > 0, "no state came while paused: nothing was watched");
  expect(
    after.frames === paused.frames,
    `${after.frames - paused.frames} frames drawn while paused (${states} states came)`,
  );
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

/** The description's parts: where the plate is, its motion, the heavier roller, the period. */
function readDescription(text) {
  const where =
    /The plate is (?:(\d+) mm (left|right) of centre|at the centre), (moving (left|right)|at rest)\./.exec(
      text,
    );
  const roller =
    /The (left|right) roller carries more of its weight: ([\d.]+) N against ([\d.]+) N on the (left|right)\./.exec(
      text,
    );
  const period = /The period so far: (T = [^,]+ s), from (\d+) periods?\./.exec(text);
  return { where, roller, period, none: text.includes("No period measured yet.") };
}

await check(
  "the live description: where the plate is, the heavier roller, the period",
  async () => {
    const { page, context, complaints } = await openPage(
      "/?scene=minimal&set=world.duration%3D60s",
    );
    await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
    const region = page.getByTestId("rig-now");
    expect((await region.getAttribute("aria-live")) === "polite", "not a polite live region");
    // The set-up in a sentence, the 3D view's description.
    const setUp = await page.getByTestId("rig-setup").textContent();
    expect(/Two rollers 89 mm apart/.test(setUp) && / rpm/.test(setUp), `set-up: "${setUp}"`);
    const describedBy = await page.locator("#view canvas").getAttribute("aria-describedby");
    expect(describedBy.split(" ").includes("rig-setup"), `the view is described by ${describedBy}`);
    // Once the estimator's period shows, a description says it, as the readout did then.
    await page.waitForFunction(() =>
      /T = \d/.test(document.querySelector('[data-testid="period"]').textContent),
    );
    await page.waitForFunction(() =>
      window.__access.said.some((s) => s.text.includes("The period so far: T = ")),
    );
    await page.getByTestId("play").click(); // pause
    await page.getByTestId("status").filter({ hasText: "paused" }).waitFor();
    await page.waitForFunction(() =>
      window.__access.said.at(-1)?.text.startsWith("Paused at t = "),
    );
    const said = await page.evaluate(() => window.__access.said);
    const { rig } = await (
      await fetch(`${base}/api/sessions`, {
        method: "POST",
        body: JSON.stringify({ scene: "minimal", set: ["world.duration=60s"] }),
      })
    ).json();
    const spoken = said.filter((s) => s.text !== "");
    for (const { text, state, period } of spoken) {
      const d = readDescription(text);
      expect(d.where && state, `no place in "${text}"`);
      const [, mm, side, , direction] = d.where;
      const x = Math.round(Math.abs(state.x) * 1000);
      expect(
        x === 0 ? mm === undefined : Number(mm) === x && side === (state.x < 0 ? "left" : "right"),
        `"${text}" for x = ${state.x} m`,
      );
      expect(
        Math.abs(state.vx) < 0.001
          ? direction === undefined
          : direction === (state.vx < 0 ? "left" : "right"),
        `"${text}" for vx = ${state.vx} m/s`,
      );
      // Before the first step (t = 0) the lab has computed no contact force: the description
      // says the thin plate's static share, m g (l/2 -+ x) / l, for the minimal scene's plate.
      const [left, right] =
        state.normals[0] + state.normals[1] > 0
          ? state.normals
          : [
              (rig.plate.mass * rig.gravity * (rig.spacing / 2 - state.x)) / rig.spacing,
              (rig.plate.mass * rig.gravity * (rig.spacing / 2 + state.x)) / rig.spacing,
            ];
      expect(d.roller, `no roller in "${text}" (normal forces ${left}, ${right} N)`);
      expect(
        d.roller[1] === (left > right ? "left" : "right"),
        `"${text}": normals ${left}, ${right}`,
      );
      expect(
        Number(d.roller[2]) === Number(Math.max(left, right).toFixed(2)),
        `"${text}": ${Math.max(left, right)} N`,
      );
      if (period.startsWith("T = —"))
        expect(d.none, `"${text}" while the readout says "${period}"`);
      else
        expect(d.period && d.period[1] === period, `"${text}" while the readout says "${period}"`);
    }
    expect(
      spoken.some((s) => readDescription(s.text).period),
      "the period was never said",
    );
    // While playing, at most one description every 5 s (by the page's clock: the observer runs
    // in the same task as the page's writing, microseconds after it).
    const playing = spoken.filter((s) => s.text.startsWith("Playing"));
    expect(playing.length >= 2, `${playing.length} descriptions while playing`);
    for (let i = 1; i < playing.length; i++) {
      const gap = playing[i].at - playing[i - 1].at;
      expect(gap >= 4990, `two descriptions ${gap.toFixed(0)} ms apart`);
    }
    // Paused: said once, then silent while the paused run's states come.
    const pausedSaid = said.length;
    const states = await page.evaluate(() => window.__access.states.length);
    await page.waitForFunction((n) => window.__access.states.length >= n + 30, states);
    const later = await page.evaluate(() => window.__access.said.length);
    expect(later === pausedSaid, `${later - pausedSaid} descriptions while paused`);
    expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
    await context.close();
  },
);

await check("each plot's table: the samples it plots, once the run pauses", async () => {
  const { page, context, complaints } = await openPage("/?scene=minimal&set=world.duration%3D60s");
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  const rowsOf = (key) =>
    page.evaluate(
      (k) =>
        Array.from(document.querySelectorAll(`[data-testid="table-${k}"] tr`), (tr) =>
          Array.from(tr.cells, (td) => Number(td.textContent)),
        ),
      key,
    );
  await runPast(page, 1);
  // Not written while the run plays.
  const before = JSON.stringify(await rowsOf("x"));
  await runPast(page, (await shownTime(page)) + 1);
  expect(JSON.stringify(await rowsOf("x")) === before, "the table changed while playing");
  await runPast(page, 6); // past the plots' 5 s window
  await page.getByTestId("play").click(); // pause
  // The paused run's first state: the tables are written as the page takes it.
  await page.waitForFunction(() => window.__access.states.at(-1)?.playing === false);
  const { states, hall } = await page.evaluate(() => window.__access);
  for (const [key, samples, decimals] of [
    ["x", states.map((s) => [s.t, s.x * 1000]), 2],
    ["hall", hall, 0],
  ]) {
    const rows = await rowsOf(key);
    expect(rows.length > 1 && rows.length <= 200, `${key}: ${rows.length} rows`);
    expect(
      rows.every(([t], i) => i === 0 || t > rows[i - 1][0]),
      `${key}: t does not increase: ${rows.map((r) => r[0]).join(" ")}`,
    );
    // The plot's window: the last 5 s of its samples, thinned evenly (a row every 5 s / 200 at
    // least), to the table's 3 decimals.
    const last = samples.at(-1)[0];
    const [first, end] = [rows[0][0], rows.at(-1)[0]];
    expect(
      end <= last + 0.0005 && end >= last - 0.05,
      `${key}: ends at ${end}, its last sample at ${last}`,
    );
    expect(
      first >= last - 5 - 0.0005 && first <= last - 4.9,
      `${key}: starts at ${first}, its last sample at ${last}`,
    );
    // Each row a sample the page received, as received.
    const byTime = new Map(samples.map(([t, v]) => [t.toFixed(3), v.toFixed(decimals)]));
    const strays = rows.filter(([t, v]) => byTime.get(t.toFixed(3)) !== v.toFixed(decimals));
    expect(
      strays.length === 0,
      `${key}: rows not among the samples: ${JSON.stringify(strays.slice(0, 5))}`,
    );
  }
  // Each caption says what its table holds: every sample of x(t) at 30 per second, a 200th of
  // the Hall sensor's.
  const [xRows, hallRows] = [(await rowsOf("x")).length, (await rowsOf("hall")).length];
  const xCaption = await page.locator("#table-x caption").textContent();
  expect(xCaption.endsWith(`every sample plotted (${xRows}).`), `caption "${xCaption}"`);
  const hallCaption = await page.locator("#table-hall caption").textContent();
  expect(
    new RegExp(`: ${hallRows} of the \\d+ samples plotted, evenly in time\\.$`).test(hallCaption),
    `caption "${hallCaption}"`,
  );
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("reduced motion: no transitions; without it, the buttons' hover fades", async () => {
  const durations = async (options) => {
    const { page, context } = await openPage("/", options);
    await labReady(page);
    const found = await page.evaluate(() =>
      Array.from(document.querySelectorAll("button"), (b) =>
        Math.max(
          ...getComputedStyle(b)
            .transitionDuration.split(",")
            .map((d) => parseFloat(d)),
        ),
      ),
    );
    await context.close();
    return found;
  };
  const reduced = await durations({ ...LAPTOP, reducedMotion: "reduce" });
  expect(reduced.length > 0 && reduced.every((d) => d === 0), `reduced: ${reduced.join(" ")}`);
  const full = await durations({ ...LAPTOP, reducedMotion: "no-preference" });
  expect(
    full.some((d) => d > 0),
    "no transition to turn off: this check sees nothing",
  );
});

/** Machado, Oliveira and Fernandes (2009): a colour as seen with protanopia or deuteranopia,
 * severity 1, on linear RGB. */
const DICHROMACY = {
  protanopia: [
    [0.152286, 1.052583, -0.204868],
    [0.114503, 0.786281, 0.099216],
    [-0.003882, -0.048116, 1.051998],
  ],
  deuteranopia: [
    [0.367322, 0.860646, -0.227968],
    [0.280085, 0.672501, 0.047413],
    [-0.01182, 0.04294, 0.968881],
  ],
  none: [
    [1, 0, 0],
    [0, 1, 0],
    [0, 0, 1],
  ],
};
const linear = (hex) =>
  [1, 3, 5].map((i) => {
    const c = parseInt(hex.slice(i, i + 2), 16) / 255;
    return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
  });
function lab([r, g, b]) {
  const f = (t) => (t > 0.008856 ? Math.cbrt(t) : 7.787 * t + 16 / 116);
  const x = f((0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047);
  const y = f(0.2126 * r + 0.7152 * g + 0.0722 * b);
  const z = f((0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883);
  return [116 * y - 16, 500 * (x - y), 200 * (y - z)];
}
const seenAs = (hex, matrix) =>
  lab(
    matrix.map((row) =>
      Math.min(
        1,
        Math.max(
          0,
          row.reduce((s, m, i) => s + m * linear(hex)[i], 0),
        ),
      ),
    ),
  );
const luminance = (hex) => linear(hex).reduce((s, c, i) => s + c * [0.2126, 0.7152, 0.0722][i], 0);

await check(
  "the forces' colours: told apart with protanopia and deuteranopia; the legend's",
  async () => {
    const { FORCE_COLORS, PLOT_COLORS } = await importTs(join(web, "src/palette.ts"));
    const pairs = (colors) => colors.flatMap((a, i) => colors.slice(i + 1).map((b) => [a, b]));
    // CIE76 ΔE of at least 20: far apart at a glance (the former palette's orange and green: 12.5
    // with protanopia).
    for (const [kind, matrix] of Object.entries(DICHROMACY)) {
      for (const [what, colors] of [
        ["forces", Object.values(FORCE_COLORS)],
        ["Hall and pulses", [PLOT_COLORS.hall, PLOT_COLORS.pulse]],
        ["the rig's periods", [PLOT_COLORS.hall, PLOT_COLORS.accepted, PLOT_COLORS.rejected]],
      ]) {
        for (const [a, b] of pairs(colors)) {
          const [p, q] = [seenAs(a, matrix), seenAs(b, matrix)];
          const distance = Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
          expect(distance >= 20, `${what}, ${kind}: ${a} and ${b} ΔE ${distance.toFixed(1)}`);
        }
      }
    }
    // Every line and arrow at least 3:1 against white (WCAG 1.4.11).
    for (const color of [...Object.values(FORCE_COLORS), ...Object.values(PLOT_COLORS)]) {
      const contrast = 1.05 / (luminance(color) + 0.05);
      expect(contrast >= 3, `${color}: ${contrast.toFixed(2)}:1 against white`);
    }
    const { page, context } = await openPage("/");
    await labReady(page);
    const legend = await page.evaluate(() =>
      Object.fromEntries(
        ["normal", "friction", "weight"].map((key) => [
          key,
          getComputedStyle(document.querySelector(`.key.${key}`), "::before").backgroundColor,
        ]),
      ),
    );
    for (const [key, hex] of Object.entries(FORCE_COLORS)) {
      const rgb = `rgb(${[1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16)).join(", ")})`;
      expect(legend[key] === rgb, `the legend's ${key} is ${legend[key]}, the arrows' ${rgb}`);
    }
    await context.close();
  },
);

await check("a plot's rows: evenly in time, a pulse kept", async () => {
  const { decimate } = await importTs(join(web, "src/decimate.ts"));
  const times = Array.from({ length: 5000 }, (_, i) => i / 1000);
  const values = times.map((t, i) => (i === 2503 ? 900 : 500 + Math.sin(t)));
  const first = decimate(times, values, 200, "first");
  expect(first.length === 200, `${first.length} rows`);
  expect(
    first.every(([t], i) => Math.abs(t - i * 0.025) < 1e-9),
    "not every 25th sample",
  );
  const farthest = decimate(times, values, 200, "farthest");
  expect(
    farthest.length === 200 && farthest.some(([t, v]) => v === 900 && t === 2.503),
    "no pulse",
  );
  const few = decimate([0, 1, 2], [5, 6, 7], 200, "first");
  expect(JSON.stringify(few) === "[[0,5],[1,6],[2,7]]", `a short record: ${JSON.stringify(few)}`);
});

await browser.close();
await stop();
finish();
