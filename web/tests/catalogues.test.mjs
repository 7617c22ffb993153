// The page's catalogues (../assets/locales/*.ftl, Fluent), held to each other and to the page:
// each parses whole with @fluent/bundle (every entry the file starts is a message it reads, none
// given twice) and formats every message and attribute without an error; each holds the messages,
// the attributes and, message by message, the variables English's holds; every id the page asks
// for (index.html's and class.html's data-l10n-id with the attributes their data-l10n-attrs
// name, src/'s t("...") and a regime's message for each regime the lab names) is in English's;
// and every message of English's is asked for by the page or said by the C++ lab (the report-*
// messages are the C++ lab's own, for its report).
//
//   node tests/catalogues.test.mjs
import { FluentBundle, FluentResource } from "@fluent/bundle";
import { readdir, readFile } from "node:fs/promises";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { readCatalogues } from "../catalogues.mjs";
import { importTs } from "./import_ts.mjs";

const web = join(dirname(fileURLToPath(import.meta.url)), "..");
const repository = join(web, "..");
let failed = 0;
const fail = (message) => {
  console.error(message);
  failed += 1;
};

/** The variables a pattern uses (in its text, its selectors and its variants). */
function variablesOf(pattern, into = new Set()) {
  if (typeof pattern === "string" || pattern === null) return into;
  for (const element of pattern) {
    if (typeof element !== "string") expressionVariables(element, into);
  }
  return into;
}

function expressionVariables(expression, into) {
  switch (expression.type) {
    case "var":
      into.add(expression.name);
      break;
    case "select":
      expressionVariables(expression.selector, into);
      for (const variant of expression.variants) variablesOf(variant.value, into);
      break;
    case "func":
    case "term":
      for (const argument of [...expression.positional, ...expression.named]) {
        expressionVariables(argument.type === "narg" ? argument.value : argument, into);
      }
      break;
  }
  return into;
}

/** A catalogue's messages: id -> { value: Set of variables or null, attributes: name -> Set }. */
function messagesOf(resource) {
  const messages = new Map();
  for (const entry of resource.body) {
    if (entry.id.startsWith("-")) continue; // a term: used through the messages
    const attributes = new Map(
      Object.entries(entry.attributes).map(([name, pattern]) => [name, variablesOf(pattern)]),
    );
    messages.set(entry.id, {
      value: entry.value === null ? null : variablesOf(entry.value),
      attributes,
    });
  }
  return messages;
}

const sameSet = (a, b) => a.size === b.size && [...a].every((x) => b.has(x));
const listed = (set) => `{${[...set].sort().join(", ")}}`;

