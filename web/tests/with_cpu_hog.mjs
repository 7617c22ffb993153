// Runs a command while busy loops burn the machine's cores: the browser tests on a loaded
// machine, as the CI runs them a second time. The hogs end with the command however it ends (its
// exit, a signal to this runner); each also ends by itself once its parent is gone, so that not
// even a runner killed outright leaves one behind. Exits with the command's status (77: skipped).
//
//   node tests/with_cpu_hog.mjs [--hogs N] -- COMMAND [ARGS...]     (N: the cores, by default)
import { spawn } from "node:child_process";
import { availableParallelism, constants } from "node:os";

const args = process.argv.slice(2);
const dashes = args.indexOf("--");
if (dashes < 0 || dashes === args.length - 1) {
  console.error("usage: node tests/with_cpu_hog.mjs [--hogs N] -- COMMAND [ARGS...]");
  process.exit(2);
}
const [command, ...commandArgs] = args.slice(dashes + 1);
const hogsAt = args.indexOf("--hogs");
const hogCount = hogsAt >= 0 && hogsAt < dashes ? Number(args[hogsAt + 1]) : availableParallelism();
if (!Number.isInteger(hogCount) || hogCount < 1) {
  console.error(`expected --hogs as a whole number of 1 or more, found ${args[hogsAt + 1]}`);
  process.exit(2);
}

// A busy loop that looks every ten million turns whether its parent is still this runner.
const BUSY = `const parent = process.ppid;
for (let i = 0; ; i++) if (i % 1e7 === 0 && process.ppid !== parent) process.exit(0);`;
const hogs = Array.from({ length: hogCount }, () =>
  spawn(process.execPath, ["-e", BUSY], { stdio: "ignore" }),
);
console.log(
  `with_cpu_hog: ${hogCount} busy loop(s) beside: ${[command, ...commandArgs].join(" ")}`,
);

function stopHogs() {
  for (const hog of hogs) if (hog.exitCode === null && hog.signalCode === null) hog.kill("SIGKILL");
}
process.on("exit", stopHogs);

const child = spawn(command, commandArgs, { stdio: "inherit" });
for (const signal of ["SIGINT", "SIGTERM", "SIGHUP"]) {
  process.on(signal, () => {
    child.kill(signal);
    stopHogs();
    process.exit(128 + constants.signals[signal]);
  });
}
child.on("error", (error) => {
  console.error(`with_cpu_hog: could not run ${command}: ${error.message}`);
  process.exit(127);
});
child.on("exit", (code, signal) => {
  stopHogs();
  process.exit(code ?? 128 + constants.signals[signal]);
});
