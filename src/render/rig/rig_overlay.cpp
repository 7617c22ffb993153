#include "render/rig/rig_overlay.hpp"

#include "render/rig/caption_overlay.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "core/units.hpp"
#include "io/plus_minus.hpp"
#include "render/rig/overlay_palette.hpp"

namespace fl::render {
namespace {

using palette::kGrid;
using palette::kPanel;
using palette::kPulse;
using palette::kSoft;
using palette::kWhite;

const Color kTrace{1.0f, 0.78f, 0.15f, 1.0f};
const Color kDiscarded{0.95f, 0.25f, 0.22f, 0.28f};  // a discarded period, shaded

std::string slow_motion_text(double factor) {
  if (std::fabs(factor - 1.0) < 1e-9) return "real time";
  if (factor > 1.0) return fmt::format("slow motion \xc3\x97{:g}", factor);
  return fmt::format("sped up \xc3\x97{:g}", 1.0 / factor);
}

std::string measured_text(const Measured& m) {
  return fmt::format("{:.{}f} \xc2\xb1 {:.{}f}", m.value, m.decimals, m.uncertainty,
                     m.uncertainty_decimals);
}

const Color kLearning{0.62f, 0.66f, 0.72f, 1.0f};  // a pulse the estimator learned from

std::string plural(int n, const char* word) {
  return fmt::format("{} {}{}", n, word, n == 1 ? "" : "s");
}

// A legend entry right-aligned at `right`: a dot and a word. Returns the entry's left end.
float legend(Overlay& o, float right, float y, float s, const char* word, const Color& color) {
  o.text(word, Eigen::Vector2f(right, y), 12 * s, color, TextAlign::kRight);
  const Rect box = o.measure_text(word, 12 * s);
  const float dot_x = right - box.width - 6 * s;
  o.dot(Eigen::Vector2f(dot_x, y + box.height / 2.0f), 3.0f * s, color);
  return dot_x - 3.0f * s;
}

void draw_hall_plot(Overlay& o, const Rect& panel, float s, const RigOverlayState& state) {
  o.rect(panel, kPanel);
  o.text("Hall sensor: ADC counts against t (s)", Eigen::Vector2f(panel.x + 6 * s, panel.y + 4 * s),
         12 * s, kSoft);
  const double t0 = state.t - state.hall_window;
  const auto visible = [&](double t) { return t >= t0 && t <= state.t; };
  const bool learning_shown =
      std::any_of(state.learning_pulses.begin(), state.learning_pulses.end(), visible);
  float right = legend(o, panel.x + panel.width - 6 * s, panel.y + 4 * s, s, "pulse", kPulse);
  if (learning_shown) legend(o, right - 6 * s, panel.y + 4 * s, s, "learning", kLearning);

  // Room on the left for the counts and below for the times.
  const Rect area{panel.x + 32 * s, panel.y + 21 * s, panel.width - 38 * s, panel.height - 36 * s};
  o.rect_outline(area, 1.0f, kGrid);
  if (!state.has_sensor) {
    o.text("no Hall sensor in this scene", Eigen::Vector2f(area.x + 6 * s, area.y + 6 * s), 12 * s,
           kSoft);
    return;
  }
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
  // The axes' values: counts on the left, simulated time below, with faint grid lines.
  draw_value_axis(o, area, s, range[0], range[1], y_of, 11 * s);
  draw_time_axis(o, area, s, t0, state.t);
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
  // Every pulse the panel counts is marked: those the estimator times in green, those it learned
  // the signal from in grey.
  const auto mark = [&](double pulse, const Color& color) {
    const float x = x_of(pulse);
    o.line(Eigen::Vector2f(x, area.y + 1.0f), Eigen::Vector2f(x, area.y + area.height - 1.0f),
           1.0f * s, Color{color.r, color.g, color.b, 0.55f});
    o.dot(Eigen::Vector2f(x, area.y + 5.0f * s), 3.0f * s, color);
  };
  for (const double pulse : state.learning_pulses)
    if (visible(pulse)) mark(pulse, kLearning);
  for (const double pulse : state.pulses)
    if (visible(pulse)) mark(pulse, kPulse);
}

void draw_results(Overlay& o, const Rect& panel, float s, const RigOverlayState& state) {
  o.rect(panel, kPanel);
  const ResultsText text = results_text(state);
  float y = panel.y + 6 * s;
  const float x = panel.x + 8 * s;
  const float room = panel.width - 16 * s;
  // Each line shrinks to the panel's width (to 10 px at 640x360), never past its edge.
  const auto line = [&](const std::string& words, float size, const Color& color, float at_x,
                        float width) {
    const FittedText fitted = fit_text(o, words, width, size, std::min(size, 10.0f), s, 1);
    return o.text(fitted.lines.empty() ? std::string() : fitted.lines.front(),
                  Eigen::Vector2f(at_x, y), fitted.pixel_size, color);
  };
  const bool value = state.has_sensor && (state.estimator.period.has_value() ||
                                          state.estimator.provisional_period.has_value());
  const Rect r = line(text.period, state.has_sensor ? 17 : 14, kWhite, x, room);
  if (!text.note.empty()) {
    const float after = r.x + r.width + 6 * s;
    y += 4 * s;
    line(text.note, 12, kSoft, after, panel.x + panel.width - 8 * s - after);
    y -= 4 * s;
  }
  y += 22 * s;
  // mu_k as large as the values; what the estimator waits for, or why a value is provisional,
  // smaller.
  const bool provisional = !state.estimator.period && value;
  if (!text.detail.empty())
    line(text.detail, value && !provisional ? 15 : 13, value && !provisional ? kWhite : kSoft, x,
         room);
  y += 20 * s;
  line(text.paper, 12, kSoft, x, room);
}

}  // namespace

float overlay_scale(int width, int height) {
  return std::min(static_cast<float>(width) / 640.0f, static_cast<float>(height) / 360.0f);
}

std::string rig_heading(const CompiledRig& rig, const std::string& material) {
  std::string heading =
      material + " on " +
      (rig.rollers.material == "pvc" ? std::string("PVC") : rig.rollers.material) + " rollers";
  if (rig.friction_source.temperature_set)
    heading += fmt::format("  \xc2\xb7  {}{:.0f} K", rig.warming ? "from " : "",
                           rig.friction_source.temperature);
  heading += fmt::format("  \xc2\xb7  l = {:.0f} mm", rig.rollers.spacing * 1e3);
  if (rig.world.tilt != 0.0)
    heading += fmt::format("  \xc2\xb7  tilted {:+.1f}\xc2\xb0", rig.world.tilt * 180.0 / kPi);
  if (rig.roller_radii[0] != rig.roller_radii[1])
    heading += fmt::format("  \xc2\xb7  rollers {:.1f} / {:.1f} mm", rig.roller_radii[0] * 2e3,
                           rig.roller_radii[1] * 2e3);
  return heading;
}

ResultsText results_text(const RigOverlayState& state) {
  ResultsText out;
  out.paper = state.paper_period && state.paper_mu_k
                  ? "paper: T = " + measured_text(*state.paper_period) +
                        " s, \xce\xbc\xe2\x82\x96 = " + measured_text(*state.paper_mu_k)
                  : "(no paper value for this material)";
  const EstimatorValues& e = state.estimator;
  if (!state.has_sensor) {
    out.period = "no sensor: no period measured";
    return out;
  }
  // T +- dT as every front end shows it (io/plus_minus.hpp); one period has no spread: T alone,
  // never "± 0".
  const auto with_spread = [](double mean, std::optional<double> spread) {
    return spread && *spread > 0.0 ? plus_minus(mean, *spread, 0, "\xc2\xb1")
                                   : fmt::format("{:.3f}", mean);
  };
  const auto value = [&](double mean, std::optional<double> spread, int n) {
    return with_spread(mean, n >= 2 ? spread : std::nullopt);
  };
  if (e.period && e.periods > 0) {
    out.period = "T = " + value(*e.period, e.period_std, e.periods) + " s";
    out.note = e.periods_discarded > 0
                   ? fmt::format("(N = {}, {} discarded)", e.periods, e.periods_discarded)
                   : fmt::format("(N = {})", e.periods);
    if (e.mu_k) out.detail = "\xce\xbc\xe2\x82\x96 = " + with_spread(*e.mu_k, e.mu_k_err);
    return out;
  }
  if (e.provisional_period && e.provisional_periods > 0) {
    // The estimator recognises one pulse or a pair per period from five pulses in a row; until
    // then the intervals of the pulses it timed give the period, and say so.
    out.period = "T \xe2\x89\x88 " +
                 value(*e.provisional_period, e.provisional_std, e.provisional_periods) + " s";
    out.note = fmt::format("(N = {})", e.provisional_periods);
    out.detail = "provisional until 5 timed pulses";
    return out;
  }
  out.period = "T: measuring\xe2\x80\xa6";
  const int shown = e.learning_pulses + e.pulses;  // every pulse the plot marks
  if (!e.signal_learned)
    out.detail = "learning the signal from its first pulses";
  else if (!e.geometry_known)
    out.detail = fmt::format("{} seen, {} timed (green): a first T at 2 timed",
                             plural(shown, "pulse"), e.pulses);
  else
    out.detail =
        fmt::format("{} seen; no period has passed the checks yet", plural(shown, "pulse"));
  return out;
}

std::vector<AxisTick> hall_time_ticks(double t0, double t1) {
  std::vector<AxisTick> ticks;
  const double step = t1 - t0 > 5.0 ? 1.0 : 0.5;
  for (double k = std::ceil(std::max(0.0, t0) / step - 1e-9); k * step <= t1 + 1e-9; k += 1.0)
    ticks.push_back({k * step + 0.0, fmt::format("{:.1f}", k * step + 0.0)});  // + 0: no "-0.0"
  return ticks;
}

void draw_time_axis(Overlay& o, const Rect& area, float s, double t0, double t1) {
  for (const AxisTick& tick : hall_time_ticks(t0, t1)) {
    const float x = area.x + area.width * static_cast<float>((tick.value - t0) / (t1 - t0));
    o.line(Eigen::Vector2f(x, area.y + area.height),
           Eigen::Vector2f(x, area.y + area.height + 2 * s), 1.0f, kSoft);
    // Centred under its tick, but never past the plot's right end into the panel's edge.
    const float half = 0.5f * o.measure_text(tick.label, 11 * s).width;
    o.text(tick.label,
           Eigen::Vector2f(std::min(x, area.x + area.width + 2 * s - half),
                           area.y + area.height + 2 * s),
           11 * s, kSoft, TextAlign::kCenter);
  }
}

std::vector<AxisTick> value_ticks(double bottom, double top) {
  std::vector<AxisTick> ticks;
  const double span = top - bottom;
  if (!(span > 0.0) || !std::isfinite(span)) return ticks;
  // The smallest of 1, 2, 5 x 10^k that leaves at most four ticks.
  double step = std::pow(10.0, std::floor(std::log10(span / 4.0)));
  for (const double m : {1.0, 2.0, 5.0, 10.0}) {
    if (span / (m * step) <= 4.0) {
      step *= m;
      break;
    }
  }
  for (double k = std::ceil(bottom / step - 1e-9); k * step <= top + 1e-9; k += 1.0)
    ticks.push_back({k * step + 0.0, fmt::format("{:g}", k * step + 0.0)});  // + 0: no "-0"
  return ticks;
}

void draw_value_axis(Overlay& o, const Rect& area, float s, double bottom, double top,
                     const std::function<float(double)>& row_of, float text_size) {
  for (const AxisTick& tick : value_ticks(bottom, top)) {
    const float y = row_of(tick.value);
    o.line(Eigen::Vector2f(area.x, y), Eigen::Vector2f(area.x + area.width, y), 1.0f, kGrid);
    o.text(tick.label, Eigen::Vector2f(area.x - 3 * s, y - 5.5f * s), text_size, kSoft,
           TextAlign::kRight);
  }
}

TitleCard make_title_card(const CompiledRig& rig, const std::string& material, double slow_motion,
                          int fps, const std::string& title) {
  TitleCard card;
  card.title = title.empty() ? "The friction (Timoshenko) oscillator" : title;
  card.subtitle = fmt::format("{} on {} rollers, {:.0f} K", material,
                              rig.rollers.material == "pvc" ? "PVC" : rig.rollers.material,
                              rig.friction_source.temperature);
  const double rpm = rig.roller_speed_nominal * kRpmPerRadPerSecond;
  const std::array<double, 2>& a = rig.roller_radii;
  card.lines.push_back(fmt::format(
      "roller spacing l = {:.0f} mm, rollers {} mm across, {} at {:.0f} rpm",
      rig.rollers.spacing * 1e3,
      a[0] == a[1] ? fmt::format("{:.0f}", a[0] * 2e3)
                   : fmt::format("{:.1f} and {:.1f}", a[0] * 2e3, a[1] * 2e3),
      rig.rollers.sense == RollerSense::kInward ? "tops turning inward" : "tops turning outward",
      rpm));
  if (rig.drive) {
    const DriveDesc& d = rig.drive->parts;
    card.lines.push_back(fmt::format(
        "{:.0f} V motor at {:.0f} % duty ({:.0f} rpm), {:g}:1 gearbox, idlers couple the rollers",
        d.motor.rated_voltage, d.motor.duty * 100.0,
        d.motor.duty * d.motor.no_load_speed * kRpmPerRadPerSecond, rig.drive->gearbox_ratio));
  }
  std::string payload =
      fmt::format("plate {:.0f} \xc3\x97 {:.0f} \xc3\x97 {:g} mm", rig.plate_desc.length * 1e3,
                  rig.plate_desc.width * 1e3, rig.plate_desc.thickness * 1e3);
  if (!rig.plate_desc.blocks.empty())
    payload += fmt::format(", {} LEGO brick{}", rig.plate_desc.blocks.size(),
                           rig.plate_desc.blocks.size() == 1 ? "" : "s");
  if (!rig.magnets.empty())
    payload += fmt::format(", {} magnet{}", rig.magnets.size(), rig.magnets.size() == 1 ? "" : "s");
  if (rig.sensor)
    payload += fmt::format("; Hall sensor at x = {:.0f} mm", rig.sensor->position[0] * 1e3);
  card.lines.push_back(payload);
  card.lines.push_back(fmt::format(
      "released {:.0f} mm off centre; \xce\xbc\xe2\x82\x96 = {:.3g}{}", rig.plate_desc.offset * 1e3,
      rig.friction.mu_k, rig.friction_source.paper_material ? " (the paper's value)" : ""));
  if (rig.friction_source.paper_period && rig.friction_source.paper_mu_k)
    card.lines.push_back(
        "the paper measured T = " + measured_text(*rig.friction_source.paper_period) +
        " s, \xce\xbc\xe2\x82\x96 = " + measured_text(*rig.friction_source.paper_mu_k));
  card.footer = fmt::format("simulated by frictionlab  \xc2\xb7  {}  \xc2\xb7  {} fps",
                            slow_motion_text(slow_motion), fps);
  return card;
}

TitleCard make_end_card(const RigOverlayState& state, const std::string& theory,
                        const std::string& stopped) {
  TitleCard card;
  card.title = "What the run measured";
  const ResultsText text = results_text(state);
  card.subtitle = text.note.empty() ? text.period : text.period + "  " + text.note;
  if (!text.detail.empty()) card.lines.push_back(text.detail);
  if (!theory.empty()) card.lines.push_back(theory);
  card.lines.push_back(text.paper);
  if (!state.regime.empty()) card.lines.push_back("the plate: " + state.regime);
  if (!stopped.empty()) card.lines.push_back(stopped);
  card.footer =
      "T from the rig's Hall estimator; \xce\xbc\xe2\x82\x96 = 2\xcf\x80\xc2\xb2 l / (g T\xc2\xb2)";
  return card;
}

void draw_guard_banner(Overlay& o, int width, int height, const std::string& text) {
  const float s = overlay_scale(width, height);
  if (s < kSmallestOverlayScale) return;
  const float w = static_cast<float>(width);
  const float h = static_cast<float>(height);
  // "stopped at t = ...: why": the first part as the banner's heading, the reason below it,
  // wrapped to the frame's width.
  const std::size_t colon = text.find(": ");
  const std::string heading = colon == std::string::npos ? text : text.substr(0, colon);
  const std::string reason = colon == std::string::npos ? std::string() : text.substr(colon + 2);
  std::vector<std::string> lines;
  std::string current;
  std::size_t at = 0;
  while (at < reason.size()) {
    std::size_t end = reason.find(' ', at);
    if (end == std::string::npos) end = reason.size();
    const std::string word = reason.substr(at, end - at);
    const std::string longer = current.empty() ? word : current + " " + word;
    if (!current.empty() && o.measure_text(longer, 12 * s).width > w - 24 * s) {
      lines.push_back(current);
      current = word;
    } else {
      current = longer;
    }
    at = end + 1;
  }
  if (!current.empty()) lines.push_back(current);
  const Rect bar{0, 0.36f * h, w, (28 + 16 * static_cast<float>(lines.size())) * s};
  o.rect(bar, Color{0.62f, 0.08f, 0.08f, 0.92f});
  o.text("The run " + heading, Eigen::Vector2f(w / 2, bar.y + 6 * s), 15 * s, kWhite,
         TextAlign::kCenter);
  float y = bar.y + 26 * s;
  for (const std::string& line : lines) {
    o.text(line, Eigen::Vector2f(w / 2, y), 12 * s, kWhite, TextAlign::kCenter);
    y += 16 * s;
  }
}

void draw_rig_overlay(Overlay& o, int width, int height, const RigOverlayState& state) {
  const float s = overlay_scale(width, height);
  if (s < kSmallestOverlayScale) return;
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
    o.text(fmt::format("{:.0f} rpm", std::fabs(*state.motor_speed) * kRpmPerRadPerSecond),
           Eigen::Vector2f(speeds.x + speeds.width - 6 * s, y), 13 * s, kWhite, TextAlign::kRight);
    y += 17 * s;
  }
  o.text("rollers", Eigen::Vector2f(speeds.x + 6 * s, y), 13 * s, kSoft);
  o.text(fmt::format("{:.0f} rpm", std::fabs(state.roller_speed) * kRpmPerRadPerSecond),
         Eigen::Vector2f(speeds.x + speeds.width - 6 * s, y), 13 * s, kWhite, TextAlign::kRight);
  // What the plate does, as the run reads it so far.
  if (!state.regime.empty()) {
    // As wide as its text (at least the speeds' panel), up to the frame's half.
    const Rect words = o.measure_text(state.regime, 13 * s);
    const float wide = std::clamp(words.width + 12 * s, 230 * s, 0.5f * static_cast<float>(width));
    const Rect regime{8 * s, speeds.y + speeds.height + 4 * s, wide, 23 * s};
    o.rect(regime, kPanel);
    o.text(state.regime, Eigen::Vector2f(regime.x + 6 * s, regime.y + 4 * s), 13 * s, kWhite);
    y = regime.y + regime.height;
  } else {
    y = speeds.y + speeds.height;
  }
  // How the weight is shared, under them.
  if (state.forces)
    draw_weight_share(o, Eigen::Vector2f(8 * s, y + 4 * s), s, *state.forces, state.force_scale);
  // The motion against theory, top right.
  if (state.motion)
    draw_motion_strip(o, Rect{w - 276 * s, 28 * s, 268 * s, 88 * s}, s, *state.motion);
  // The phase portrait under the strip's right end, above where two lines of caption reach.
  if (state.phase) draw_phase_portrait(o, phase_portrait_panel(w, s), s, *state.phase);

