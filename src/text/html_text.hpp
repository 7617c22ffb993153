// Text made safe to place in HTML (an element's content or a quoted attribute's value).
#pragma once

#include <string>
#include <string_view>

namespace fl {

// `&`, `<`, `>`, `"` and `'` as character references; everything else as it is.
std::string html_text(std::string_view text);

}  // namespace fl
