// Base64 (RFC 4648, the standard alphabet, padded), as a browser's btoa() writes it: how a page
// sends a file's bytes inside a JSON request.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace fl {

// The bytes `text` encodes; nullopt where it is not base64 (a character outside the alphabet, a
// length that is not a multiple of 4, padding anywhere but at its end).
std::optional<std::string> decode_base64(std::string_view text);

}  // namespace fl
