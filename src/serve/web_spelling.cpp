#include "serve/web_spelling.hpp"

#include "io/field_ref.hpp"

namespace fl::serve {

std::string web_spelled(std::string_view text) {
  return spell_fields(text, [](const FieldMention& m) {
    if (m.path == "set") return m.value ? *m.value : std::string("set");
    return m.value ? "\"" + m.path + "\" " + *m.value : "\"" + m.path + "\"";
  });
}

}  // namespace fl::serve
