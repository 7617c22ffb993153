// What to tell someone who named a material that is not in the paper's Table I: the materials
// it has, and the closest to the name given when it looks like a typo.
#pragma once

#include <string>
#include <string_view>

#include "core/paper_table.hpp"

namespace fl {

// "the paper's materials are lego, paper, ..., flexible-foam; did you mean 'plexiglas'?" (the
// question only when one key is close to `name`). Callers say first what was wrong.
std::string unknown_material_note(const PaperTable& table, std::string_view name);

// The whole message: "unknown material \"brasss\"; the paper's materials are ...; did you mean
// 'brass'?".
std::string unknown_material_message(const PaperTable& table, std::string_view name);

}  // namespace fl
