// The Python module's spelling of a request's fields (io/field_ref.hpp): a keyword argument,
// "geometry" is "geometry", with a value "geometry='pair'"; an override "set={'friction.mu_k':
// '0.3'}". Every text of the lab's the module shows (errors, str(summary)) goes through spelled().
#pragma once

#include <string>
#include <string_view>

#include "io/field_ref.hpp"

namespace fl::python {

std::string argument_of(const FieldMention& field);

std::string spelled(std::string_view text);

}  // namespace fl::python
