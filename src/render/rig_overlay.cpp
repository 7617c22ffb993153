#include "render/rig_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace fl::render {
namespace {

const Color kPanel{0.05f, 0.07f, 0.10f, 0.74f};
const Color kWhite{1.0f, 1.0f, 1.0f, 1.0f};
const Color kSoft{0.80f, 0.85f, 0.92f, 1.0f};
const Color kTrace{1.0f, 0.78f, 0.15f, 1.0f};
const Color kPulse{0.35f, 0.92f, 0.45f, 1.0f};
const Color kDiscarded{0.95f, 0.25f, 0.22f, 0.28f};  // a discarded period, shaded
const Color kGrid{1.0f, 1.0f, 1.0f, 0.18f};

constexpr double kRpm = 60.0 / (2.0 * std::numbers::pi);
// Below half the 640x360 layout (320x180) the text would be too small to read: no overlay.
constexpr float kSmallestScale = 0.5f;

// The frame's scale against the 640x360 layout.
float layout_scale(int width, int height) {
  return std::min(static_cast<float>(width) / 640.0f, static_cast<float>(height) / 360.0f);
}

std::string slow_motion_text(double factor) {
  if (std::fabs(factor - 1.0) < 1e-9) return "real time";
  if (factor > 1.0) return fmt::format("slow motion \xc3\x97{:g}", factor);
  return fmt::format("sped up \xc3\x97{:g}", 1.0 / factor);
}

std::string measured_text(const Measured& m) {
  return fmt::format("{:.{}f} \xc2\xb1 {:.{}f}", m.value, m.decimals, m.uncertainty,
                     m.uncertainty_decimals);
}

void draw_hall_plot(Overlay& o, const Rect& panel, float s, const RigOverlayState& state) {
  o.rect(panel, kPanel);
  o.text(fmt::format("Hall sensor (ADC counts), last {:g} s", state.hall_window),
         Eigen::Vector2f(panel.x + 6 * s, panel.y + 4 * s), 12 * s, kSoft);
  o.text("pulse", Eigen::Vector2f(panel.x + panel.width - 6 * s, panel.y + 4 * s), 12 * s, kPulse,
         TextAlign::kRight);
  const Rect word = o.measure_text("pulse", 12 * s);
  o.dot(Eigen::Vector2f(panel.x + panel.width - 6 * s - word.width - 6 * s,
                        panel.y + 4 * s + word.height / 2.0f),
        3.0f * s, kPulse);

  const Rect area{panel.x + 6 * s, panel.y + 22 * s, panel.width - 12 * s, panel.height - 28 * s};
  o.rect_outline(area, 1.0f, kGrid);
  o.line(Eigen::Vector2f(area.x, area.y + area.height / 2.0f),
         Eigen::Vector2f(area.x + area.width, area.y + area.height / 2.0f), 1.0f, kGrid);
  if (!state.has_sensor) {
    o.text("no Hall sensor in this scene", Eigen::Vector2f(area.x + 6 * s, area.y + 6 * s), 12 * s,
           kSoft);
    return;
  }
  const double t0 = state.t - state.hall_window;
  const auto x_of = [&](double t) {
    return area.x + area.width * static_cast<float>((t - t0) / state.hall_window);
  };
  std::array<double, 2> range{0.0, 1023.0};
  if (state.hall_range) range = *state.hall_range;
  const double span = std::max(1.0, range[1] - range[0]);
  const auto y_of = [&](double adc) {
    const double f = std::clamp((adc - range[0]) / span, 0.0, 1.0);
    return area.y + area.height - 2.0f * s - static_cast<float>(f) * (area.height - 4.0f * s);
  };
  // Thousands of samples to a point every two pixels (at 640x360 and above), keeping the pulses:
  // in each column the sample that makes the largest triangle with the point chosen before it
  // and the next column's mean ("largest triangle three buckets").
  std::vector<Eigen::Vector2f> samples;
  for (const HallPoint& p : state.hall)
    if (p.t >= t0 && p.t <= state.t) samples.emplace_back(x_of(p.t), y_of(p.adc));
  const std::size_t columns =
      std::max<std::size_t>(2, static_cast<std::size_t>(area.width / std::max(1.0f, 2.0f * s)));
  std::vector<Eigen::Vector2f> trace;
  if (samples.size() <= columns + 2) {
    trace = samples;
  } else {
    const double per = static_cast<double>(samples.size() - 2) / static_cast<double>(columns);
    const auto bucket = [&](std::size_t i) {
      return std::pair{1 + static_cast<std::size_t>(per * static_cast<double>(i)),
                       std::min(samples.size() - 1,
                                1 + static_cast<std::size_t>(per * static_cast<double>(i + 1)))};
    };
    trace.push_back(samples.front());
    for (std::size_t i = 0; i < columns; ++i) {
      const auto [first, last] = bucket(i);
      Eigen::Vector2f next = samples.back();
      if (i + 1 < columns) {
        const auto [n0, n1] = bucket(i + 1);
        next = Eigen::Vector2f::Zero();
        for (std::size_t k = n0; k < n1; ++k) next += samples[k];
        next /= static_cast<float>(std::max<std::size_t>(1, n1 - n0));
      }
      const Eigen::Vector2f a = trace.back();
      float best = -1.0f;
      std::size_t chosen = first;
      for (std::size_t k = first; k < last; ++k) {
        const Eigen::Vector2f u = samples[k] - a;
        const Eigen::Vector2f v = next - a;
        const float area2 = std::fabs(u.x() * v.y() - u.y() * v.x());
        if (area2 > best) {
          best = area2;
          chosen = k;
        }
      }
      trace.push_back(samples[chosen]);
    }
    trace.push_back(samples.back());
  }
  // The periods the estimator discarded, shaded behind the trace.
  bool any_discarded = false;
  for (const std::array<double, 2>& d : state.discarded) {
    if (d[1] < t0 || d[0] > state.t) continue;
    const float a = x_of(std::max(d[0], t0)), b = x_of(std::min(d[1], state.t));
    o.rect(Rect{a, area.y + 1.0f, std::max(1.0f, b - a), area.height - 2.0f}, kDiscarded);
    any_discarded = true;
  }
  if (any_discarded)
    o.text("discarded period", Eigen::Vector2f(area.x + 4 * s, area.y + 3 * s), 11 * s,
           Color{kDiscarded.r, kDiscarded.g, kDiscarded.b, 1.0f});
  o.polyline(trace, 1.5f * s, kTrace);
  for (const double pulse : state.pulses) {
    if (pulse < t0 || pulse > state.t) continue;
    const float x = x_of(pulse);
    o.line(Eigen::Vector2f(x, area.y + 1.0f), Eigen::Vector2f(x, area.y + area.height - 1.0f),
           1.0f * s, Color{kPulse.r, kPulse.g, kPulse.b, 0.55f});
    o.dot(Eigen::Vector2f(x, area.y + 5.0f * s), 3.0f * s, kPulse);
  }
}

void draw_results(Overlay& o, const Rect& panel, float s, const RigOverlayState& state) {
  o.rect(panel, kPanel);
  const EstimatorValues& e = state.estimator;
  float y = panel.y + 6 * s;
  const float x = panel.x + 8 * s;
  if (!state.has_sensor) {
    o.text("no sensor: no period measured", Eigen::Vector2f(x, y), 14 * s, kWhite);
    y += 22 * s;
  } else if (e.period) {
    const Rect r = o.text("T = " + format_plus_minus(*e.period, e.period_std.value_or(0.0)) + " s",
                          Eigen::Vector2f(x, y), 17 * s, kWhite);
    o.text(e.periods_discarded > 0
               ? fmt::format("(N = {}, {} discarded)", e.periods, e.periods_discarded)
               : fmt::format("({} period{})", e.periods, e.periods == 1 ? "" : "s"),
           Eigen::Vector2f(r.x + r.width + 6 * s, y + 4 * s), 12 * s, kSoft);
    y += 22 * s;
    if (e.mu_k)
      o.text("\xce\xbc\xe2\x82\x96 = " + format_plus_minus(*e.mu_k, e.mu_k_err.value_or(0.0)),
             Eigen::Vector2f(x, y), 15 * s, kWhite);
    y += 20 * s;
  } else {
    o.text("T: measuring\xe2\x80\xa6", Eigen::Vector2f(x, y), 17 * s, kWhite);
    y += 22 * s;
    o.text(fmt::format("{} pulse{} so far", e.pulses, e.pulses == 1 ? "" : "s"),
           Eigen::Vector2f(x, y), 13 * s, kSoft);
    y += 20 * s;
  }
  if (state.paper_period && state.paper_mu_k) {
    o.text("paper: T = " + measured_text(*state.paper_period) +
               " s, \xce\xbc\xe2\x82\x96 = " + measured_text(*state.paper_mu_k),
           Eigen::Vector2f(x, y), 12 * s, kSoft);
  } else {
    o.text("(no paper value for this material)", Eigen::Vector2f(x, y), 12 * s, kSoft);
  }
}

}  // namespace

