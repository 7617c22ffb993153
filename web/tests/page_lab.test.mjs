// The page against the real `frictionlab serve`, in Debian's chromium, headless (software
// WebGL): it loads without console errors, a set-up from a link runs and its period is the one
// `frictionlab run` gives for it (the same number, to the last bit), changing the spacing and
// the material changes the period as the thick-plate theory says, an invalid value shows its
// message beside its control, a measurement file chosen on the page gives `estimate`'s period, a
// screenshot is written, a shared server's limits, and the live rig on a pseudo-terminal (its
// periods in the page are `estimate`'s on the log it downloads).
//
//   node tests/page_lab.test.mjs --exe build/release/src/cli/frictionlab
//                                --web build/release/src/cli/web [--shot FILE]
// Exit status: 0 all passed, 1 a check failed, 77 no chromium (the test is skipped).
import { execFileSync, spawn } from "node:child_process";
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join, resolve } from "node:path";
import { createInterface } from "node:readline";
import { fileURLToPath } from "node:url";
import { parseArgs } from "node:util";
import {
  check,
  expect,
  finish,
  launchChromium,
  skipWithoutChromium,
  reportAgainstSummary,
} from "./browser_checks.mjs";

const repository = resolve(dirname(fileURLToPath(import.meta.url)), "../..");
const { values: options } = parseArgs({
  options: {
    exe: { type: "string" },
    web: { type: "string" },
    report: { type: "string", default: "/tmp/report-print.png" },
    shot: { type: "string", default: "/tmp/frictionlab-page.png" },
  },
});
if (!options.exe || !options.web) {
  console.error("usage: node tests/page_lab.test.mjs --exe FRICTIONLAB --web DIR [--shot FILE]");
  process.exit(2);
}
skipWithoutChromium();

/** A server on any free port, with `more` options; its first line names the address. */
async function startServer(more = []) {
  const child = spawn(
    options.exe,
    ["serve", "--port", "0", "--web", options.web, "--scenes", `${repository}/scenes`, ...more],
    { stdio: ["ignore", "pipe", "inherit"] },
  );
  const address = await new Promise((done, fail) => {
    const lines = createInterface({ input: child.stdout });
    lines.on("line", (line) => {
      const found = /http:\/\/[\d.]+:\d+/.exec(line);
      if (found) done(found[0]);
    });
    child.on("exit", (code) => fail(new Error(`frictionlab serve exited with ${code}`)));
  });
  return { child, address };
}
const { child: server, address: base } = await startServer();
const browser = await launchChromium();

/** A page at `path` that records console errors and warnings. */
async function openPage(path, at = base) {
  const context = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const page = await context.newPage();
  const complaints = [];
  page.on("console", (m) => {
    if (m.type() === "error" || m.type() === "warning") complaints.push(m.text());
  });
  page.on("pageerror", (error) => complaints.push(`pageerror: ${error.message}`));
  await page.goto(`${at}${path}`);
  return { page, context, complaints };
}

/** The set-up a link names, run in the page to its end: the period it shows, full precision. */
async function pagePeriod(set) {
  const query = ["scene=minimal", ...set.map((s) => `set=${encodeURIComponent(s)}`)].join("&");
  const { page, context, complaints } = await openPage(`/?${query}`);
  await page.getByTestId("status").filter({ hasText: "done" }).waitFor({ timeout: 60000 });
  const period = Number(await page.getByTestId("period").getAttribute("data-value"));
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
  return period;
}

/** The same set-up as `frictionlab run` runs it. */
function runPeriod(set) {
  const args = ["run", `${repository}/scenes/minimal.yaml`, "--json"];
  for (const s of set) args.push("--set", s);
  return JSON.parse(execFileSync(options.exe, args, { encoding: "utf8" })).period_s;
}

/** The thick plate's period, 2 pi sqrt((l - 2 mu h_c) / (2 mu g)) (the paper's eq. with h_c). */
function thickPeriod(l, mu, h_c, g) {
  return 2 * Math.PI * Math.sqrt((l - 2 * mu * h_c) / (2 * mu * g));
}

// The minimal scene's plate, from the API (h_c is the plate's geometry, an input of the theory).
const rig = await (
  await fetch(`${base}/api/sessions`, {
    method: "POST",
    body: JSON.stringify({ scene: "minimal" }),
  })
).json();
const { h_c } = rig.rig.plate;
const g = rig.rig.gravity;
const duration = "world.duration=6s";

const periods = {};
await check("a link's set-up runs in the page and its period is run's", async () => {
  const set = [duration, "rollers.spacing=70mm"];
  periods.l70 = await pagePeriod(set);
  const expected = runPeriod(set);
  expect(periods.l70 === expected, `page ${periods.l70} s, run ${expected} s`);
});

