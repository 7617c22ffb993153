// The page's catalogues: every Fluent file of ../assets/locales (en.ftl, fr.ftl, ...), one a
// language, named by its language's tag. The page imports them as the module
// "frictionlab:catalogues" ({ en: "the file's text", fr: ... }), which the plugin below makes at
// build time from the files found there: a new file is a new language of the page, with no change
// of code. build.mjs and the tests' importTs (tests/import_ts.mjs) bundle with it.
import { readdir, readFile } from "node:fs/promises";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";

export const LOCALES_DIR = resolve(dirname(fileURLToPath(import.meta.url)), "../assets/locales");

/** Every catalogue: its language's tag (the file's name without .ftl) and its text, by tag. */
export async function readCatalogues(dir = LOCALES_DIR) {
  const names = (await readdir(dir)).filter((name) => name.endsWith(".ftl")).sort();
  const catalogues = {};
  for (const name of names) {
    catalogues[name.slice(0, -".ftl".length)] = await readFile(join(dir, name), "utf8");
  }
  return catalogues;
}

/** esbuild's plugin: `import catalogues from "frictionlab:catalogues"` gives readCatalogues(). */
export const cataloguesPlugin = {
  name: "frictionlab-catalogues",
  setup(build) {
    build.onResolve({ filter: /^frictionlab:catalogues$/ }, () => ({
      path: LOCALES_DIR,
      namespace: "frictionlab-catalogues",
    }));
    build.onLoad({ filter: /.*/, namespace: "frictionlab-catalogues" }, async () => {
      const catalogues = await readCatalogues();
      if (!("en" in catalogues)) {
        return {
          errors: [{ text: `no en.ftl in ${LOCALES_DIR}: English is every message's fallback` }],
        };
      }
      return {
        contents: `export default ${JSON.stringify(catalogues)};`,
        loader: "js",
        watchDirs: [LOCALES_DIR],
        watchFiles: Object.keys(catalogues).map((tag) => join(LOCALES_DIR, `${tag}.ftl`)),
      };
    });
  },
};
