// The browser page's spelling of a request's fields in the lab's messages (io/field_ref.hpp): a
// `set` entry as the page's link writes it ("rollers.spacing=70mm"), any other field by its name
// in quotes ("scene"). The page shows a message beside the control its field names.
#pragma once

#include <string>
#include <string_view>

namespace fl::serve {

std::string web_spelled(std::string_view text);

}  // namespace fl::serve
