// Whether a JSON body is what the lab's declaration of its web API says an object of a type is
// (src/api/api_fields.hpp; the declaration as api_declaration_json() gives it, in the mock's
// recording): every declared key there (unless optional), none undeclared, each value of its type,
// null only where the key is nullable. The same rules as src/api/api_contract.cpp, which holds
// serve's own bodies to it.

function splitOutsideBrackets(text, separator) {
  const parts = [];
  let depth = 0;
  let part = "";
  for (const c of text) {
    if (c === "[") depth++;
    if (c === "]") depth--;
    if (c === separator && depth === 0) {
      parts.push(part.trim());
      part = "";
    } else part += c;
  }
  parts.push(part.trim());
  return parts;
}

const found = (value) => {
  const text = JSON.stringify(value);
  return text.length > 60 ? `${text.slice(0, 57)}...` : text;
};

/** Each place `value` departs from `type`, as "PATH: what was expected, what was found". */
export function contractProblems(declaration, value, type, path) {
  const problems = [];
  const check = (v, t, where) => {
    t = t.trim();
    const alternatives = splitOutsideBrackets(t, "|");
    if (alternatives.length > 1) {
      const ok = alternatives.some((a) =>
        a.startsWith('"') ? typeof v === "string" && JSON.stringify(v) === a : v === Number(a),
      );
      if (!ok) problems.push(`${where}: expected one of ${t}, found ${found(v)}`);
      return;
    }
    const plain = { number: "number", string: "string", boolean: "boolean" };
    if (t in plain) {
      if (typeof v !== plain[t]) problems.push(`${where}: expected a ${t}, found ${found(v)}`);
      return;
    }
    if (t === "object") {
      if (v === null || typeof v !== "object" || Array.isArray(v)) {
        problems.push(`${where}: expected a object, found ${found(v)}`);
      }
      return;
    }
    if (t.endsWith("[]")) {
      if (!Array.isArray(v)) {
        problems.push(`${where}: expected an array, found ${found(v)}`);
        return;
      }
      v.forEach((item, i) => check(item, t.slice(0, -2), `${where}[${i}]`));
      return;
    }
    if (t.startsWith("[")) {
      const items = splitOutsideBrackets(t.slice(1, -1), ",");
      if (!Array.isArray(v) || v.length !== items.length) {
        problems.push(`${where}: expected ${t}, found ${found(v)}`);
        return;
      }
      items.forEach((item, i) => check(v[i], item, `${where}[${i}]`));
      return;
    }
    if (t in declaration.aliases) return check(v, declaration.aliases[t], where);
    const keys = declaration.objects[t];
    if (!keys) {
      problems.push(`${where}: the type ${t} is not declared`);
      return;
    }
    if (v === null || typeof v !== "object" || Array.isArray(v)) {
      problems.push(`${where}: expected an object ${t}, found ${found(v)}`);
      return;
    }
    for (const k of keys) {
      const at = `${where}.${k.name}`;
      if (!(k.name in v)) {
        if (!k.optional) problems.push(`${at}: declared, but not there`);
      } else if (v[k.name] === null) {
        if (!k.nullable) problems.push(`${at}: null, but not declared nullable`);
      } else check(v[k.name], k.type, at);
    }
    for (const name of Object.keys(v)) {
      if (!keys.some((k) => k.name === name)) {
        problems.push(`${where}.${name}: not declared for ${t} (src/api/api_fields.cpp)`);
      }
    }
  };
  check(value, type, path);
  return problems;
}
