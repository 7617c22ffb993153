#include "cli/monte_carlo_report.hpp"

#include <fmt/format.h>

namespace fl::cli {

void print_mu_k_monte_carlo(const AnalyticReport& r, int width, const std::string& png) {
  const MuKMonteCarlo& mc = *r.monte_carlo;
  if (!mc.mu_k) {
    fmt::print("  {:<{}}no draw of {} fell inside the formula's domain\n", "mu_k, Monte Carlo",
               width, mc.draws);
    return;
  }
  const SampleSummary& m = *mc.mu_k;
  fmt::print("  {:<{}}{:.4f} +- {} (mean and sd of {} draws, seed {}); 95 % in [{:.4f}, {:.4f}]\n",
             "mu_k, Monte Carlo", width, m.mean,
             m.sd ? fmt::format("{:.4f}", *m.sd) : std::string("-"), mc.accepted, mc.seed,
             m.quantile_025, m.quantile_975);
  fmt::print("  {:<{}}T, l{} drawn from Gaussians, through the {} formula{}{}{}\n", "", width,
             r.set_up.h_c_err > 0.0 ? " and h_c" : "",
             r.set_up.h_c > 0.0 ? fmt::format("thick (h_c = {:.2f} mm)", r.set_up.h_c * 1e3)
                                : std::string("paper's"),
             r.set_up.h_c_err > 0.0 ? " (the rules above leave dh_c out)" : "",
             mc.skipped > 0 ? fmt::format("; {} draws outside its domain skipped", mc.skipped)
                            : std::string(),
             png.empty() ? "" : "; histogram " + png);
}

}  // namespace fl::cli
