// A request's field named in a message, for each front end to spell its own way. The lab writes
// field_ref("geometry", "pair") where a message tells a user what to give; the command prints it
// as "--geometry pair", the Python module as "geometry='pair'", the browser page as the label of
// the control. A message from the lab never names a command-line flag (docs/architecture.md).
//
// The mention travels inside the text between two marks no message uses otherwise, "⟦" and "⟧":
// "⟦geometry=pair⟧". spell_fields replaces every mention; a front end calls it on each text of
// the lab's it shows (errors, notes, the summary's lines).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace fl {

inline constexpr std::string_view kFieldOpen = "\u27e6";   // ⟦
inline constexpr std::string_view kFieldClose = "\u27e7";  // ⟧

// A field of a request: its path ("geometry", "video.size", "set") and, when the message gives
// one, the value a user would write ("pair", "friction.mu_k=0.3").
struct FieldMention {
  std::string path;
  std::optional<std::string> value;
};

// "⟦path⟧" and "⟦path=value⟧".
std::string field_ref(std::string_view path);
std::string field_ref(std::string_view path, std::string_view value);

// How a front end writes a field: "--geometry pair", "geometry='pair'".
using FieldSpelling = std::function<std::string(const FieldMention&)>;

// The text with every mention spelled; a text without one is returned as it is.
std::string spell_fields(std::string_view text, const FieldSpelling& spelling);

// The text as files hold it, the same whichever front end asked: each field by its own path, its
// value after a space ("set rollers.spacing=3mm", "geometry pair").
std::string plain_fields(std::string_view text);

// Whether the text still holds a mention (a front end's tests check none escapes).
bool mentions_field(std::string_view text);

// The mention "⟦path=value⟧" read back (the whole text must be one mention); nullopt otherwise.
std::optional<FieldMention> parse_field_ref(std::string_view text);

}  // namespace fl
