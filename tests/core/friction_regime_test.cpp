// The regime a friction law gives the paper's rig (core/friction_regime.hpp), against what the
// reference model (tests/support/reference_oscillator.hpp) does over the same 20 s: the rig's
// l = 89 mm, h_c = 2.5 and 3.6 mm, a 30 mm start, 200 and 1600 rpm on 10 mm rollers, mu_k = 0.29
// with mu_s / mu_k from 1 to 1.5, stribeck speeds from 1 mm/s to 0.1 m/s and linear slopes from
// -0.5 to +0.5 s/m (where the law stays positive up to 2 v_r).
#include "core/friction_regime.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"
#include "core/averaged_motion.hpp"
#include "friction_regime_rig.hpp"
#include "support/reference_oscillator.hpp"

namespace fl {
namespace {

using test::coulomb;
using test::describe_law;
using test::kFast;
using test::kG;
using test::kHorizon;
using test::kL;
using test::kSlow;
using test::kTolerance;
using test::reference_regime;
using test::stribeck;

TEST(FrictionRegime, PredictionsForThePapersRigMatchTheReferenceModel) {
  std::vector<FrictionLaw> laws;
  for (double ratio : {1.0, 1.1, 1.5}) laws.push_back(coulomb(0.29, 0.29 * ratio));
  for (double beta : {-0.5, -0.1, -0.01, 0.01, 0.1, 0.5})
    laws.push_back(stribeck(0.29, 0.01, beta));
  for (double ratio : {1.1, 1.5})
    for (double v_s : {0.001, 0.01, 0.1})
      for (double beta : {-0.5, -0.05, 0.0, 0.05, 0.5})
        laws.push_back(stribeck(0.29 * ratio, v_s, beta));
  // Either side of the boundary where the slip arc after a stick stops reaching the other
  // roller's speed (at 200 rpm: beta = 0.18 keeps sticking, 0.2 decays after one stick).
  laws.push_back(stribeck(0.435, 0.03, 0.18));
  laws.push_back(stribeck(0.435, 0.03, 0.2));
  int compared = 0;
  for (double h_c : {0.0025, 0.0036}) {
    for (double v_r : {kSlow, kFast}) {
      for (const FrictionLaw& law : laws) {
        const PlateOnRollers plate{kL, h_c, kG};
        // A law that is not positive up to 2 v_r has no meaning at this speed.
        if (law.kinetic(2.0 * v_r) <= 0.0) {
          EXPECT_THROW(predict_friction_regime(law, plate, v_r, 0.03, kHorizon), DomainError);
          continue;
        }
        const FrictionRegimePrediction p =
            predict_friction_regime(law, plate, v_r, test::kStart, kHorizon, kTolerance);
        EXPECT_EQ(regime_name(p.regime), std::string(regime_name(reference_regime(law, h_c, v_r))))
            << describe_law(law) << " h_c " << h_c << " v_r " << v_r;
        ++compared;
      }
    }
  }
  EXPECT_EQ(compared, 148);  // and 16 refused at 1600 rpm (negative at 2 v_r)
}

TEST(FrictionRegime, CoulombAt200RpmSticksAndCarriesItsCycle) {
  const PlateOnRollers plate{kL, 0.0025, kG};
  const FrictionRegimePrediction clipped =
      predict_friction_regime(coulomb(0.29, 0.29), plate, kSlow, 0.03);
  EXPECT_EQ(clipped.regime, Regime::kClipped);
  ASSERT_TRUE(clipped.cycle.has_value());
  // Written out, not read back from the prediction: the slipping plate's angular frequency,
  // Omega^2 = 2 mu_k g / (l - 2 mu_k h_c), and the clip at the amplitude whose largest speed is
  // the rollers' surface speed, A Omega = v_r.
  const double omega = std::sqrt(2.0 * 0.29 * kG / (kL - 2.0 * 0.29 * 0.0025));
  EXPECT_NEAR(clipped.cycle->amplitude, kSlow / omega, 1e-15);
  const FrictionRegimePrediction sticks =
      predict_friction_regime(coulomb(0.29, 0.435), plate, kSlow, 0.03);
  EXPECT_EQ(sticks.regime, Regime::kStickSlip);
  ASSERT_TRUE(sticks.stick_time.has_value());
  // From rest at x = A: x = A cos(Omega t), so the plate's speed A Omega sin(Omega t) first
  // reaches v_r at t = asin(v_r / (A Omega)) / Omega.
  EXPECT_NEAR(sticks.margin, kSlow / (0.03 * omega), 1e-13);
  EXPECT_NEAR(*sticks.stick_time, std::asin(kSlow / (0.03 * omega)) / omega, 1e-13);
  const FrictionRegimePrediction slips =
      predict_friction_regime(coulomb(0.29, 0.435), plate, kFast, 0.03);
  EXPECT_EQ(slips.regime, Regime::kOscillates);
  EXPECT_GT(slips.margin, 6.0);
  EXPECT_FALSE(slips.stick_time.has_value());
}

TEST(FrictionRegime, SettlesOnTheSlipCycleWhereTheAveragedRateVanishes) {
  const FrictionLaw law = stribeck(0.319, 0.1, 0.24);
  const PlateOnRollers plate{kL, 0.0025, kG};
  const double v_r = 0.0707;
  for (double start : {0.001, 0.007}) {
    const FrictionRegimePrediction p = predict_friction_regime(law, plate, v_r, start);
    EXPECT_EQ(p.regime, Regime::kOscillates) << start;
    ASSERT_TRUE(p.settled_amplitude.has_value());
    EXPECT_NEAR(averaged_growth_rate(law, plate, v_r, *p.settled_amplitude), 0.0, 1e-9);
    EXPECT_NEAR(*p.settled_amplitude, 0.003135, 1e-6);
    // Over a short horizon the approach itself shows.
    EXPECT_EQ(predict_friction_regime(law, plate, v_r, start, 5.0).regime,
              start < *p.settled_amplitude ? Regime::kGrows : Regime::kDecays);
  }
}

TEST(FrictionRegime, TipsAndNoRestoringForce) {
  const PlateOnRollers plate{kL, 0.0036, kG};
  // Starting beyond l/2 - mu h_c.
  const FrictionRegimePrediction beyond =
      predict_friction_regime(coulomb(0.29, 0.29), plate, kFast, 0.0440);
  EXPECT_EQ(beyond.regime, Regime::kTips);
  EXPECT_EQ(*beyond.tip_time, 0.0);
  // A falling linear law at 1600 rpm grows the amplitude to the tipping offset (v_r / Omega is
  // beyond it): ln((l/2 - mu h_c) / A) / gamma for a linear law.
  const FrictionRegimePrediction grows =
      predict_friction_regime(stribeck(0.29, 0.01, -0.01), plate, kFast, 0.03);
  EXPECT_EQ(grows.regime, Regime::kTips);
  ASSERT_TRUE(grows.tip_time.has_value());
  EXPECT_NEAR(*grows.tip_time, std::log(grows.tipping_offset / 0.03) / grows.motion.gamma, 1e-6);
  EXPECT_EQ(predict_friction_regime(coulomb(10.0, 10.0), PlateOnRollers{kL, 0.005, kG}, kSlow, 0.01)
                .regime,
            Regime::kNoRestoringForce);
}

TEST(FrictionRegime, RefusesMeaninglessInput) {
  const PlateOnRollers plate{kL, 0.0025, kG};
  const FrictionLaw law = coulomb(0.29, 0.4);
  EXPECT_THROW(predict_friction_regime(law, plate, kSlow, 0.0), DomainError);
  EXPECT_THROW(predict_friction_regime(law, plate, 0.0, 0.03), DomainError);
  EXPECT_THROW(predict_friction_regime(law, plate, kSlow, 0.03, 0.0), DomainError);
  EXPECT_THROW(predict_friction_regime(law, plate, kSlow, 0.03, 10.0, 0.0), DomainError);
  EXPECT_THROW(predict_friction_regime(law, plate, kSlow, 0.03, 10.0, 1.0), DomainError);
  EXPECT_THROW(predict_friction_regime(coulomb(0.29, 0.2), plate, kSlow, 0.03), DomainError);
  EXPECT_THROW(predict_friction_regime(stribeck(0.29, 0.01, -0.5), plate, kFast, 0.03),
               DomainError);
}

}  // namespace
}  // namespace fl
