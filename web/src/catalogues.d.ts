// The page's catalogues, by language tag: the text of each ../assets/locales/TAG.ftl, made at build
// time by catalogues.mjs's esbuild plugin.
declare module "frictionlab:catalogues" {
  const catalogues: Readonly<Record<string, string>>;
  export default catalogues;
}
