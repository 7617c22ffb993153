// The static site (tools/site) in Debian's chromium, headless, served by a plain static server
// (python3 -m http.server): the lab runs in the page's own worker. A link's period is
// `frictionlab run`'s for the same set-up (data-value, within 1e-9 relative), a refused set-up
// shows the request layer's message at its control, a rig log and a phone's file chosen in the
// file input give `frictionlab estimate`'s period, no request leaves for an API, a reload with
// the network gone still opens the lab (the service worker), and the live rig through a stand-in
// for Web Serial shows the periods `frictionlab estimate` finds in the log the page saves.
//
//   node tests/site_page.test.mjs --site DIR --exe build/release/src/cli/frictionlab [--shot FILE]
// Exit status: 0 all passed, 1 a check failed, 77 no chromium or no site (the test is skipped).
import { execFileSync } from "node:child_process";
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { parseArgs } from "node:util";
import {
  check,
  expect,
  finish,
  launchChromium,
  serveFolder,
  skipWithoutChromium,
  reportAgainstSummary,
} from "./browser_checks.mjs";

const repository = resolve(dirname(fileURLToPath(import.meta.url)), "../..");
const { values: options } = parseArgs({
  options: {
    site: { type: "string" },
    exe: { type: "string" },
    shot: { type: "string", default: "/tmp/frictionlab-site.png" },
  },
});
if (!options.site || !options.exe) {
  console.error("usage: node tests/site_page.test.mjs --site DIR --exe FRICTIONLAB [--shot FILE]");
  process.exit(2);
}
skipWithoutChromium();
if (!existsSync(join(options.site, "frictionlab-lab.wasm"))) {
  console.error(`skipped: no site in ${options.site} (tools/site ${options.site} builds it)`);
  process.exit(77);
}

// Python's own static server: the site as any web space serves it.
const served = await serveFolder(resolve(options.site));
const base = served.base;
const browser = await launchChromium();

/** A page at `path`: the console's errors and warnings, and every address it asked for. */
async function openPage(path, context = null) {
  const own = context ?? (await browser.newContext({ viewport: { width: 1366, height: 768 } }));
  const page = await own.newPage();
  const complaints = [];
  const asked = [];
  page.on("console", (m) => {
    if (m.type() === "error" || m.type() === "warning") complaints.push(m.text());
  });
  page.on("pageerror", (error) => complaints.push(`pageerror: ${error.message}`));
  own.on("request", (request) => asked.push(request.url()));
  await page.goto(`${base}${path}`);
  return { page, context: own, complaints, asked };
}

function runJson(args) {
  return JSON.parse(execFileSync(options.exe, args, { encoding: "utf8" }));
}

await check("a link's set-up runs in the page and its period is run's", async () => {
  const set = ["world.duration=6s", "rollers.spacing=70mm"];
  const query = ["scene=minimal", ...set.map((s) => `set=${encodeURIComponent(s)}`)].join("&");
  const { page, context, complaints, asked } = await openPage(`/?${query}`);
  await page.getByTestId("lab-place").filter({ hasText: "in this browser" }).waitFor();
  // The class (a student's name, the class's table) is a classroom server's.
  expect(await page.locator("#class-section").isHidden(), "the class's section is shown");
  await page.getByTestId("status").filter({ hasText: "done" }).waitFor({ timeout: 60000 });
  const shown = Number(await page.getByTestId("period").getAttribute("data-value"));
  const args = ["run", `${repository}/scenes/minimal.yaml`, "--json"];
  for (const s of set) args.push("--set", s);
  const expected = runJson(args).period_s;
  expect(Math.abs(shown / expected - 1) <= 1e-9, `page ${shown} s, run ${expected} s`);
  await page.screenshot({ path: options.shot });
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  const api = asked.filter((url) => new URL(url).pathname.includes("/api/"));
  expect(api.length === 0, `requests for an API: ${api.join(", ")}`);
  const elsewhere = asked.filter((url) => !url.startsWith(base) && !url.startsWith("blob:"));
  expect(elsewhere.length === 0, `requests beyond the site: ${elsewhere.join(", ")}`);
  await context.close();
});

