// The English message catalogue (assets/locales/en.ftl) as the lab was built with it: the
// command line's and Python's words, read from no file at run time.
#pragma once

#include <string_view>

namespace fl {

std::string_view english_catalogue_text();

}  // namespace fl
