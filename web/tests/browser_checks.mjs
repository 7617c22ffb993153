// What the browser tests share: Debian's chromium (CHROMIUM=/path for another), headless on
// software WebGL, a plain static server (Python's), and the checks each test runs, each printed on a line as it ends and counted for
// the test's summary and exit status (0 all passed, 1 a check failed, 77 no chromium: skipped).
import { spawn } from "node:child_process";
import { existsSync } from "node:fs";
import { createInterface } from "node:readline";
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