// Each catalogue read whole, and formatted.
const catalogues = await readCatalogues();
const tags = Object.keys(catalogues);
if (!tags.includes("en") || tags.length < 2) fail(`catalogues: ${tags.join(", ")}`);
const parsed = new Map();
for (const [tag, text] of Object.entries(catalogues)) {
  const resource = new FluentResource(text);
  // The runtime parser skips an entry it cannot read: every entry the file starts must be read.
  const started = [...text.matchAll(/^(-?[a-zA-Z][\w-]*)\s*=/gm)].map((m) => m[1]);
  const read = resource.body.map((entry) => entry.id);
  const skipped = started.filter((id) => !read.includes(id));
  if (skipped.length > 0 || started.length !== read.length) {
    fail(`${tag}.ftl: entries not read (a syntax error in them): ${skipped.join(", ") || "?"}`);
  }
  const stray = text.split("\n").filter((line) => /^[^\s#\-a-zA-Z]/.test(line));
  if (stray.length > 0) fail(`${tag}.ftl: lines that start no entry: ${stray.join(" | ")}`);
  const bundle = new FluentBundle(tag, { useIsolating: false });
  const errors = bundle.addResource(resource);
  for (const error of errors) fail(`${tag}.ftl: ${error.message}`);
  const messages = messagesOf(resource);
  for (const [id, { value, attributes }] of messages) {
    const message = bundle.getMessage(id);
    const patterns = [
      [id, message.value, value],
      ...[...attributes].map(([name, used]) => [`${id}.${name}`, message.attributes[name], used]),
    ];
    for (const [what, pattern, used] of patterns) {
      if (pattern === null) continue;
      // Each variable a number (the selectors choose their other variant) and then a text.
      for (const sample of [1, "x"]) {
        const args = Object.fromEntries([...used].map((name) => [name, sample]));
        const problems = [];
        bundle.formatPattern(pattern, args, problems);
        for (const problem of problems) fail(`${tag}.ftl: ${what}: ${problem.message}`);
      }
    }
  }
  if (!messages.get("language-name")?.value) fail(`${tag}.ftl: no language-name`);
  parsed.set(tag, messages);
}

// Every catalogue holds English's messages, attributes and variables, and no other.
const english = parsed.get("en") ?? new Map();
for (const [tag, messages] of parsed) {
  if (tag === "en") continue;
  for (const [id, en] of english) {
    const other = messages.get(id);
    if (!other) {
      fail(`${tag}.ftl lacks ${id}`);
      continue;
    }
    if ((en.value === null) !== (other.value === null)) {
      fail(`${tag}.ftl: ${id} has ${other.value === null ? "no" : "a"} value, en.ftl's not`);
    } else if (en.value !== null && !sameSet(en.value, other.value)) {
      fail(`${tag}.ftl: ${id} uses ${listed(other.value)}, en.ftl's ${listed(en.value)}`);
    }
    for (const [name, used] of en.attributes) {
      const theirs = other.attributes.get(name);
      if (!theirs) fail(`${tag}.ftl: ${id} lacks .${name}`);
      else if (!sameSet(used, theirs)) {
        fail(`${tag}.ftl: ${id}.${name} uses ${listed(theirs)}, en.ftl's ${listed(used)}`);
      }
    }
    for (const name of other.attributes.keys()) {
      if (!en.attributes.has(name)) fail(`${tag}.ftl: ${id}.${name} is not in en.ftl`);
    }
  }
  for (const id of messages.keys()) {
    if (!english.has(id)) fail(`${tag}.ftl: ${id} is not in en.ftl`);
  }
}

// What the page asks for is in English's catalogue.
const asked = new Set(["language-name"]);
const need = (id, where, attributes = []) => {
  asked.add(id);
  const message = english.get(id);
  if (!message) {
    fail(`${where} asks for "${id}", which en.ftl lacks`);
    return;
  }
  for (const name of attributes) {
    if (!message.attributes.has(name)) fail(`${where} asks for ${id}.${name}, which en.ftl lacks`);
  }
};
for (const page of ["index.html", "class.html"]) {
  const html = await readFile(join(web, page), "utf8");
  let count = 0;
  for (const tag of html.matchAll(/<[a-z][^>]*\sdata-l10n-id="([^"]*)"[^>]*>/g)) {
    const attrs = /\sdata-l10n-attrs="([^"]*)"/.exec(tag[0]);
    need(tag[1], page, attrs ? attrs[1].split(",").map((name) => name.trim()) : []);
    count += 1;
  }
  if (count < 15) fail(`${page}: only ${count} elements with a data-l10n-id`);
}