await check("the spacing and the material change the period as theory says", async () => {
  periods.l89 = await pagePeriod([duration]);
  periods.iron = await pagePeriod([duration, "plate.material=iron"]);
  const lego = 0.29; // Table I at 300 K
  const iron = 0.42;
  const near = (a, b, tolerance) => Math.abs(a / b - 1) <= tolerance;
  // Each period within 0.2 % of the thick plate's, and the ratios within 0.2 % of theory's: the
  // estimator times pulses the sensor samples every millisecond, 1 ms in a 0.6 to 0.8 s period
  // is 0.13 to 0.17 %.
  expect(near(periods.l89, thickPeriod(0.089, lego, h_c, g), 2e-3), `89 mm: ${periods.l89}`);
  expect(near(periods.l70, thickPeriod(0.07, lego, h_c, g), 2e-3), `70 mm: ${periods.l70}`);
  expect(near(periods.iron, thickPeriod(0.089, iron, h_c, g), 2e-3), `iron: ${periods.iron}`);
  const spacing = thickPeriod(0.07, lego, h_c, g) / thickPeriod(0.089, lego, h_c, g);
  expect(near(periods.l70 / periods.l89, spacing, 2e-3), `T70/T89 ${periods.l70 / periods.l89}`);
  const material = thickPeriod(0.089, iron, h_c, g) / thickPeriod(0.089, lego, h_c, g);
  expect(
    near(periods.iron / periods.l89, material, 2e-3),
    `iron/lego ${periods.iron / periods.l89}`,
  );
});

await check("an invalid run-out shows the lab's message beside its control", async () => {
  const { page, context, complaints } = await openPage("/?scene=minimal");
  await page.getByTestId("spacing").filter({ hasText: "89 mm" }).waitFor();
  await page.fill("#runout-mm", "-1");
  await page.press("#runout-mm", "Enter");
  const field = page.locator(".field", { has: page.locator("#runout-mm") });
  await field.getByTestId("problem-runout").filter({ hasText: "must be >= 0" }).waitFor();
  // The browser logs the refusal's 400 itself; nothing else may complain.
  const others = complaints.filter((c) => !c.includes("status of 400"));
  expect(others.length === 0, `console: ${others.join("\n")}`);
  await context.close();
});

await check(
  "a spacing beyond the drive's gears is refused at its control, never sent",
  async () => {
    const { page, context, complaints } = await openPage("/?scene=paper-rig");
    await page.getByTestId("spacing").filter({ hasText: "89 mm" }).waitFor();
    await page.fill("#spacing-mm", "120");
    await page.press("#spacing-mm", "Enter");
    const problem = page.getByTestId("problem-spacing");
    // The range is the lab's own (its checks, bisected): the page says it without asking.
    await problem.filter({ hasText: "beyond what this set-up accepts, 40 to 104 mm" }).waitFor();
    // And the lab refuses that value itself, at the spacing, saying why (its gears).
    const refused = await fetch(`${base}/api/sessions`, {
      method: "POST",
      body: JSON.stringify({ scene: "paper-rig", set: ["rollers.spacing=120mm"] }),
    });
    const why = await refused.json();
    expect(
      refused.status === 400 && why.problems[0].value === "rollers.spacing=120mm",
      `the lab: ${JSON.stringify(why)}`,
    );
    expect(/spans roller spacings from 40 to 104 mm/.test(why.problems[0].message), "no reason");
    const text = await problem.textContent();
    expect(!text.includes("/") && !text.includes(".yaml"), `a path in the message: ${text}`);
    expect((await page.getByTestId("problem-scene").textContent()) === "", "a problem at Scene");
    expect((await page.locator("#spacing-mm").inputValue()) === "89", "the control left at 120");
    // Another control still works: the spacing's refused value is not sent again.
    await page.selectOption("#material", "iron@300");
    await page.getByTestId("material").filter({ hasText: "iron" }).waitFor();
    const others = complaints.filter((c) => !c.includes("status of 400"));
    expect(others.length === 0, `console: ${others.join("\n")}`);
    await context.close();
  },
);