await check("the lab report, made in this browser: its numbers are summary.json's", async () => {
  const { page, context, complaints, asked } = await openPage(
    `/?scene=minimal&set=${encodeURIComponent("world.duration=6s")}`,
  );
  await page.getByTestId("status").filter({ hasText: "done" }).waitFor({ timeout: 60000 });
  // The student's measurement, read in this browser: in the report with its periods.
  await page
    .getByTestId("measurement-file")
    .setInputFiles(`${repository}/assets/examples/instruments/phone-magnetometer.csv`);
  await page.waitForFunction(() =>
    document.querySelector('[data-testid="measured-period"]').getAttribute("data-value"),
  );
  await page.waitForFunction(
    () => !document.querySelector('[data-testid="export-report"]').disabled,
  );
  const [download] = await Promise.all([
    page.waitForEvent("download"),
    page.getByTestId("export-report").click(),
  ]);
  const whole = readFileSync(await download.path(), "utf8");
  const at = whole.indexOf("<h2>Measurement: phone-magnetometer.csv");
  expect(at > 0, "the measurement is not in the report");
  const part = whole.slice(at);
  const table = part.slice(part.indexOf('<table class="periods-table">'));
  const rows = table.slice(0, table.indexOf("</table>")).split("<tr").length - 2; // - header
  expect(rows >= 5, `the measurement's periods: ${rows} rows`);
  const html = whole.slice(0, at);
  // summary.json as the page offers it (a Blob's address), read in the page.
  const summary = JSON.parse(
    await page.evaluate(async () => {
      const href = document.querySelector('[data-testid="file-summary"]').href;
      return (await fetch(href)).text();
    }),
  );
  const marked = reportAgainstSummary(html, summary);
  expect(marked.problems.length === 0, marked.problems.join("; "));
  // The simulation's part (the measurement's numbers are its estimate's).
  expect(marked.count >= 7, `only ${marked.count} numbers marked (T, dT, N, σ, μk, dμk, worst)`);
  expect(whole.includes("American Journal of Physics"), "the paper is not cited");
  const api = asked.filter((url) => new URL(url).pathname.includes("/api/"));
  expect(api.length === 0, `requests for an API: ${api.join(", ")}`);
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("the site works from a folder of a web space, its links too", async () => {
  // The static server's folder is the site's parent: the lab is at /NAME/.
  const folder = resolve(options.site);
  const name = folder.split("/").pop();
  const parent = await serveFolder(dirname(folder));
  const at = parent.base;
  try {
    const context = await browser.newContext({ viewport: { width: 1366, height: 768 } });
    const page = await context.newPage();
    await page.goto(
      `${at}/${name}/?scene=minimal&set=${encodeURIComponent("rollers.spacing=70mm")}`,
    );
    await page.getByTestId("status").filter({ hasText: "playing" }).waitFor({ timeout: 60000 });
    await page.getByTestId("spacing").filter({ hasText: "70 mm" }).waitFor();
    const link = await page.getByTestId("setup-link").inputValue();
    expect(
      link === `${at}/${name}/?scene=minimal&set=rollers.spacing%3D70mm`,
      `the link to the set-up: ${link}`,
    );
    await context.close();
  } finally {
    parent.stop();
  }
});

await check("a refused set-up shows the request layer's message at its control", async () => {
  const { page, context } = await openPage("/?scene=minimal");
  await page.getByTestId("spacing").filter({ hasText: "89 mm" }).waitFor({ timeout: 30000 });
  await page.fill("#runout-mm", "-1");
  await page.press("#runout-mm", "Enter");
  const field = page.locator(".field", { has: page.locator("#runout-mm") });
  const problem = field.getByTestId("problem-runout");
  await problem.filter({ hasText: "must be >= 0" }).waitFor();
  // The words the request layer writes (BrowserLab answers with them as the server does).
  const text = await problem.textContent();
  expect(text.includes("found -1 mm"), `the message: ${text}`);
  await context.close();
});

await check("a rig log and a phone's file chosen on the page give estimate's period", async () => {
  const { page, context, complaints } = await openPage("/?scene=paper-rig");
  await page.getByTestId("spacing").filter({ hasText: "89 mm" }).waitFor({ timeout: 30000 });
  const input = page.getByTestId("measurement-file");
  const shown = page.getByTestId("measured-period");
  const detail = page.getByTestId("measured-detail");
  const instruments = `${repository}/assets/examples/instruments`;
  for (const file of [
    `${repository}/assets/examples/spacing-series/lego-l089.csv`,
    `${instruments}/phone-magnetometer.csv`,
    `${instruments}/phone-accelerometer.csv`,
    `${instruments}/phone-export.zip`,
    `${instruments}/tracker-plate.txt`,
  ]) {
    const name = file.split("/").pop();
    await input.setInputFiles(file);
    await detail
      .filter({ hasText: `${name}` })
      .filter({ hasText: "N = " })
      .waitFor({ timeout: 60000 });
    const value = Number(await shown.getAttribute("data-value"));
    const expected = runJson(["estimate", file, "--json"]).period_s;
    expect(value === expected, `${name}: page ${value} s, estimate ${expected} s`);
  }
  // A file dropped on the panel is read as one chosen.
  const dropped = `${instruments}/tracker-plate.txt`;
  await page.getByTestId("measurement-file").setInputFiles([]);
  const transfer = await page.evaluateHandle(
    ({ text }) => {
      const files = new DataTransfer();
      files.items.add(new File([text], "dropped-tracker.txt"));
      return files;
    },
    { text: readFileSync(dropped, "utf8") },
  );
  await page.getByTestId("measurement-panel").dispatchEvent("drop", { dataTransfer: transfer });
  await detail.filter({ hasText: "dropped-tracker.txt" }).filter({ hasText: "N = " }).waitFor();
  const fromDrop = Number(await shown.getAttribute("data-value"));
  const expectedDrop = runJson(["estimate", dropped, "--json"]).period_s;
  expect(fromDrop === expectedDrop, `dropped: page ${fromDrop} s, estimate ${expectedDrop} s`);

  // A phone's video: decoded by the browser's own decoder (not libav), its plate followed by the
  // lab's tracker. The decoders' pictures differ in their grey levels, so the period is held to
  // the native estimate's within its standard error.
  await input.setInputFiles(`${instruments}/phone-video.mp4`);
  await detail
    .filter({ hasText: "phone-video.mp4" })
    .filter({ hasText: "N = " })
    .waitFor({ timeout: 120000 });
  const video = Number(await shown.getAttribute("data-value"));
  const native = runJson(["estimate", `${instruments}/phone-video.mp4`, "--json"]);
  console.log(
    `     the video: page ${video} s, estimate ${native.period_s} s (se ${native.period_sem_s} s)`,
  );
  expect(
    Math.abs(video - native.period_s) <= native.period_sem_s,
    `phone-video.mp4: page ${video} s, estimate ${native.period_s} +- ${native.period_sem_s} s`,
  );
  expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
  await context.close();
});

await check("a reload with the network gone still opens the lab", async () => {
  const { page, context } = await openPage("/?scene=minimal");
  await page.getByTestId("spacing").filter({ hasText: "89 mm" }).waitFor({ timeout: 30000 });
  // The service worker has cached the site once it controls the page.
  await page.evaluate(async () => {
    await navigator.serviceWorker.ready;
    if (!navigator.serviceWorker.controller) {
      await new Promise((done) =>
        navigator.serviceWorker.addEventListener("controllerchange", done, { once: true }),
      );
    }
  });
  await context.setOffline(true);
  await page.reload();
  await page.getByTestId("lab-place").filter({ hasText: "in this browser" }).waitFor();
  await page.getByTestId("status").filter({ hasText: "playing" }).waitFor({ timeout: 30000 });
  await page.getByTestId("period").filter({ hasText: "±" }).waitFor({ timeout: 60000 });
  await context.close();
});

await check(
  "the rig through Web Serial: the page's periods are estimate's on its log",
  async () => {
    // A simulated run of the paper's rig with a rigid-foam plate (T = 0.30 s), as the firmware's
    // lines, from a port that a script in the page stands in for (navigator.serial).
    const folder = mkdtempSync(join(tmpdir(), "fl-site-rig-"));
    try {
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
      const rows = readFileSync(`${folder}/run/hall.csv`, "utf8").trim().split("\n").slice(1);
      const sent =
        "# frictionlab rig firmware 1: sample_hz=1000 sample_us=1000.0000 raw_every=1\r\n" +
        "t_us,adc\r\n" +
        rows.map((row) => `${row}\r\n`).join("");
      const context = await browser.newContext({ viewport: { width: 1366, height: 768 } });
      await context.addInitScript((text) => {
        const bytes = new TextEncoder().encode(text);
        let at = 0;
        const readable = new ReadableStream({
          // Pieces of 1000 bytes every 5 ms: lines split anywhere, as a port gives them.
          pull: (controller) =>
            new Promise((done) =>
              setTimeout(() => {
                if (at >= bytes.length) controller.close();
                else controller.enqueue(bytes.slice(at, (at += 1000)));
                done();
              }, 5),
            ),
        });
        const port = {
          readable,
          open: async ({ baudRate }) => {
            if (baudRate !== 250000) throw new Error(`opened at ${baudRate} baud`);
          },
          close: async () => {},
          getInfo: () => ({ usbVendorId: 0x2341, usbProductId: 0x0043 }),
        };
        Object.defineProperty(navigator, "serial", {
          value: { requestPort: async () => port },
          configurable: true,
        });
      }, sent);
      const { page, complaints } = await openPage("/?scene=paper-rig", context);
      await page.getByTestId("spacing").filter({ hasText: "89 mm" }).waitFor({ timeout: 30000 });
      await page.locator("#rig-details").evaluate((details) => (details.open = true));
      await page.getByTestId("rig-connect").click();
      const lines = rows.length + 2;
      await page
        .getByTestId("rig-state")
        .filter({ hasText: `unplugged: USB 2341:0043 went away after ${lines} lines` })
        .waitFor({ timeout: 60000 });
      const shown = (await page.getByTestId("rig-period").allTextContents()).reverse();
      expect(shown.length >= 8, `${shown.length} periods shown`);
      // The log as the page saves it: every byte the port gave.
      const link = page.getByTestId("rig-log");
      await page.waitForFunction(
        async (count) => {
          const href = document.querySelector('[data-testid="rig-log"]')?.getAttribute("href");
          if (!href) return false;
          const text = await (await fetch(href)).text();
          return text.split("\n").length - 1 === count;
        },
        lines,
        { timeout: 10000 },
      );
      const log = await link.evaluate(async (a) => (await fetch(a.href)).text());
      expect(log === sent, "the saved log is not what the port sent");
      writeFileSync(`${folder}/rig.log`, log);
      const estimate = runJson(["estimate", `${folder}/rig.log`, "--spacing", "89mm", "--json"]);
      const periods = estimate.periods.map((p) => p.period_s.toFixed(6));
      expect(
        periods.length === shown.length || periods.length === shown.length + 1,
        `estimate ${periods.length} periods, page ${shown.length}`,
      );
      for (let i = 0; i < shown.length; ++i)
        expect(
          shown[i] === periods[i],
          `period ${i + 1}: page ${shown[i]}, estimate ${periods[i]}`,
        );
      expect(complaints.length === 0, `console: ${complaints.join("\n")}`);
      await context.close();
    } finally {
      rmSync(folder, { recursive: true, force: true });
    }
  },
);

await check("a browser without Web Serial says so and offers the file", async () => {
  // Firefox and Safari have no navigator.serial.
  const context = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  await context.addInitScript(() =>
    Object.defineProperty(navigator, "serial", { value: undefined, configurable: true }),
  );
  const { page } = await openPage("/?scene=minimal", context);
  await page.locator("#rig-details").evaluate((details) => (details.open = true));
  await page.getByTestId("rig-state").filter({ hasText: "Web Serial" }).waitFor({ timeout: 30000 });
  expect(await page.getByTestId("rig-connect").isDisabled(), "Connect is offered");
  await context.close();
});

await browser.close();
served.stop();
finish();
