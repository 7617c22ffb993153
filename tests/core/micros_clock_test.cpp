// The rig's 32-bit microsecond clock unwrapped: readings after a wrap continue the axis, an
// instant reported before the wrap lands before it, and a reading that merely went back is not
// taken for a wrap.
#include "core/micros_clock.hpp"

#include <cstdint>

#include <gtest/gtest.h>

namespace fl {
namespace {

constexpr double kWrap = 4294967296.0;  // 2^32 us

TEST(MicrosClock, ReadingsAfterAWrapContinueTheAxis) {
  MicrosClock clock;
  EXPECT_EQ(clock.advance(4294966000.0), 4294966000.0);
  EXPECT_EQ(clock.advance(4294967000.0), 4294967000.0);
  // 1296 us after 4294967000 the clock reads 1000.
  EXPECT_EQ(clock.advance(1000.0), kWrap + 1000.0);
  EXPECT_EQ(clock.wraps(), 1);
  EXPECT_EQ(clock.advance(2000.0), kWrap + 2000.0);
  EXPECT_EQ(clock.wraps(), 1);
}

TEST(MicrosClock, InstantsBeforeTheLatestReadingLandOnTheirSideOfTheWrap) {
  MicrosClock clock;
  clock.advance(4294967000.0);
  // Before any wrap a past instant is its reading.
  EXPECT_EQ(clock.unwrap_past(4294966500u), 4294966500.0);
  clock.advance(500.0);
  // An instant between the two samples, before the wrap ...
  EXPECT_EQ(clock.unwrap_past(4294967100u), 4294967100.0);
  // ... and one after it.
  EXPECT_EQ(clock.unwrap_past(200u), kWrap + 200.0);
  EXPECT_EQ(clock.unwrap_past(500u), kWrap + 500.0);
}

TEST(MicrosClock, ManyWrapsAreCounted) {
  MicrosClock clock;
  double expected = 0.0;
  std::uint32_t reading = 0;
  // 1 s steps over 5 wraps (about 358 minutes).
  for (int i = 0; i < 5 * 4295 + 10; ++i) {
    EXPECT_EQ(clock.advance(static_cast<double>(reading)), expected) << i;
    reading += 1000000u;  // wraps as the firmware's clock does
    expected += 1e6;
  }
  EXPECT_EQ(clock.wraps(), 5);
}

TEST(MicrosClock, AReadingThatWentBackALittleIsNotAWrap) {
  // A log whose times go back (a bad log) is the caller's to refuse, not a wrap.
  MicrosClock clock;
  clock.advance(5000.0);
  EXPECT_EQ(clock.advance(4000.0), 4000.0);
  EXPECT_EQ(clock.wraps(), 0);
  // Nor is a drop from a reading that was never a 32-bit clock's (above 2^32).
  MicrosClock wide;
  wide.advance(6e9);
  EXPECT_EQ(wide.advance(1e9), 1e9);
  EXPECT_EQ(wide.wraps(), 0);
}

}  // namespace
}  // namespace fl
