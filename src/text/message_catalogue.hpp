// A language's messages, read from a Fluent file (projectfluent.org), the one file a translator
// edits for the page and the lab's report alike (assets/locales/LANG.ftl). This reads the part of
// Fluent the lab's own messages use: `id = text`, continued on indented lines, with `{ $name }`
// placeables and `{ "literal" }`; comments and blank lines. A message using more of Fluent (a
// selector, a term, attributes) is the page's (read by @fluent/bundle there) and skipped here.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace fl {

class MessageCatalogue {
 public:
  MessageCatalogue() = default;
  // Never throws: what it cannot read is skipped (the page's catalogue test holds the files to
  // Fluent's own parser).
  static MessageCatalogue parse(std::string_view ftl);

  // The message with its placeables filled from `args` (a placeable whose name `args` lacks is
  // left as `{$name}`); nullopt when the catalogue has no such message.
  std::optional<std::string> format(std::string_view id,
                                    const std::map<std::string, std::string>& args = {}) const;
  bool has(std::string_view id) const { return messages_.contains(std::string(id)); }

 private:
  std::map<std::string, std::string> messages_;  // id -> pattern, as written
};

}  // namespace fl
