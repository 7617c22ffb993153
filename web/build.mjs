// Builds the pages into a folder: app.js (src/main.ts, the lab) and class.js (src/class_page.ts,
// the teacher's class table), each bundled and minified with every catalogue of ../assets/locales
// (catalogues.mjs: a new .ftl file there is a new language of the page); app.css (uPlot's
// stylesheet, then the pages'); index.html and class.html. The folder: `node build.mjs OUTDIR`,
// else $FRICTIONLAB_WEB_OUT, else dist/ beside this file.
//   node build.mjs OUTDIR --lab browser   the page of the static site (tools/site): the lab in
//                                         the page's own Web Worker (src/lab_client_worker.ts in
//                                         place of src/lab_client.ts, and lab_worker.js), no
//                                         class table
import { build } from "esbuild";
import { cataloguesPlugin } from "./catalogues.mjs";
import { copyFile, mkdir, readFile, writeFile } from "node:fs/promises";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
const labAt = args.indexOf("--lab");
const lab = labAt >= 0 ? args.splice(labAt, 2)[1] : "server";
if (lab !== "server" && lab !== "browser") {
  console.error(`build.mjs: --lab takes server or browser, found ${lab}`);
  process.exit(2);
}
const outdir = resolve(args[0] ?? process.env.FRICTIONLAB_WEB_OUT ?? join(here, "dist"));

// The browser's lab: every import of the lab client resolves to the worker's.
const workerClient = {
  name: "lab-client-in-the-browser",
  setup(b) {
    b.onResolve({ filter: /^\.\/lab_client$/ }, () => ({
      path: join(here, "src/lab_client_worker.ts"),
    }));
  },
};

const common = {
  outdir,
  bundle: true,
  minify: true,
  target: ["es2022"],
  sourcemap: false,
  legalComments: "eof",
  logLevel: "warning",
};

await mkdir(outdir, { recursive: true });
await build({
  ...common,
  entryPoints:
    lab === "browser"
      ? { app: join(here, "src/main.ts") }
      : { app: join(here, "src/main.ts"), class: join(here, "src/class_page.ts") },
  format: "esm",
  plugins: lab === "browser" ? [workerClient, cataloguesPlugin] : [cataloguesPlugin],
});
if (lab === "browser") {
  // A classic worker: it loads the core's script (frictionlab-lab.js) with importScripts.
  await build({
    ...common,
    entryPoints: { lab_worker: join(here, "src/lab_worker.ts") },
    format: "iife",
  });
}
const css = await Promise.all([
  readFile(join(here, "node_modules/uplot/dist/uPlot.min.css"), "utf8"),
  readFile(join(here, "app.css"), "utf8"),
]);
await writeFile(join(outdir, "app.css"), css.join("\n"));
for (const page of lab === "browser" ? ["index.html"] : ["index.html", "class.html"]) {
  await copyFile(join(here, page), join(outdir, page));
}
console.log(
  `built the page (${lab === "browser" ? "the lab in the browser" : "for a server"}) into ${outdir}`,
);
