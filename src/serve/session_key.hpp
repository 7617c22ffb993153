// A session's key (docs/web-api.md): the secret only the page that opened a session holds, which
// each of its controls carries. The session's id is public (the class's table lists it); its key
// is never listed, and without it nobody plays, resets, streams, downloads or ends the session.
#pragma once

#include <string>
#include <string_view>

namespace fl::serve {

// 128 bits from the kernel's random source (getrandom), as 32 hexadecimal digits. Throws
// std::runtime_error when the kernel gives none.
std::string new_session_key();

// Whether `given` is `key`, in a time that does not tell how much of it was right.
bool same_key(std::string_view key, std::string_view given);

}  // namespace fl::serve
