// docs/friction-laws.md's question "can a law in this family stop the oscillation at 200 rpm and
// keep it at 1600 rpm?", answered over the whole grid it names: mu_s / mu_k 1.1 to 1.5, v_s 1 mm/s
// to 0.1 m/s, beta -0.5 to +0.5 s/m, on the paper's rig (h_c 2.5 mm, 30 mm start, 20 s) at 200
// and 1600 rpm. Every prediction (core/friction_regime.hpp) matches the reference model's run;
// where the slow oscillation decays the fast one decays too; and the laws that keep a steady
// oscillation at 1600 rpm give stick-slip at 200 rpm.
#include <cstdio>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "core/friction_regime.hpp"
#include "friction_regime_rig.hpp"
#include "support/reference_oscillator.hpp"

namespace fl {
namespace {

TEST(FrictionRegimeGrid, NoLawStopsTheSlowOscillationAndKeepsTheFastOne) {
  const PlateOnRollers plate{test::kL, 0.0025, test::kG};
  int compared = 0, refused = 0, slow_decays = 0, fast_oscillates = 0;
  for (const double ratio : {1.1, 1.2, 1.3, 1.4, 1.5})
    for (const double v_s : {0.001, 0.003, 0.01, 0.03, 0.1})
      for (const double beta : {-0.5, -0.2, -0.1, -0.05, -0.02, 0.0, 0.02, 0.05, 0.1, 0.2, 0.5}) {
        const FrictionLaw law = test::stribeck(0.29 * ratio, v_s, beta);
        std::optional<Regime> slow, fast;  // what the reference model did at 200 and 1600 rpm
        for (const double v_r : {test::kSlow, test::kFast}) {
          if (law.kinetic(2.0 * v_r) <= 0.0) {  // no meaning at this speed
            ++refused;
            continue;
          }
          const FrictionRegimePrediction p = predict_friction_regime(
              law, plate, v_r, test::kStart, test::kHorizon, test::kTolerance);
          const Regime seen = test::reference_regime(law, plate.h_c, v_r);
          EXPECT_EQ(regime_name(p.regime), std::string(regime_name(seen)))
              << test::describe_law(law) << " v_r " << v_r;
          (v_r == test::kSlow ? slow : fast) = seen;
          ++compared;
        }
        if (!slow || !fast) continue;
        slow_decays += *slow == Regime::kDecays;
        fast_oscillates += *fast == Regime::kOscillates;
        if (*slow == Regime::kDecays) {
          EXPECT_EQ(*fast, Regime::kDecays) << test::describe_law(law);
        }
        if (*fast == Regime::kOscillates) {
          EXPECT_EQ(*slow, Regime::kStickSlip) << test::describe_law(law);
        }
      }
  std::printf("%d runs compared, %d refused (the law not positive up to 2 v_r)\n", compared,
              refused);
  // Both implications were put to the test.
  EXPECT_GT(slow_decays, 0);
  EXPECT_GT(fast_oscillates, 0);
  std::printf("%d laws decay at 200 rpm, %d keep a steady oscillation at 1600 rpm\n", slow_decays,
              fast_oscillates);
}

}  // namespace
}  // namespace fl
