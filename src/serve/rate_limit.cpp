#include "serve/rate_limit.hpp"

#include <algorithm>

namespace fl::serve {
namespace {

// Buckets of clients gone quiet are forgotten once there are this many (a full bucket and a
// forgotten one are the same).
constexpr std::size_t kMostRemembered = 4096;

}  // namespace

RateLimit::RateLimit(double per_second, double burst) : per_second_(per_second), burst_(burst) {}

bool RateLimit::allow(const std::string& client, Clock::time_point now, double* wait_s) {
  const std::lock_guard lock(mutex_);
  if (buckets_.size() >= kMostRemembered) {
    std::erase_if(buckets_, [&](const auto& entry) {
      const double idle = std::chrono::duration<double>(now - entry.second.at).count();
      return entry.second.tokens + idle * per_second_ >= burst_;
    });
  }
  auto [it, added] = buckets_.try_emplace(client, Bucket{burst_, now});
  Bucket& b = it->second;
  if (!added) {
    const double elapsed = std::chrono::duration<double>(now - b.at).count();
    b.tokens = std::min(burst_, b.tokens + std::max(0.0, elapsed) * per_second_);
    b.at = now;
  }
  if (b.tokens >= 1.0) {
    b.tokens -= 1.0;
    return true;
  }
  if (wait_s != nullptr) *wait_s = (1.0 - b.tokens) / per_second_;
  return false;
}

}  // namespace fl::serve