/** The text of t(...)'s first argument at each call in `source`, strings and brackets kept. */
function firstArguments(source) {
  const found = [];
  for (const call of source.matchAll(/\bt\(/g)) {
    let depth = 0;
    let quote = null;
    let i = call.index + 2;
    for (; i < source.length; i++) {
      const c = source[i];
      if (quote) {
        if (c === "\\") i += 1;
        else if (c === quote) quote = null;
      } else if (c === '"' || c === "'" || c === "`") quote = c;
      else if ("([{".includes(c)) depth += 1;
      else if (")]}".includes(c)) {
        if (depth === 0) break;
        depth -= 1;
      } else if (c === "," && depth === 0) break;
    }
    found.push(source.slice(call.index + 2, i));
  }
  return found;
}

const sources = (await readdir(join(web, "src"))).filter((name) => name.endsWith(".ts"));
let calls = 0;
for (const name of sources) {
  const source = await readFile(join(web, "src", name), "utf8");
  for (const argument of firstArguments(source)) {
    calls += 1;
    const ids = [...argument.matchAll(/"([^"]*)"/g)].map((m) => m[1]);
    for (const id of ids) need(id, `src/${name}`);
  }
}
if (calls < 100) fail(`only ${calls} calls of t() found in src/`);

// What the C++ lab says (said("id", {arg("name", ...), ...}) in src/, text/said.hpp): each id is
// in English's, with the variables the call gives, and plain (text and { $name } only), as the
// lab's own reader of en.ftl (text/message_catalogue.hpp) reads it.
async function sourcesUnder(folder) {
  const found = [];
  for (const entry of await readdir(folder, { withFileTypes: true })) {
    const path = join(folder, entry.name);
    if (entry.isDirectory()) found.push(...(await sourcesUnder(path)));
    else if (/\.(cpp|hpp)$/.test(entry.name)) found.push(path);
  }
  return found;
}

/** The end of the bracketed text that opens at `open` (its closing bracket's index). */
function closing(source, open) {
  let depth = 0;
  let quote = false;
  for (let i = open; i < source.length; i++) {
    const c = source[i];
    if (quote) {
      if (c === "\\") i += 1;
      else if (c === '"') quote = false;
    } else if (c === '"') quote = true;
    else if ("({[".includes(c)) depth += 1;
    else if (")}]".includes(c) && --depth === 0) return i;
  }
  return source.length;
}

/** Each said("id", {...}) call's ids (two for said(c ? "a" : "b", ...)) and the names of its own
 * args (not those of a said inside). */
function saidCalls(source) {
  const calls = [];
  const id = '"([a-z][a-z0-9-]*)"';
  const callPattern = new RegExp(
    `\\bsaid\\(\\s*(?:${id}|[^";{}]*?\\?\\s*${id}\\s*:\\s*${id})`,
    "g",
  );
  for (const call of source.matchAll(callPattern)) {
    const names = new Set();
    const end = closing(source, call.index + "said".length);
    const list = source.indexOf("{", call.index);
    if (list !== -1 && list < end) {
      const listEnd = closing(source, list);
      let depth = 0;
      for (let i = list + 1; i < listEnd; i++) {
        const c = source[i];
        if (c === '"') i = source.indexOf('"', i + 1);
        else if ("({[".includes(c)) depth += 1;
        else if (")}]".includes(c)) depth -= 1;
        else if (depth === 0 && source.startsWith('arg("', i)) {
          names.add(source.slice(i + 5, source.indexOf('"', i + 5)));
        }
      }
    }
    calls.push({ ids: [call[1], call[2], call[3]].filter(Boolean), names });
  }
  return calls;
}

const plain = (pattern) =>
  typeof pattern === "string" ||
  pattern.every((e) => typeof e === "string" || e.type === "var" || e.type === "str");
const englishBundle = new FluentBundle("en", { useIsolating: false });
englishBundle.addResource(new FluentResource(catalogues.en ?? ""));
const labSaid = new Set();
let saidCount = 0;
for (const path of await sourcesUnder(join(repository, "src"))) {
  const source = await readFile(path, "utf8");
  const where = path.slice(repository.length + 1);
  for (const { ids, names } of saidCalls(source))
    for (const id of ids) {
      saidCount += 1;
      labSaid.add(id);
      need(id, where);
      const message = english.get(id);
      if (!message) continue;
      if (!sameSet(message.value ?? new Set(), names)) {
        fail(`${where}: said("${id}") gives ${listed(names)}, en.ftl's ${listed(message.value)}`);
      }
      const pattern = englishBundle.getMessage(id)?.value;
      if (pattern && !plain(pattern)) fail(`en.ftl: ${id}, which the lab reads, is not plain text`);
    }
  // The quantities a range bounds and the paper's values, which check-implausible quotes.
  if (where === "src/core/plausible_range.hpp") {
    for (const m of source.matchAll(/"((?:quantity|paper)-[a-z0-9-]+)"/g)) {
      labSaid.add(m[1]);
      need(m[1], where);
    }
  }
}
if (saidCount < 15) fail(`only ${saidCount} calls of said() found in src/`);

// A message for each regime the lab names.
const regimeSource = await readFile(join(repository, "src/core/regime.cpp"), "utf8");
const namer = /regime_name\(Regime regime\) \{([\s\S]*?)\n\}/.exec(regimeSource)?.[1] ?? "";
const regimes = [...namer.matchAll(/return "([^"]+)";/g)]
  .map((m) => m[1])
  .filter((r) => r !== "unknown");
const { REGIME_MESSAGES, REGIME_HELP, regimeWords } = await importTs(
  join(web, "src/regime_words.ts"),
);
if (regimes.length < 10) fail(`only ${regimes.length} regimes read from src/core/regime.cpp`);
for (const regime of regimes) {
  const id = REGIME_MESSAGES[regime];
  if (id === undefined) fail(`the page has no message for the regime "${regime}"`);
  else need(id, "src/regime_words.ts");
  const help = REGIME_HELP[regime];
  if (help === undefined) fail(`the page does not say what the regime "${regime}" means`);
  else need(help, "src/regime_words.ts");
}
// English's words for a regime are the lab's; a regime no catalogue has shows as the lab wrote it.
for (const regime of regimes) {
  if (regimeWords(regime) !== regime) fail(`"${regime}" in English: "${regimeWords(regime)}"`);
}
if (regimeWords("wobbles") !== "wobbles") fail(`an unknown regime: "${regimeWords("wobbles")}"`);
// A live line (src/lab/run/regime_monitor.cpp's regime_so_far) reads in English as the lab wrote it.
for (const line of [
  "clipped since t = 0.016 s",
  "oscillates; 1 jump off a roller, up to 0.3 mm",
  "stick-slip since t = 1.250 s; 12 jumps off a roller, up to 1.5 mm",
]) {
  if (regimeWords(line) !== line) fail(`"${line}" in English: "${regimeWords(line)}"`);
}

// A message for each scene the lab ships (scenes/*.yaml).
const { SCENE_MESSAGES } = await importTs(join(web, "src/scene_words.ts"));
const shipped = (await readdir(join(repository, "scenes")))
  .filter((name) => name.endsWith(".yaml"))
  .map((name) => name.slice(0, -".yaml".length));
for (const scene of shipped) {
  const id = SCENE_MESSAGES[scene];
  if (id === undefined) fail(`the page has no words for the shipped scene "${scene}"`);
  else need(id, "src/scene_words.ts");
}

// Words for each material of the paper's Table I, English's the table's own name.
const table = await readFile(join(repository, "assets/paper/table1.yaml"), "utf8");
const materials = [...table.matchAll(/^ {2}- key: (\S+)\n {4}name: (.+)$/gm)];
if (materials.length < 10) fail(`only ${materials.length} materials read from table1.yaml`);
for (const [, key, name] of materials) {
  need(`material-${key}`, "src/material_words.ts");
  const words = englishBundle.getMessage(`material-${key}`)?.value;
  if (words && englishBundle.formatPattern(words) !== name) {
    fail(`en.ftl: material-${key} is not Table I's name "${name}"`);
  }
}

// Every message is asked for by the page, or is the C++ lab's (its report's).
for (const id of english.keys()) {
  if (!asked.has(id) && !id.startsWith("report-"))
    fail(`en.ftl: ${id} is used nowhere in the page or the lab`);
}

const count = english.size;
console.log(
  `catalogues: ${tags.join(", ")}, ${count} messages each; ${asked.size} asked for by the page` +
    (failed ? `; ${failed} problems` : ""),
);
process.exit(failed === 0 ? 0 : 1);
