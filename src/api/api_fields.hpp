// The one declaration of the web API's bodies (docs/web-api.md): every object the server sends,
// each key's type, unit and meaning. The page's TypeScript types (web/src/api_types.ts) and
// docs/web-api.md's key tables are generated from it (tools/generate-fields); a test holds what
// serve's C++ writes to it (api/api_contract.hpp), and the page's mock server reads it, with
// replies the lab recorded (serve/api_recording.hpp), and is held to it too. A run's summary (the
// `done` event, summary.json) is the object RunSummaryJson, declared once with the run's fields
// (lab/run/summary_fields.hpp).
//
// A type is written as TypeScript writes it, in a small subset the checkers read: `number`,
// `string`, `boolean`, a declared object's or alias's name, `T[]`, a tuple `[T, U]`, and a union
// of quoted texts or of numbers (`"inward" | "outward"`, `1 | 0.25`). `| null` is not written: a
// key's `nullable` says it. `RunSummaryJson` is the run's summary, `object` any object.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace fl::api {

struct ApiKey {
  const char* name = "";
  const char* type = "number";
  const char* unit = "";      // SI ("m", "s", "N", "rad", "K"), "" for none or in the name (_mm)
  const char* meaning = "";   // one sentence for the docs and the page's types
  bool nullable = false;      // null where the lab did not measure it or the rig has none
  bool optional = false;      // the key may be absent (a summary key written only when measured)
  const char* csv = nullptr;  // its column in the CSV form of the object (class.csv); nullptr: none
  double csv_scale = 1.0;     // the column's value is the key's times this (metres to _mm: 1e3)
};

struct ApiObject {
  const char* name = "";     // the page's type name
  const char* meaning = "";  // where the server sends it
  std::vector<ApiKey> keys = {};
  // Its TypeScript type is written elsewhere: RunSummaryJson, from the run's fields, in
  // web/src/run_summary.ts.
  bool typed_elsewhere = false;
};

// A named type that is not an object: a union of texts or numbers, or a tuple.
struct ApiAlias {
  const char* name = "";
  const char* type = "";
  const char* meaning = "";
};

struct ApiDeclaration {
  std::vector<ApiAlias> aliases;
  std::vector<ApiObject> objects;  // the last, RunSummaryJson, from the run's fields
};

const ApiDeclaration& api_declaration();

// The declaration as JSON, for the checkers outside C++ (the mock server's test): {"aliases":
// {NAME: TYPE}, "objects": {NAME: [{"name", "type", "nullable", "optional", "csv", "csv_scale"},
// ...]}}, keys in their declared order.
nlohmann::json api_declaration_json();

}  // namespace fl::api
