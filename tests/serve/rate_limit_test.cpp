// Each client's share (serve/rate_limit.hpp): a token bucket per address, checked on a clock the
// test sets: the burst, the rate after it, the wait it names, and clients that do not share.
#include "serve/rate_limit.hpp"

#include <gtest/gtest.h>

namespace fl::serve {
namespace {

using Clock = RateLimit::Clock;

TEST(RateLimit, ABurstThenTheRateAndTheWaitItNames) {
  RateLimit limit(10.0, 30.0);
  const Clock::time_point t0{};
  int allowed = 0;
  for (int i = 0; i < 100; ++i) allowed += limit.allow("a", t0) ? 1 : 0;
  EXPECT_EQ(allowed, 30);
  double wait_s = 0.0;
  EXPECT_FALSE(limit.allow("a", t0, &wait_s));
  EXPECT_DOUBLE_EQ(wait_s, 0.1);  // one request's worth at 10 a second
  // Over the next second: ten more, one every 0.1 s.
  allowed = 0;
  for (int ms = 1; ms <= 1000; ++ms)
    allowed += limit.allow("a", t0 + std::chrono::milliseconds(ms)) ? 1 : 0;
  EXPECT_EQ(allowed, 10);
}

TEST(RateLimit, OneClientsBurstLeavesTheOthersTheirShare) {
  RateLimit limit(1.0, 3.0);
  const Clock::time_point t0{};
  for (int i = 0; i < 10; ++i) limit.allow("10.0.0.1", t0);
  EXPECT_FALSE(limit.allow("10.0.0.1", t0));
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(limit.allow("10.0.0.2", t0)) << i;
  EXPECT_FALSE(limit.allow("10.0.0.2", t0));
}

TEST(RateLimit, AmongThousandsOfClientsABucketRefillsToItsBurstAndNoFurther) {
  RateLimit limit(1.0, 2.0);
  const Clock::time_point t0{};
  for (int i = 0; i < 10000; ++i) limit.allow("client " + std::to_string(i), t0);
  // An hour later every bucket has refilled: a client that had used its burst has it again.
  const Clock::time_point later = t0 + std::chrono::hours(1);
  EXPECT_TRUE(limit.allow("client 0", later));
  EXPECT_TRUE(limit.allow("client 0", later));
  EXPECT_FALSE(limit.allow("client 0", later));
}

}  // namespace
}  // namespace fl::serve
