#include "core/sample_summary.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/domain_check.hpp"

namespace fl {

double quantile_of_sorted(std::span<const double> sorted, double p) {
  require_domain(!sorted.empty(), "a quantile of no samples");
  require_domain(p >= 0.0 && p <= 1.0, describe("a quantile's p must be in [0, 1], got ", p));
  const double at = p * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(at));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const double fraction = at - static_cast<double>(below);
  return sorted[below] + fraction * (sorted[above] - sorted[below]);
}

double median_of(std::vector<double> v) {
  require_domain(!v.empty(), "a median of no samples");
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

SampleSummary summarise_samples(std::span<const double> samples) {
  require_domain(!samples.empty(), "a summary of no samples");
  SampleSummary out;
  const double n = static_cast<double>(samples.size());
  double sum = 0.0;
  for (const double x : samples) sum += x;
  out.mean = sum / n;
  if (samples.size() >= 2) {
    // Two passes: the squares of deviations, not of values, so no cancellation.
    double squares = 0.0;
    for (const double x : samples) squares += (x - out.mean) * (x - out.mean);
    out.sd = std::sqrt(squares / (n - 1.0));
  }
  std::vector<double> sorted(samples.begin(), samples.end());
  std::sort(sorted.begin(), sorted.end());
  out.quantile_025 = quantile_of_sorted(sorted, 0.025);
  out.quantile_975 = quantile_of_sorted(sorted, 0.975);
  return out;
}

std::optional<double> sample_correlation(std::span<const double> a, std::span<const double> b) {
  require_domain(a.size() == b.size(), "a correlation of samples of different lengths");
  if (a.size() < 2) return std::nullopt;
  const double n = static_cast<double>(a.size());
  double mean_a = 0.0;
  double mean_b = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    mean_a += a[i];
    mean_b += b[i];
  }
  mean_a /= n;
  mean_b /= n;
  double saa = 0.0;
  double sbb = 0.0;
  double sab = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    saa += (a[i] - mean_a) * (a[i] - mean_a);
    sbb += (b[i] - mean_b) * (b[i] - mean_b);
    sab += (a[i] - mean_a) * (b[i] - mean_b);
  }
  if (!(saa > 0.0 && sbb > 0.0)) return std::nullopt;
  return sab / std::sqrt(saa * sbb);
}

}  // namespace fl
