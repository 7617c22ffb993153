// What the browser tests share: Debian's chromium (CHROMIUM=/path for another), headless on
// software WebGL, and the checks each test runs, each printed on a line as it ends and counted for
// the test's summary and exit status (0 all passed, 1 a check failed, 77 no chromium: skipped).
import { existsSync } from "node:fs";
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
export function finish() {
  console.log(`${tally.passed} passed, ${tally.failed} failed`);
  process.exit(tally.failed === 0 ? 0 : 1);
}
