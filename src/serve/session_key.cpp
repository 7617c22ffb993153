#include "serve/session_key.hpp"

#include <sys/random.h>

#include <array>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include <fmt/format.h>

namespace fl::serve {

std::string new_session_key() {
  std::array<std::uint8_t, 16> bits{};
  for (std::size_t got = 0; got < bits.size();) {
    const ssize_t n = ::getrandom(bits.data() + got, bits.size() - got, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("the kernel gave no random bytes for a session's key");
    got += static_cast<std::size_t>(n);
  }
  std::string key;
  for (const std::uint8_t byte : bits) key += fmt::format("{:02x}", byte);
  return key;
}

bool same_key(std::string_view key, std::string_view given) {
  // Every byte of the key is looked at, whatever the given one holds.
  unsigned char differs = key.size() == given.size() ? 0 : 1;
  for (std::size_t i = 0; i < key.size(); ++i)
    differs |= static_cast<unsigned char>(key[i] ^ (i < given.size() ? given[i] : ~key[i]));
  return differs == 0;
}

}  // namespace fl::serve