std::string format_plus_minus(double value, double uncertainty) {
  int decimals = 3;
  if (uncertainty > 0.0 && std::isfinite(uncertainty)) {
    const double exponent = std::floor(std::log10(uncertainty));
    const double leading = uncertainty / std::pow(10.0, exponent);
    decimals = static_cast<int>(-exponent) + (leading < 2.95 ? 1 : 0);
    decimals = std::clamp(decimals, 0, 6);
  }
  return fmt::format("{:.{}f} \xc2\xb1 {:.{}f}", value, decimals, uncertainty, decimals);
}

TitleCard make_title_card(const CompiledRig& rig, const std::string& material, double slow_motion,
                          int fps) {
  const Scene& scene = rig.scene;
  TitleCard card;
  card.title = "The friction (Timoshenko) oscillator";
  card.subtitle = fmt::format("{} on {} rollers, {:.0f} K", material,
                              scene.rollers.material == "pvc" ? "PVC" : scene.rollers.material,
                              scene.friction.temperature);
  const double rpm = rig.roller_speed_nominal * kRpm;
  card.lines.push_back(fmt::format(
      "roller spacing l = {:.0f} mm, rollers {:.0f} mm across, {} at {:.0f} rpm",
      scene.rollers.spacing * 1e3, scene.rollers.radius * 2e3,
      scene.rollers.sense == RollerSense::kInward ? "tops turning inward" : "tops turning outward",
      rpm));
  if (scene.drive) {
    const DriveDesc& d = *scene.drive;
    card.lines.push_back(fmt::format(
        "{:.0f} V motor at {:.0f} % duty ({:.0f} rpm), {:g}:1 gearbox, idlers couple the rollers",
        d.motor.rated_voltage, d.motor.duty * 100.0, d.motor.duty * d.motor.no_load_speed * kRpm,
        rig.drive->gearbox_ratio));
  }
  std::string payload =
      fmt::format("plate {:.0f} \xc3\x97 {:.0f} \xc3\x97 {:g} mm", scene.plate.length * 1e3,
                  scene.plate.width * 1e3, scene.plate.thickness * 1e3);
  if (!scene.plate.blocks.empty())
    payload += fmt::format(", {} LEGO brick{}", scene.plate.blocks.size(),
                           scene.plate.blocks.size() == 1 ? "" : "s");
  if (!scene.magnets.empty())
    payload +=
        fmt::format(", {} magnet{}", scene.magnets.size(), scene.magnets.size() == 1 ? "" : "s");
  if (scene.sensor)
    payload += fmt::format("; Hall sensor at x = {:.0f} mm", scene.sensor->position[0] * 1e3);
  card.lines.push_back(payload);
  card.lines.push_back(fmt::format("released {:.0f} mm off centre; \xce\xbc\xe2\x82\x96 = {:.3g}{}",
                                   scene.plate.offset * 1e3, rig.mu_k,
                                   scene.friction.from_paper ? " (the paper's value)" : ""));
  if (scene.friction.paper_period && scene.friction.paper_mu_k)
    card.lines.push_back("the paper measured T = " + measured_text(*scene.friction.paper_period) +
                         " s, \xce\xbc\xe2\x82\x96 = " + measured_text(*scene.friction.paper_mu_k));
  card.footer = fmt::format("simulated by frictionlab  \xc2\xb7  {}  \xc2\xb7  {} fps",
                            slow_motion_text(slow_motion), fps);
  return card;
}

