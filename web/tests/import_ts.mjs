// A module of the page (TypeScript) loaded into node for a test: bundled by esbuild in memory and
// imported from the bundle's text, with the page's catalogues (catalogues.mjs).
import { build } from "esbuild";
import { cataloguesPlugin } from "../catalogues.mjs";

export async function importTs(path) {
  const bundled = await build({
    entryPoints: [path],
    bundle: true,
    format: "esm",
    write: false,
    logLevel: "warning",
    plugins: [cataloguesPlugin],
  });
  return import(
    "data:text/javascript;base64," + Buffer.from(bundled.outputFiles[0].text).toString("base64")
  );
}
