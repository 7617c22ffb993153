#include "core/ramp.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/domain_check.hpp"
#include "text/describe.hpp"

namespace fl {

Ramp::Ramp(std::vector<RampPoint> points) : points_(std::move(points)) {
  require_domain(!points_.empty(), "a ramp needs at least one point (time, value)");
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const RampPoint& p = points_[i];
    require_domain(
        std::isfinite(p.at) && p.at >= 0.0,
        describe("ramp point ", i, ": its time must be finite and >= 0, got ", p.at, " s"));
    require_domain(std::isfinite(p.value),
                   describe("ramp point ", i, ": its value must be finite, got ", p.value));
    if (i > 0)
      require_domain(p.at > points_[i - 1].at,
                     describe("ramp point ", i, ": times must increase, got ", p.at, " s after ",
                              points_[i - 1].at, " s"));
  }
}

double Ramp::at(double t) const {
  if (t <= points_.front().at) return points_.front().value;
  if (t >= points_.back().at) return points_.back().value;
  // The segment [a, b] with a.at <= t < b.at.
  const auto b = std::upper_bound(points_.begin(), points_.end(), t,
                                  [](double time, const RampPoint& p) { return time < p.at; });
  const RampPoint& a = *(b - 1);
  const double f = (t - a.at) / (b->at - a.at);
  return a.value + f * (b->value - a.value);
}

double Ramp::slope(double t) const {
  if (t < points_.front().at || t >= points_.back().at) return 0.0;
  const auto b = std::upper_bound(points_.begin(), points_.end(), t,
                                  [](double time, const RampPoint& p) { return time < p.at; });
  const RampPoint& a = *(b - 1);
  return (b->value - a.value) / (b->at - a.at);
}

double Ramp::smallest(double t0, double t1) const {
  double out = std::min(at(t0), at(t1));
  for (const RampPoint& p : points_)
    if (p.at > t0 && p.at < t1) out = std::min(out, p.value);
  return out;
}

double Ramp::largest(double t0, double t1) const {
  double out = std::max(at(t0), at(t1));
  for (const RampPoint& p : points_)
    if (p.at > t0 && p.at < t1) out = std::max(out, p.value);
  return out;
}

double Ramp::smallest() const {
  double out = points_.front().value;
  for (const RampPoint& p : points_) out = std::min(out, p.value);
  return out;
}

double Ramp::largest() const {
  double out = points_.front().value;
  for (const RampPoint& p : points_) out = std::max(out, p.value);
  return out;
}

}  // namespace fl
