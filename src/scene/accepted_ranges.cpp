#include "scene/accepted_ranges.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/plausible_range.hpp"
#include "scene/scene_checks.hpp"

namespace fl {
namespace {

// Enough halvings to bring any span below a part in 1e12 of it: a slider's step is far coarser.
constexpr int kHalvings = 48;

// One key a student turns: how to set it in a scene, and the span the search covers.
struct TurnedKey {
  const char* key;
  const char* unit;
  std::function<double&(Scene&)> value;
  double far_least;  // the search's bounds: no accepted value lies beyond them
  double far_most;
};

bool accepts(const Scene& scene, const TurnedKey& turned, double v) {
  Scene trial = scene;
  turned.value(trial) = v;
  return check_scene(trial).empty();
}

// `v` to 9 significant digits.
double nine_digits(double v) {
  if (v == 0.0) return 0.0;
  const double scale = std::pow(10.0, 8 - std::floor(std::log10(std::fabs(v))));
  return std::round(v * scale) / scale;
}

// From `accepted` toward `far`, the last value accepted, as a number of 9 significant digits: the
// rule's own bound where it takes it (40 mm, two idlers meeting), else one part in 1e8 inside a
// bound it does not (20.0000002 mm, the rollers just clear of each other). A front end rounding
// the range inward to its control's step then never offers a refused value.
double edge(const Scene& scene, const TurnedKey& turned, double accepted, double far) {
  if (accepts(scene, turned, far)) return far;
  const double start = accepted;
  double refused = far;
  for (int i = 0; i < kHalvings; ++i) {
    const double mid = 0.5 * (accepted + refused);
    (accepts(scene, turned, mid) ? accepted : refused) = mid;
  }
  const double bound = nine_digits(accepted);
  if (accepts(scene, turned, bound)) return bound;
  const double inside = nine_digits(bound + (start - bound) * 1e-8 / std::fabs(start - bound) *
                                                std::max(std::fabs(bound), 1e-300));
  return accepts(scene, turned, inside) ? inside : accepted;
}

std::vector<TurnedKey> turned_keys(const Scene& scene) {
  std::vector<TurnedKey> keys;
  keys.push_back({"rollers.spacing", "m", [](Scene& s) -> double& { return s.rollers.spacing; },
                  kSpacingRange.least, kSpacingRange.most});
  if (scene.drive)
    keys.push_back({"drive.motor.duty", "", [](Scene& s) -> double& { return s.drive->motor.duty; },
                    0.0, 1.0});
  else
    keys.push_back({"rollers.speed", "rad/s", [](Scene& s) -> double& { return s.rollers.speed; },
                    kRollerSpeedRange.least, kRollerSpeedRange.most});
  // The plate leaves a roller long before it is offset by its own length.
  const double plate = scene.plate.length;
  keys.push_back(
      {"plate.offset", "m", [](Scene& s) -> double& { return s.plate.offset; }, -plate, plate});
  // A run needs one step; at most 1e9 of them (scene_checks.cpp).
  keys.push_back({"world.duration", "s", [](Scene& s) -> double& { return s.world.duration; },
                  scene.world.time_step, 1e9 * scene.world.time_step});
  return keys;
}

}  // namespace

std::vector<AcceptedRange> accepted_ranges(const Scene& scene) {
  std::vector<AcceptedRange> out;
  for (TurnedKey& turned : turned_keys(scene)) {
    Scene copy = scene;
    const double own = turned.value(copy);
    if (!std::isfinite(own) || !accepts(scene, turned, own)) continue;
    out.push_back({turned.key, edge(scene, turned, own, turned.far_least),
                   edge(scene, turned, own, turned.far_most), turned.unit});
  }
  return out;
}

}  // namespace fl