await check("the lab report's numbers are summary.json's; its print preview", async () => {
  const { page, context, complaints } = await openPage(
    `/?scene=minimal&set=${encodeURIComponent(duration)}`,
  );
  await page.fill("#student-name", "Anne-Marie (2B)");
  // A timing by hand while it runs: the report lists it.
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  await page.click("#stopwatch-toggle");
  await page
    .getByTestId("time")
    .filter({ hasText: /t = [1-9]/ })
    .waitFor({ timeout: 60000 });
  await page.click("#stopwatch-toggle");
  await page.getByTestId("status").filter({ hasText: "done" }).waitFor({ timeout: 60000 });
  // The student's own measurement, read in "Your measurement": a part of the report too.
  await page
    .getByTestId("measurement-file")
    .setInputFiles(`${repository}/assets/examples/instruments/phone-magnetometer.csv`);
  const measured = page.getByTestId("measured-period");
  await page.waitForFunction(() =>
    document.querySelector('[data-testid="measured-period"]').getAttribute("data-value"),
  );
  const measuredPeriod = await measured.getAttribute("data-value");
  const button = page.getByTestId("export-report");
  await page.waitForFunction(
    () => !document.querySelector('[data-testid="export-report"]').disabled,
  );
  const [download] = await Promise.all([page.waitForEvent("download"), button.click()]);
  const html = readFileSync(await download.path(), "utf8");
  const summaryHref = await page.getByTestId("file-summary").getAttribute("href");
  const summary = await (await fetch(new URL(summaryHref, base))).json();
  // The simulation's part (the measurement's numbers are its estimate's, checked below).
  const marked = reportAgainstSummary(html.split("<h2>Measurement:")[0], summary);
  expect(marked.problems.length === 0, marked.problems.join("; "));
  expect(marked.count >= 7, `only ${marked.count} numbers marked (T, dT, N, σ, μk, dμk, worst)`);
  expect(html.includes("Anne-Marie (2B)"), "the student's name is not in the report");
  expect(html.includes("Timed by hand"), "the stopwatch's timing is not in the report");
  expect(html.includes("American Journal of Physics"), "the paper is not cited");
  expect(html.includes("Measurement: phone-magnetometer.csv"), "the measurement is not in it");
  const reported =
    /<h2>Measurement: phone-magnetometer.csv<\/h2>[\s\S]*?data-field="period_s" data-value="([^"]*)"/.exec(
      html,
    );
  expect(
    reported && Number(reported[1]) === Number(measuredPeriod),
    `the measurement's T: report ${reported?.[1]}, page ${measuredPeriod}`,
  );
  // The measurement read again from its file: its signal and every period, as the command
  // line's report of the same file at the same spacing lists them.
  const part = html.slice(html.indexOf("<h2>Measurement: phone-magnetometer.csv"));
  const table = part.slice(part.indexOf('<table class="periods-table">'));
  const rows = table.slice(0, table.indexOf("</table>")).split("<tr").length - 2; // - header
  const cli = JSON.parse(
    execFileSync(
      options.exe,
      [
        "report",
        `${repository}/assets/examples/instruments/phone-magnetometer.csv`,
        "--spacing",
        "89mm",
        "--out",
        join(mkdtempSync(join(tmpdir(), "fl-report-")), "report.html"),
        "--json",
      ],
      { encoding: "utf8" },
    ),
  );
  expect(
    rows === cli.parts[0].periods,
    `the measurement's periods: ${rows}, report's ${cli.parts[0].periods}`,
  );
  expect(part.split("<svg").length - 1 >= 2, "the measurement's signal and periods are not drawn");
  // Its print preview, on A4: looked at by whoever changes the report (options.report).
  const preview = await context.newPage();
  await preview.setContent(html);
  await preview.emulateMedia({ media: "print" });
  await preview.setViewportSize({ width: 794, height: 1123 });
  await preview.screenshot({ path: options.report, fullPage: false });
  const others = complaints.filter((c) => !c.includes("status of 400"));
  expect(others.length === 0, `console: ${others.join("\n")}`);
  await context.close();
});

