// The analytic model for one set-up, as every front end asks for it (`frictionlab analytic`,
// frictionlab.analytic): the rig, what mu_k comes from (a given mu_k, a measured period, or a
// material of the paper's Table I), the friction law, and the Monte Carlo of mu_k. The defaults
// are the paper's rig, here once. analyze reads and checks every field (problems by field), then
// reports (lab/analytic/analytic_report.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lab/analytic/analytic_report.hpp"
#include "lab/request/field_checks.hpp"
#include "lab/request/outcome.hpp"

namespace fl {

struct AnalyticRequest {
  QuantityInput spacing = std::string("89 mm");          // "spacing": l, the paper's rig
  QuantityInput spacing_err = std::string("2 mm");       // "spacing_err": dl, the paper's
  std::optional<QuantityInput> mu_k;                     // "mu_k"; or
  std::optional<QuantityInput> period;                   // "period", a measured T; or
  std::optional<std::string> material;                   // "material", a key of Table I
  std::optional<QuantityInput> period_err;               // "period_err": dT, with period (0 s)
  std::optional<QuantityInput> temperature;              // "temperature": with material (300 K)
  QuantityInput h_c = std::string("0 mm");               // "h_c": the thin plate
  QuantityInput h_c_err = std::string("0 mm");           // "h_c_err": drawn by the Monte Carlo
  QuantityInput gravity = std::string("9.81 m/s^2");     // "gravity"
  QuantityInput roller_radius = std::string("10 mm");    // "roller_radius": 20 mm PVC tube
  QuantityInput roller_speed = std::string("1600 rpm");  // "roller_speed": 200 rpm x 8
  QuantityInput amplitude = std::string("20 mm");        // "amplitude", for the slip margin
  std::string law = "coulomb";                           // "law": coulomb or stribeck
  std::optional<QuantityInput> mu_s;                     // "mu_s": the static limit (mu_k)
  std::optional<QuantityInput> v_s;                      // "v_s": stribeck
  std::optional<QuantityInput> beta;                     // "beta": stribeck
  std::optional<std::int64_t> mc;                        // "monte_carlo.draws"
  std::uint64_t seed = 1;                                // "seed": the Monte Carlo's
  std::string plot;                                      // "plot": the Monte Carlo's histogram
  std::string assets;                                    // "assets": where Table I is
};

struct AnalyticResult {
  AnalyticReport report;
  std::string plot;                   // the PNG drawn, if any
  std::string plot_failure;           // why it could not be drawn
  std::vector<std::string> warnings;  // field_ref mentions, for the front end to spell

  // `frictionlab analytic --json`'s object (docs/cli.md); with a Monte Carlo, its plot (null
  // when none was drawn).
  nlohmann::json json() const;
  Outcome outcome() const;
};

AnalyticResult analyze(const AnalyticRequest& request);

}  // namespace fl
