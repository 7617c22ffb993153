// Rollers warming after liquid nitrogen: the temperature held, then Newton's law of cooling, and
// mu_k linear in it between its two measured ends.
#include "core/roller_warming.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/domain_check.hpp"

namespace fl {
namespace {

TEST(RollerWarming, HeldThenNewtonsLawOfCooling) {
  const RollerWarming w(77.0, 300.0, 50.0, 20.0, 0.20, 0.29);
  EXPECT_EQ(w.temperature(0.0), 77.0);
  EXPECT_EQ(w.temperature(20.0), 77.0);
  // One time constant after the hold, the gap to the room has fallen to 1/e.
  EXPECT_NEAR(300.0 - w.temperature(70.0), 223.0 / std::exp(1.0), 1e-12);
  // dT/dt = (T_room - T) / tau at any time after the hold.
  const double t = 95.0, h = 1e-4;
  const double rate = (w.temperature(t + h) - w.temperature(t - h)) / (2.0 * h);
  EXPECT_NEAR(rate, (300.0 - w.temperature(t)) / 50.0, 1e-8);
  EXPECT_NEAR(w.temperature(1e6), 300.0, 1e-9);
}

TEST(RollerWarming, MuKIsLinearInTheTemperatureBetweenTheEnds) {
  const RollerWarming w(77.0, 300.0, 50.0, 0.0, 0.20, 0.29);
  EXPECT_EQ(w.mu_k(0.0), 0.20);
  EXPECT_NEAR(w.mu_k_at_temperature(0.5 * (77.0 + 300.0)), 0.245, 1e-15);
  EXPECT_NEAR(w.mu_k_at_temperature(300.0), 0.29, 1e-15);
  // Held at the ends beyond them.
  EXPECT_EQ(w.mu_k_at_temperature(20.0), 0.20);
  EXPECT_NEAR(w.mu_k_at_temperature(400.0), 0.29, 1e-15);
  // After one time constant mu_k has covered 1 - 1/e of its way.
  EXPECT_NEAR((w.mu_k(50.0) - 0.20) / 0.09, 1.0 - 1.0 / std::exp(1.0), 1e-12);
}

TEST(RollerWarming, RefusesWhatIsNotAWarming) {
  EXPECT_THROW(RollerWarming(300.0, 300.0, 50.0, 0.0, 0.2, 0.29), DomainError);
  EXPECT_THROW(RollerWarming(77.0, 300.0, 0.0, 0.0, 0.2, 0.29), DomainError);
  EXPECT_THROW(RollerWarming(77.0, 300.0, 50.0, -1.0, 0.2, 0.29), DomainError);
  EXPECT_THROW(RollerWarming(77.0, 300.0, 50.0, 0.0, 0.0, 0.29), DomainError);
  EXPECT_THROW(RollerWarming(77.0, 300.0, std::nan(""), 0.0, 0.2, 0.29), DomainError);
}

}  // namespace
}  // namespace fl
