// Builds the pages into a folder: app.js (src/main.ts, the lab) and class.js (src/class_page.ts,
// the teacher's class table), each bundled and minified; app.css (uPlot's stylesheet, then the
// pages'); index.html and class.html. The folder: `node build.mjs OUTDIR`, else
// $FRICTIONLAB_WEB_OUT, else dist/ beside this file.
import { build } from "esbuild";
import { copyFile, mkdir, readFile, writeFile } from "node:fs/promises";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const outdir = resolve(process.argv[2] ?? process.env.FRICTIONLAB_WEB_OUT ?? join(here, "dist"));

await mkdir(outdir, { recursive: true });
await build({
  entryPoints: {
    app: join(here, "src/main.ts"),
    class: join(here, "src/class_page.ts"),
  },
  outdir,
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
for (const page of ["index.html", "class.html"]) {
  await copyFile(join(here, page), join(outdir, page));
}
console.log(`built the page into ${outdir}`);