await check("on a French page the lab report is in French, its numbers the same", async () => {
  const { page, context, complaints } = await openPage(
    `/?lang=fr&scene=minimal&set=${encodeURIComponent(duration)}`,
  );
  await page
    .getByTestId("status")
    .filter({ hasText: /termin/ })
    .waitFor({ timeout: 60000 });
  await page.waitForFunction(
    () => !document.querySelector('[data-testid="export-report"]').disabled,
  );
  const [download] = await Promise.all([
    page.waitForEvent("download"),
    page.getByTestId("export-report").click(),
  ]);
  const html = readFileSync(await download.path(), "utf8");
  expect(html.includes('<html lang="fr">'), "the report is not in French");
  expect(html.includes("Compte rendu"), "the report's title is not French");
  const summaryHref = await page.getByTestId("file-summary").getAttribute("href");
  const summary = await (await fetch(new URL(summaryHref, base))).json();
  const period = /data-field="period_s" data-value="([^"]*)">([^<]*)</.exec(html);
  expect(period && JSON.parse(period[1]) === summary.period_s, `T: ${period?.[1]}`);
  expect(period[2].includes(","), `T shown as ${period[2]}, not with a decimal comma`);
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("the paper's rig loads without console errors; a screenshot is written", async () => {
  const { page, context, complaints } = await openPage("/?scene=paper-rig");
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
  await page.getByTestId("period").filter({ hasText: "±" }).waitFor({ timeout: 60000 });
  await page.screenshot({ path: options.shot });
  expect(existsSync(options.shot), "no screenshot");
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("a measurement file chosen on the page gives estimate's period", async () => {
  const { page, context, complaints } = await openPage("/?scene=paper-rig");
  await page.getByTestId("spacing").filter({ hasText: "89 mm" }).waitFor();
  const input = page.getByTestId("measurement-file");
  const shown = page.getByTestId("measured-period");
  const detail = page.getByTestId("measured-detail");
  const instruments = `${repository}/assets/examples/instruments`;
  for (const [name, instrument] of [
    ["phone-magnetometer.csv", "phyphox magnetometer"],
    ["phone-video.mp4", "video"],
  ]) {
    await input.setInputFiles(`${instruments}/${name}`);
    await detail.filter({ hasText: `${name}: ${instrument}` }).waitFor({ timeout: 60000 });
    const value = Number(await shown.getAttribute("data-value"));
    const expected = JSON.parse(
      execFileSync(options.exe, ["estimate", `${instruments}/${name}`, "--json"], {
        encoding: "utf8",
      }),
    ).period_s;
    expect(value === expected, `${name}: page ${value} s, estimate ${expected} s`);
  }
  // Another spacing: the file is read again, mu_k with it.
  await page.fill("#spacing-mm", "70");
  await page.press("#spacing-mm", "Enter");
  await detail.filter({ hasText: "l = 70 mm" }).waitFor({ timeout: 60000 });
  // A file of no oscillation: the reader's message, at the file as the student named it.
  await input.setInputFiles({
    name: "still.csv",
    mimeType: "text/csv",
    buffer: Buffer.from("t_s,adc\n0,500\n0.001,501\n0.002,500\n0.003,499\n"),
  });
  await page.getByTestId("problem-measurement").filter({ hasText: "still.csv" }).waitFor();
  expect((await shown.textContent()) === "T = — s", "a refused file left a period shown");
  // The browser logs the refusal's 400 itself; nothing else may complain.
  const others = complaints.filter((c) => !c.includes("status of 400"));
  expect(others.length === 0, `console: ${others.join("\n")}`);
  await context.close();
});

await check("on a French page a file the lab cannot read is refused in French", async () => {
  const { page, context, complaints } = await openPage("/?lang=fr&scene=paper-rig");
  await page.getByTestId("spacing").filter({ hasText: "89" }).waitFor();
  const input = page.getByTestId("measurement-file");
  const problem = page.getByTestId("problem-measurement");
  // A cell that is no number: the lab's message from the French catalogue, at its place.
  await input.setInputFiles({
    name: "cells.csv",
    mimeType: "text/csv",
    buffer: Buffer.from("t,x\n0,0.01\n0.1,abc\n"),
  });
  await problem.filter({ hasText: "cells.csv" }).waitFor({ timeout: 60000 });
  const cell = (await problem.textContent()).trim();
  expect(
    cell === "cells.csv:3:5: attendu un nombre dans la colonne « x », trouvé « abc »",
    `the cell's problem: ${cell}`,
  );
  // A still plate: no pulse, the lab's numbers in the French sentence.
  await input.setInputFiles({
    name: "still.csv",
    mimeType: "text/csv",
    buffer: Buffer.from("t_s,adc\n0,500\n0.001,501\n0.002,500\n0.003,499\n"),
  });
  await problem.filter({ hasText: "still.csv" }).waitFor({ timeout: 60000 });
  const still = (await problem.textContent()).trim();
  expect(
    still.startsWith("still.csv:2: aucune impulsion dans 4 échantillons sur 0,003 s") &&
      still.includes("entre 499 et 501 points") &&
      still.endsWith("l’aimant passe-t-il devant le capteur ?"),
    `the still plate's problem: ${still}`,
  );
  expect((await problem.locator("[lang]").count()) === 0, "a French message marked English");
  // A position-time table of a plate that does not move: the instrument named in French too.
  await input.setInputFiles({
    name: "table.csv",
    mimeType: "text/csv",
    buffer: Buffer.from("t,x\n0,0.01\n0.1,0.02\n0.2,0.01\n"),
  });
  await problem.filter({ hasText: "table.csv" }).waitFor({ timeout: 60000 });
  const table = (await problem.textContent()).trim();
  expect(
    table.startsWith(
      "table.csv:1: attendu un mouvement périodique, trouvé aucun dans « x » de l’enregistrement " +
        "(tableau position-temps)",
    ),
    `the table's problem: ${table}`,
  );
  const others = complaints.filter((c) => !c.includes("status of 400"));
  expect(others.length === 0, `console: ${others.join("\n")}`);
  await context.close();
});

await check("a shared server answers only its token's pages and refuses one too many", async () => {
  const shared = await startServer(["--max-sessions", "1", "--token", "s3cret"]);
  try {
    const first = await openPage("/?token=s3cret&scene=minimal", shared.address);
    await first.page.getByTestId("status").filter({ hasText: "playing" }).waitFor();
    // A second page: the lab is full, and the page says so plainly.
    const second = await openPage("/?token=s3cret&scene=minimal", shared.address);
    await second.page.getByTestId("refused").filter({ hasText: "the lab is full" }).waitFor();
    // A page without the token is told what it lacks.
    const stranger = await openPage("/?scene=minimal", shared.address);
    await stranger.page.locator("#page-problem").filter({ hasText: "token" }).waitFor();
    // The browser logs the refusals' 503 and 403 itself; nothing else may complain.
    for (const { complaints } of [first, second, stranger]) {
      const others = complaints.filter((c) => !/status of (503|403)/.test(c));
      expect(others.length === 0, `console: ${others.join("\n")}`);
    }
    for (const { context } of [first, second, stranger]) await context.close();
  } finally {
    shared.child.kill("SIGTERM");
  }
});

await check("the live rig: the page's periods are estimate's on the log it downloads", async () => {
  // A simulated run of the paper's rig with a rigid-foam plate (T = 0.30 s: enough periods in a
  // few seconds), sent in the firmware's format at real speed on a pseudo-terminal.
  const folder = mkdtempSync(join(tmpdir(), "fl-rig-page-"));
  execFileSync(options.exe, [
    "run",
    `${repository}/scenes/paper-rig.yaml`,
    "--set",
    "friction.mu_k=rigid-foam",
    "--duration",
    "4s",
    "--out",
    `${folder}/run`,
  ]);
  const feeder = spawn(
    "python3",
    [`${repository}/web/tests/feed_rig.py`, `${folder}/run/hall.csv`],
    {
      stdio: ["pipe", "pipe", "inherit"],
    },
  );
  const said = createInterface({ input: feeder.stdout });
  const lines = [];
  let heard = () => {};
  said.on("line", (line) => {
    lines.push(line);
    heard();
  });
  const line = (index) =>
    new Promise((done) => {
      const look = () => (lines.length > index ? done(lines[index]) : (heard = look));
      look();
    });
  const port = await line(0);
  const live = await startServer(["--serial", port]);
  try {
    const { page, context, complaints } = await openPage("/?scene=paper-rig", live.address);
    await page.getByTestId("rig-state").filter({ hasText: "waiting" }).waitFor();
    feeder.stdin.write("go\n");
    expect((await line(1)) === "sent", `the feeder said ${lines[1]}`);
    await page.getByTestId("rig-state").filter({ hasText: "4003 lines" }).waitFor();
    const shown = (await page.getByTestId("rig-period").allTextContents()).reverse(); // oldest first
    expect(shown.length >= 8, `${shown.length} periods shown`);
    // The raw log as the page offers it, through `frictionlab estimate` (the same spacing).
    const href = await page.getByTestId("rig-log").getAttribute("href");
    const log = await (await fetch(new URL(href, live.address))).text();
    writeFileSync(`${folder}/rig.log`, log);
    const estimate = JSON.parse(
      execFileSync(options.exe, ["estimate", `${folder}/rig.log`, "--spacing", "89mm", "--json"], {
        encoding: "utf8",
      }),
    );
    const periods = estimate.periods.map((p) => p.period_s.toFixed(6));
    expect(
      periods.length === shown.length || periods.length === shown.length + 1,
      `estimate ${periods.length} periods, page ${shown.length}`,
    );
    for (let i = 0; i < shown.length; ++i)
      expect(shown[i] === periods[i], `period ${i + 1}: page ${shown[i]}, estimate ${periods[i]}`);
    expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
    await context.close();
  } finally {
    feeder.stdin.end();
    live.child.kill("SIGTERM");
    rmSync(folder, { recursive: true, force: true });
  }
});

await browser.close();
server.kill("SIGTERM");
finish();
