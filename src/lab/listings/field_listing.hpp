// The declaration of a run's fields (lab/run/summary_fields.hpp) written out for the places that
// list them by hand otherwise: docs/cli.md's table of `run --json` keys, docs/sweep-format.md's
// table of a sweep's run columns, the Python stub's RunSummary attributes, the page's TypeScript
// type of a run's summary. tools/generate-fields writes them into those files between their
// markers; a test checks that the files hold what this gives.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace fl {

struct FieldListing {
  std::string name;  // the marker's name in a file: "run-json-keys", "sweep-run-columns", ...
  std::string text;  // what goes between the markers, lines ending in '\n'
};

// Every listing, in a fixed order.
std::vector<FieldListing> field_listings();

// `file_text` with every generated block whose name is a listing's replaced by that listing's
// text. A block is the lines between a line holding "generated: NAME" and the next line holding
// "end generated"; the marker lines stay. nullopt when a block names no listing or has no end.
std::optional<std::string> with_listings(const std::string& file_text,
                                         const std::vector<FieldListing>& listings,
                                         std::string* problem);

}  // namespace fl
