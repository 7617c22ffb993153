// Builds the page into a folder: app.js (src/main.ts bundled and minified), app.css (uPlot's
// stylesheet, then the page's) and index.html. The folder: `node build.mjs OUTDIR`, else
// $FRICTIONLAB_WEB_OUT, else dist/ beside this file.
import { build } from "esbuild";
import { copyFile, mkdir, readFile, writeFile } from "node:fs/promises";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const outdir = resolve(process.argv[2] ?? process.env.FRICTIONLAB_WEB_OUT ?? join(here, "dist"));

await mkdir(outdir, { recursive: true });
await build({
  entryPoints: [join(here, "src/main.ts")],
  outfile: join(outdir, "app.js"),
  bundle: true,
  minify: true,
  format: "esm",
  target: ["es2022"],
  sourcemap: false,
  legalComments: "eof",
  logLevel: "warning",
});
const css = await Promise.all([
  readFile(join(here, "node_modules/uplot/dist/uPlot.min.css"), "utf8"),
  readFile(join(here, "app.css"), "utf8"),
]);
await writeFile(join(outdir, "app.css"), css.join("\n"));
await copyFile(join(here, "index.html"), join(outdir, "index.html"));
console.log(`built the page into ${outdir}`);
