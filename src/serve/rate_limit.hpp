// Each client's share of the server: a token bucket per address (docs/web-api.md, "Limits").
// A client may make `per_second` requests a second on average, and `burst` at once; beyond, it
// is told to wait, and the other clients are not slowed. Safe to call from several threads.
#pragma once

#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>
#include <unordered_map>

namespace fl::serve {

class RateLimit {
 public:
  using Clock = std::chrono::steady_clock;

  RateLimit(double per_second, double burst);

  // Whether `client` may make a request at `now` (taking one token when it may); `wait_s`, when
  // it may not: how long until it may.
  bool allow(const std::string& client, Clock::time_point now, double* wait_s = nullptr);

  double per_second() const { return per_second_; }

 private:
  struct Bucket {
    double tokens = 0.0;
    Clock::time_point at;
  };
  double per_second_;
  double burst_;
  std::mutex mutex_;
  std::unordered_map<std::string, Bucket> buckets_;
};

}  // namespace fl::serve
