// What a set of Monte Carlo draws says about one quantity: mean, standard deviation and the
// central 95 % interval, and the correlation of two quantities drawn together.
#pragma once

#include <optional>
#include <span>
#include <vector>

namespace fl {

struct SampleSummary {
  double mean = 0.0;
  std::optional<double> sd;   // sample standard deviation (n - 1); absent below 2 samples
  double quantile_025 = 0.0;  // 2.5 % quantile, linear between order statistics
  double quantile_975 = 0.0;  // 97.5 % quantile
};

// Refuses an empty set with fl::DomainError.
SampleSummary summarise_samples(std::span<const double> samples);

// The p-quantile (0 <= p <= 1) of sorted samples, linear between order statistics
// (x[(n - 1) p]: Hyndman and Fan's type 7, numpy's default).
double quantile_of_sorted(std::span<const double> sorted, double p);

// The median: the middle sample, or the mean of the two middle ones. Refuses an empty set with
// fl::DomainError.
double median_of(std::vector<double> samples);

// Pearson's correlation of paired samples; absent below 2 pairs or when either has no spread.
std::optional<double> sample_correlation(std::span<const double> a, std::span<const double> b);

}  // namespace fl
