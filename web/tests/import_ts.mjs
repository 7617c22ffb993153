// A module of the page (TypeScript) loaded into node for a test: bundled by esbuild in memory and
// imported from the bundle's text.
import { build } from "esbuild";

export async function importTs(path) {
  const bundled = await build({
    entryPoints: [path],
    bundle: true,
    format: "esm",
    write: false,
    logLevel: "warning",
  });
  return import(
    "data:text/javascript;base64," + Buffer.from(bundled.outputFiles[0].text).toString("base64")
  );
}