  draw_hall_plot(o, Rect{8 * s, h - 104 * s, 300 * s, 96 * s}, s, state);
  draw_results(o, Rect{w - 276 * s, h - 76 * s, 268 * s, 68 * s}, s, state);
}

Rect phase_portrait_panel(float width, float s) {
  return Rect{width - 150 * s, 122 * s, 142 * s, 80 * s};
}

void draw_title_card(Overlay& o, int width, int height, const TitleCard& card, float opacity) {
  const float s = overlay_scale(width, height);
  if (s < kSmallestOverlayScale) return;
  const float w = static_cast<float>(width);
  const float h = static_cast<float>(height);
  const float a = std::clamp(opacity, 0.0f, 1.0f);
  // Opaque at full strength: the panels drawn before it must not show through.
  o.rect(Rect{0, 0, w, h}, Color{0.04f, 0.06f, 0.09f, a});
  const auto faded = [a](Color c) {
    c.a *= a;
    return c;
  };
  float y = h * 0.16f;
  // A long title (run --title) wraps to three lines at most, then shrinks to fit them (28 px
  // to 10 px at 640x360).
  const FittedText title = fit_text(o, card.title, w - 32 * s, 28.0f, 10.0f, s, 3);
  for (std::size_t i = 0; i < title.lines.size(); ++i) {
    if (i > 0) y += title.pixel_size * 1.25f;
    o.text(title.lines[i], Eigen::Vector2f(w / 2, y), title.pixel_size, faded(kWhite),
           TextAlign::kCenter);
  }
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