void draw_rig_overlay(Overlay& o, int width, int height, const RigOverlayState& state) {
  const float s = layout_scale(width, height);
  if (s < kSmallestScale) return;
  const float w = static_cast<float>(width);
  const float h = static_cast<float>(height);
  // The top bar: what is on screen, and the clock.
  o.rect(Rect{0, 0, w, 22 * s}, kPanel);
  o.text(state.heading, Eigen::Vector2f(8 * s, 4 * s), 13 * s, kWhite);
  o.text(fmt::format("t = {:.2f} s  \xc2\xb7  ", state.t) + slow_motion_text(state.slow_motion),
         Eigen::Vector2f(w - 8 * s, 4 * s), 13 * s, kSoft, TextAlign::kRight);

  // The drive's speeds.
  const float rows = state.motor_speed ? 2.0f : 1.0f;
  const Rect speeds{8 * s, 28 * s, 138 * s, (6 + 17 * rows) * s};
  o.rect(speeds, kPanel);
  float y = speeds.y + 4 * s;
  if (state.motor_speed) {
    o.text("motor", Eigen::Vector2f(speeds.x + 6 * s, y), 13 * s, kSoft);
    o.text(fmt::format("{:.0f} rpm", std::fabs(*state.motor_speed) * kRpm),
           Eigen::Vector2f(speeds.x + speeds.width - 6 * s, y), 13 * s, kWhite, TextAlign::kRight);
    y += 17 * s;
  }
  o.text("rollers", Eigen::Vector2f(speeds.x + 6 * s, y), 13 * s, kSoft);
  o.text(fmt::format("{:.0f} rpm", std::fabs(state.roller_speed) * kRpm),
         Eigen::Vector2f(speeds.x + speeds.width - 6 * s, y), 13 * s, kWhite, TextAlign::kRight);
  // What the plate does, as the run reads it so far.
  if (!state.regime.empty()) {
    // As wide as its text (at least the speeds' panel), up to the frame's half.
    const Rect words = o.measure_text(state.regime, 13 * s);
    const float wide = std::clamp(words.width + 12 * s, 230 * s, 0.5f * static_cast<float>(width));
    const Rect regime{8 * s, speeds.y + speeds.height + 4 * s, wide, 23 * s};
    o.rect(regime, kPanel);
    o.text(state.regime, Eigen::Vector2f(regime.x + 6 * s, regime.y + 4 * s), 13 * s, kWhite);
  }

  draw_hall_plot(o, Rect{8 * s, h - 104 * s, 300 * s, 96 * s}, s, state);
  draw_results(o, Rect{w - 276 * s, h - 76 * s, 268 * s, 68 * s}, s, state);
}

void draw_title_card(Overlay& o, int width, int height, const TitleCard& card, float opacity) {
  const float s = layout_scale(width, height);
  if (s < kSmallestScale) return;
  const float w = static_cast<float>(width);
  const float h = static_cast<float>(height);
  const float a = std::clamp(opacity, 0.0f, 1.0f);
  o.rect(Rect{0, 0, w, h}, Color{0.04f, 0.06f, 0.09f, 0.84f * a});
  const auto faded = [a](Color c) {
    c.a *= a;
    return c;
  };
  float y = h * 0.16f;
  o.text(card.title, Eigen::Vector2f(w / 2, y), 28 * s, faded(kWhite), TextAlign::kCenter);
  y += 40 * s;
  o.text(card.subtitle, Eigen::Vector2f(w / 2, y), 18 * s, faded(kTrace), TextAlign::kCenter);
  y += 34 * s;
  for (const std::string& line : card.lines) {
    o.text(line, Eigen::Vector2f(w / 2, y), 13 * s, faded(kSoft), TextAlign::kCenter);
    y += 20 * s;
  }
  o.text(card.footer, Eigen::Vector2f(w / 2, h - 28 * s), 12 * s, faded(kSoft), TextAlign::kCenter);
}

}  // namespace fl::render
