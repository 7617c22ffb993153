// Text made safe to place in HTML: an element's content, or an attribute's value in double quotes
// (the only quotes the lab writes attributes in).
#pragma once

#include <string>
#include <string_view>

namespace fl {

// `&`, `<`, `>` and `"` as character references; everything else as it is.
std::string html_text(std::string_view text);

}  // namespace fl
