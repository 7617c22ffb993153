#include "lab/run/warming_report.hpp"

#include "core/analytic_model.hpp"

namespace fl {
namespace {

// The accepted periods among `periods` that pass `keep`, as a window (null if none).
template <typename Keep>
std::optional<WarmingWindow> window(const std::vector<EstimatedPeriod>& periods, double spacing,
                                    double gravity, Keep keep) {
  WarmingWindow w;
  double sum = 0.0;
  for (const EstimatedPeriod& p : periods) {
    if (p.status != fl_estimator::kAccepted || !keep(p, w.periods)) continue;
    sum += p.period;
    ++w.periods;
  }
  if (w.periods == 0) return std::nullopt;
  w.period = sum / w.periods;
  w.mu_k = mu_k_from_period_thin(w.period, spacing, gravity);
  return w;
}

}  // namespace

WarmingReport warming_report(const RollerWarming& warming,
                             const std::vector<EstimatedPeriod>& periods, double spacing,
                             double h_c, double gravity, double duration) {
  WarmingReport r;
  r.start_temperature = warming.start_temperature();
  r.room_temperature = warming.room_temperature();
  r.time_constant = warming.time_constant();
  r.hold = warming.hold();
  r.mu_k_start = warming.mu_k_start();
  r.mu_k_room = warming.mu_k_room();
  r.end_temperature = warming.temperature(duration);
  r.mu_k_end = warming.mu_k(duration);
  r.mu_k_cold_paper_formula = mu_k_from_period_thin(
      period_thick(spacing, warming.mu_k_start(), h_c, gravity), spacing, gravity);
  r.first_10_periods = window(periods, spacing, gravity,
                              [](const EstimatedPeriod&, int taken) { return taken < 10; });
  r.first_30_s = window(periods, spacing, gravity,
                        [](const EstimatedPeriod& p, int) { return p.end <= 30.0; });
  r.whole_run = window(periods, spacing, gravity, [](const EstimatedPeriod&, int) { return true; });
  return r;
}

}  // namespace fl
