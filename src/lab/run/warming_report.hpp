// What rollers warming over a run do to the mu_k a student computes (core/roller_warming.hpp): the
// rig's estimator's accepted periods, averaged over the first 10 of them, over those ended by
// 30 s, and over the whole run, each turned into mu_k by the paper's formula
// mu_k = 2 pi^2 l / (g T^2), beside the start's mu_k (77 K after liquid nitrogen) and the end's,
// and beside what the same formula gives on rollers that stay cold (the thick plate's period at the
// start's mu_k: the paper's formula reads it a little high, by 1 / (1 - 2 mu_k h_c / l)).
#pragma once

#include <optional>
#include <vector>

#include "core/roller_warming.hpp"
#include "estimator/host_estimator.hpp"

namespace fl {

// The mu_k of a window of accepted periods: how many, their mean period, mu_k from it.
struct WarmingWindow {
  int periods = 0;
  double period = 0.0;  // s
  double mu_k = 0.0;
};

struct WarmingReport {
  double start_temperature = 0.0;  // K
  double room_temperature = 0.0;   // K
  double time_constant = 0.0;      // s
  double hold = 0.0;               // s
  double mu_k_start = 0.0;         // at the start temperature
  double mu_k_room = 0.0;          // at the room's
  double end_temperature = 0.0;    // K, at the run's end
  double mu_k_end = 0.0;           // at the run's end
  // The paper's formula on the thick plate's period at mu_k_start: what a student gets from
  // rollers that stay at the start's temperature.
  double mu_k_cold_paper_formula = 0.0;
  // Null when the window holds no accepted period.
  std::optional<WarmingWindow> first_10_periods;
  std::optional<WarmingWindow> first_30_s;
  std::optional<WarmingWindow> whole_run;
};

// `periods`: the estimator's, on the run's time axis [s]; `spacing` l [m], the plate's h_c [m],
// `gravity` g [m/s^2], `duration` the run's [s].
WarmingReport warming_report(const RollerWarming& warming,
                             const std::vector<EstimatedPeriod>& periods, double spacing,
                             double h_c, double gravity, double duration);

}  // namespace fl
