// What the browser tests share: Debian's chromium (CHROMIUM=/path for another), headless on
// software WebGL, a plain static server (Python's), and the checks each test runs, each printed on a line as it ends and counted for
// the test's summary and exit status (0 all passed, 1 a check failed, 77 no chromium: skipped).
import { spawn } from "node:child_process";
import { existsSync } from "node:fs";
import { dirname, join } from "node:path";
import { createInterface } from "node:readline";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";

export const executablePath = process.env.CHROMIUM ?? "/usr/bin/chromium";

/** Ends the test as skipped (77) when there is no chromium. */
export function skipWithoutChromium() {
  if (existsSync(executablePath)) return;
  console.error(
    `skipped: no chromium at ${executablePath} (apt-get install chromium, or set CHROMIUM)`,
  );
  process.exit(77);
}

/** Chromium, headless, drawing WebGL in software (SwiftShader). */
export function launchChromium() {
  return chromium.launch({
    executablePath,
    args: ["--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--no-sandbox"],
  });
}

/** `folder` served by python3 -m http.server on any free port of 127.0.0.1: its address, and
 * how to stop it. */
export async function serveFolder(folder) {
  const server = spawn(
    "python3",
    ["-u", "-m", "http.server", "0", "--bind", "127.0.0.1", "--directory", folder],
    { stdio: ["ignore", "pipe", "ignore"] },
  );
  const base = await new Promise((done, fail) => {
    createInterface({ input: server.stdout }).on("line", (line) => {
      const found = /port (\d+)/.exec(line);
      if (found) done(`http://127.0.0.1:${found[1]}`);
    });
    server.on("exit", (code) => fail(new Error(`python3 -m http.server exited with ${code}`)));
  });
  return { base, stop: () => server.kill() };
}

/** A deadline for a wait that fails only when something is wrong, not when the machine is busy
 * (two cores shared with a build, a CPU hog beside the test). */
export const WAIT_MS = 60000;

/** `url` in a browser context of its own (`contextOptions`: viewport, locale, ...; `initScript`
 * runs in each page before its own script), recording the console's errors and warnings. */
export async function openWatchedPage(browser, url, contextOptions, initScript = null) {
  const context = await browser.newContext(contextOptions);
  context.setDefaultTimeout(WAIT_MS);
  if (initScript) await context.addInitScript(initScript);
  const page = await context.newPage();
  const complaints = [];
  page.on("console", (message) => {
    if (message.type() === "error" || message.type() === "warning") {
      complaints.push(`${message.type()}: ${message.text()}`);
    }
  });
  page.on("pageerror", (error) => complaints.push(`pageerror: ${error.message}`));
  await page.goto(url);
  return { page, context, complaints };
}

/** What differs between the numbers a lab report marks (data-field, data-value) and the run's
 * summary.json: { count, problems }. */
export function reportAgainstSummary(html, summary) {
  const problems = [];
  let count = 0;
  for (const [, field, value] of html.matchAll(/data-field="([a-z_]+)" data-value="([^"]*)"/g)) {
    if (!(field in summary)) problems.push(`the report's ${field} is not summary.json's`);
    else if (JSON.stringify(JSON.parse(value)) !== JSON.stringify(summary[field]))
      problems.push(`${field}: report ${value}, summary.json ${summary[field]}`);
    count += 1;
  }
  return { count, problems };
}

const tally = { passed: 0, failed: 0 };

/** Runs one check: "ok NAME (ms)" or "FAIL NAME: why", the test going on either way. */
export async function check(name, body) {
  const started = Date.now();
  try {
    await body();
    tally.passed += 1;
    console.log(`ok   ${name} (${Date.now() - started} ms)`);
  } catch (error) {
    tally.failed += 1;
    console.log(`FAIL ${name}: ${error instanceof Error ? error.stack : error}`);
  }
}

export function expect(condition, message) {
  if (!condition) throw new Error(message);
}

/** Prints how many checks passed and failed, and ends the test with its status. */
const axeScript = join(
  dirname(fileURLToPath(import.meta.url)),
  "../node_modules/axe-core/axe.min.js",
);

/** Checks axe-core's WCAG 2.1 A and AA rules on the page: each violation fails the check,
 * listed as "id at target: summary" with `when` it was seen. */
export async function expectNoViolations(page, when) {
  if (!(await page.evaluate(() => "axe" in window))) await page.addScriptTag({ path: axeScript });
  const violations = await page.evaluate(async () => {
    const result = await window.axe.run(document, {
      runOnly: { type: "tag", values: ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"] },
    });
    return result.violations.flatMap((v) =>
      v.nodes.map((n) => `${v.id} at ${n.target.join(" ")}: ${n.failureSummary}`),
    );
  });
  expect(violations.length === 0, `axe ${when}:\n  ${violations.join("\n  ")}`);
}

export function finish() {
  console.log(`${tally.passed} passed, ${tally.failed} failed`);
  process.exit(tally.failed === 0 ? 0 : 1);
}
