#include "lab/report/report_html.hpp"

#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "io/plus_minus.hpp"
#include "lab/report/svg_plot.hpp"
#include "text/html_text.hpp"

namespace fl {
namespace {

constexpr const char* kCitation =
    "R. Henaff, G. Le Doudic, B. Pilette, C. Even, J.-M. Fischbach, F. Bouquet, J. Bobroff, "
    "M. Monteverde and C. A. Marrache-Kikuchi, &ldquo;A study of kinetic friction: The Timoshenko "
    "oscillator&rdquo;, <i>American Journal of Physics</i> <b>86</b>, 174 (2018)";

// Colours told apart with any colour vision (Okabe and Ito).
constexpr const char* kBlue = "#0072B2";
constexpr const char* kOrange = "#D55E00";

constexpr const char* kStyle = R"(
body { font: 11pt/1.45 Georgia, "DejaVu Serif", serif; color: #111; max-width: 180mm;
       margin: 2em auto; padding: 0 1em; }
h1 { font-size: 18pt; margin: 0 0 0.2em; }
h2 { font-size: 14pt; margin: 1.4em 0 0.4em; border-bottom: 1px solid #999; }
h3 { font-size: 12pt; margin: 1em 0 0.3em; }
.byline { color: #333; margin: 0 0 1em; }
table { border-collapse: collapse; margin: 0.4em 0; font-size: 10pt; }
th, td { border: 1px solid #bbb; padding: 2px 6px; text-align: left; vertical-align: top; }
td.n { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
.result { font-size: 13pt; margin: 0.3em 0; }
.why { color: #333; font-size: 10pt; margin: 0 0 0.6em; }
figure { margin: 0.6em 0; break-inside: avoid; }
figure svg { width: 100%; height: auto; }
figcaption { font-size: 10pt; color: #333; }
.periods { columns: 2; column-gap: 1.5em; }
.rejected { color: #8a1c00; }
footer { margin-top: 2em; font-size: 9pt; color: #444; }
@page { margin: 15mm; }
@media print {
  body { margin: 0; padding: 0; max-width: none; font-size: 10pt; }
  h2 { break-after: avoid; }
  table, figure, .result { break-inside: avoid; }
  thead { display: table-header-group; }
  a { color: inherit; text-decoration: none; }
}
)";

// The exact value as the summary's JSON writes it (shortest round trip).
std::string exact(double v) {
  return nlohmann::json(v).dump();
}

// A number with its source: `text` shown, the value exact in data-value; "—" when not measured.
std::string number(const ReportNumber& n, const std::string& text) {
  if (!n.value) return fmt::format("<span data-field=\"{}\" data-value=\"null\">—</span>", n.field);
  return fmt::format("<span data-field=\"{}\" data-value=\"{}\">{}</span>", n.field,
                     exact(*n.value), text);
}

std::string fixed(double v, int decimals) {
  return fmt::format("{:.{}f}", v, decimals);
}

std::string value_with_error(const ReportNumber& value, const ReportNumber& error, int decimals,
                             const std::string& unit) {
  if (!value.value) return number(value, "");
  if (!error.value)
    return number(value, fixed(*value.value, decimals)) + " ± " + number(error, "") + unit +
           " (no spread: one period)";
  const std::string both = plus_minus(*value.value, *error.value, decimals, "±");
  const std::size_t sign = both.find(" ± ");
  return number(value, both.substr(0, sign)) + " ± " + number(error, both.substr(sign + 3)) + unit;
}

std::string set_up_table(const ReportPart& part) {
  std::string out = "<table class=\"set-up\"><tbody>\n";
  for (const auto& [what, value] : part.set_up)
    out += fmt::format("<tr><th scope=\"row\">{}</th><td>{}</td></tr>\n", html_text(what),
                       html_text(value));
  return out + "</tbody></table>\n";
}

std::string figures(const ReportPart& part) {
  std::string out;
  const auto figure = [&out](const ReportCurve& curve, const std::string& title,
                             const std::string& caption) {
    SvgPlot plot;
    plot.title = title;
    plot.x_label = "t (s)";
    plot.y_label = curve.label;
    plot.series.push_back({curve.t_s, curve.value, "", kBlue, false});
    out += "<figure>\n" + svg_line_plot(plot) +
           fmt::format("<figcaption>{}</figcaption></figure>\n", caption);
  };
  if (part.position)
    figure(*part.position, "The plate's position x(t)",
           "The plate's position x(t), the whole run (the simulation's trajectory).");
  if (part.signal)
    figure(*part.signal, part.signal->label,
           part.simulated ? "The Hall sensor's signal, as the rig's Arduino reads it: a pulse "
                            "each time a magnet passes over the sensor."
                          : "The measurement, as read: the channel the estimator timed.");
  if (!part.periods.empty()) {
    SvgPlot plot;
    plot.title = "Each period against its start";
    plot.x_label = "start of the period (s)";
    plot.y_label = "T (s)";
    SvgSeries accepted{{}, {}, "accepted", kBlue, false, true};
    SvgSeries rejected{{}, {}, "discarded", kOrange, false, true};
    for (const ReportPeriod& p : part.periods) {
      SvgSeries& into = p.accepted ? accepted : rejected;
      into.x.push_back(p.start_s);
      into.y.push_back(p.period_s);
    }
    plot.series.push_back(accepted);
    if (!rejected.x.empty()) plot.series.push_back(rejected);
    out += "<figure>\n" + svg_line_plot(plot) +
           "<figcaption>Each period at its start: the scatter of the accepted ones is the "
           "periods' standard deviation.</figcaption></figure>\n";
  }
  return out;
}

std::string periods_table(const ReportPart& part) {
  if (part.periods.empty()) return "<p>The estimator found no period.</p>\n";
  std::string out =
      "<table class=\"periods-table\"><thead><tr><th>#</th><th>start (s)</th><th>end "
      "(s)</th><th>T (s)</th><th>accepted</th></tr></thead><tbody>\n";
  int i = 0;
  for (const ReportPeriod& p : part.periods)
    out += fmt::format(
        "<tr{}><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td "
        "class=\"n\" data-value=\"{}\">{}</td><td>{}</td></tr>\n",
        p.accepted ? "" : " class=\"rejected\"", ++i, fixed(p.start_s, 4), fixed(p.end_s, 4),
        exact(p.period_s), fixed(p.period_s, 4),
        p.accepted ? "yes" : "no: beyond 20 % of the running median");
  return out + "</tbody></table>\n";
}

std::string results(const ReportPart& part) {
  std::string out;
  out += "<p class=\"result\">T = " + value_with_error(part.period, part.period_se, 4, " s") +
         "</p>\n";
  out += fmt::format(
      "<p class=\"why\">T is the mean of the {} accepted periods; dT is their standard error "
      "(standard deviation {} s over the square root of their number).</p>\n",
      number(part.periods_used,
             part.periods_used.value ? fmt::format("{:.0f}", *part.periods_used.value) : ""),
      number(part.period_sd, part.period_sd.value ? fixed(*part.period_sd.value, 5) : ""));
  out +=
      "<p class=\"result\">μ<sub>k</sub> = " + value_with_error(part.mu_k, part.mu_k_err, 3, "") +
      "</p>\n";
  out += fmt::format(
      "<p class=\"why\">μ<sub>k</sub> = 2π² l / (g T²), with l = {} mm and g = {} m/s². Its "
      "uncertainty combines in quadrature the spacing's, dl / l with dl = {} mm, and the "
      "period's, 2 σ<sub>T</sub> / T with σ<sub>T</sub> the periods' standard deviation, as the "
      "rig's Arduino computes it; added instead of combined, they give ± {}.</p>\n",
      fixed(part.spacing_m * 1e3, 1), fixed(part.gravity_m_s2, 2),
      fixed(part.spacing_err_m * 1e3, 1),
      number(part.mu_k_err_worst,
             part.mu_k_err_worst.value ? fixed(*part.mu_k_err_worst.value, 4) : ""));
  return out;
}

std::string part_section(const ReportPart& part, int index) {
  std::string out = fmt::format("<section class=\"part\" id=\"part-{}\"><h2>{}</h2>\n", index,
                                html_text(part.title));
  out += "<h3>Set-up</h3>\n" + set_up_table(part);
  out += "<h3>Data</h3>\n" + figures(part);
  out += "<h3>Result</h3>\n" + results(part);
  if (!part.regime.empty())
    out += fmt::format("<p>Regime: <span data-field=\"regime\">{}</span>.</p>\n",
                       html_text(part.regime));
  out += "<h3>The periods</h3>\n<div class=\"periods\">" + periods_table(part) + "</div>\n";
  return out + "</section>\n";
}

std::string comparison(const ReportContent& c) {
  std::string out =
      "<section id=\"comparison\"><h2>Comparison</h2>\n<table><thead><tr><th>source</th><th>T "
      "(s)</th><th>μ<sub>k</sub></th></tr></thead><tbody>\n";
  for (const ReportPart& part : c.parts) {
    out += fmt::format("<tr><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td></tr>\n",
                       html_text(part.title), value_with_error(part.period, part.period_se, 4, ""),
                       value_with_error(part.mu_k, part.mu_k_err, 3, ""));
    if (part.period_thin.value && part.mu_k_set.value)
      out += fmt::format(
          "<tr><td>Theory for μ<sub>k</sub> = {} set: thin plate, π √(2 l / (μ<sub>k</sub> "
          "g)); with the plate's thickness</td><td class=\"n\">{}; {}</td><td "
          "class=\"n\">{}</td></tr>\n",
          fixed(*part.mu_k_set.value, 3),
          number(part.period_thin, fixed(*part.period_thin.value, 4)),
          part.period_thick.value ? number(part.period_thick, fixed(*part.period_thick.value, 4))
                                  : number(part.period_thick, ""),
          number(part.mu_k_set, fixed(*part.mu_k_set.value, 3)));
    if (part.mu_k_thick.value)
      out += fmt::format(
          "<tr><td>{}: μ<sub>k</sub> from T through the thick formula, 2π² l / (g T² + 4π² "
          "h<sub>c</sub>), with the plate's centre of mass h<sub>c</sub> above the "
          "contacts</td><td class=\"n\"></td><td class=\"n\">{}</td></tr>\n",
          html_text(part.title), number(part.mu_k_thick, fixed(*part.mu_k_thick.value, 3)));
  }
  bool any_paper = false;
  for (const ReportPart& part : c.parts) {
    if (!part.paper) continue;
    const ReportPaperRow& p = *part.paper;
    any_paper = true;
    out += fmt::format(
        "<tr><td>The paper's Table I: {}, {:.0f} K</td><td class=\"n\">{}</td><td "
        "class=\"n\">{}</td></tr>\n",
        html_text(p.material), p.temperature_k, plus_minus(p.period_s, p.period_err_s, 2, "±"),
        plus_minus(p.mu_k, p.mu_k_err, 2, "±"));
    break;
  }
  out += "</tbody></table>\n";
  if (!any_paper)
    out += "<p>The paper's Table I has no row for this material at this temperature.</p>\n";
  return out + "</section>\n";
}

std::string stopwatch(const ReportContent& c) {
  if (c.stopwatch.empty()) return "";
  std::string out =
      "<section id=\"stopwatch\"><h2>Timed by hand</h2>\n<table><thead><tr><th>periods</th><th>"
      "wall clock (s)</th><th>simulated (s)</th><th>T by hand (s)</th></tr></thead><tbody>\n";
  for (const StopwatchTiming& s : c.stopwatch) {
    const double timed = s.simulated_s.value_or(s.wall_s);
    out += fmt::format(
        "<tr><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td "
        "class=\"n\">{}</td></tr>\n",
        s.periods, fixed(s.wall_s, 2), s.simulated_s ? fixed(*s.simulated_s, 3) : "—",
        fixed(timed / s.periods, 3));
  }
  out +=
      "</tbody></table>\n<p class=\"why\">A press of the stopwatch is late or early by a "
      "reaction time, about 0.2 s: over ten periods that is 0.02 s in T.</p></section>\n";
  return out;
}

std::string method() {
  return fmt::format(
      "<section id=\"method\"><h2>Method</h2>\n<p>A plate lies on two rollers a distance l "
      "apart that turn in opposite senses, their tops toward each other. Kinetic friction at "
      "each contact is μ<sub>k</sub> times the roller's share of the plate's weight, and the "
      "nearer roller carries more: the difference pulls the plate back toward the middle with a "
      "force proportional to its offset. The plate oscillates with period T = π √(2 l / "
      "(μ<sub>k</sub> g)), so a measured period gives μ<sub>k</sub> = 2π² l / (g T²) ({}). A "
      "Hall sensor senses the magnets on the plate's ends; the rig's estimator times its "
      "pulses, keeps each period within 20 % of the running median, and averages "
      "them.</p></section>\n",
      kCitation);
}

}  // namespace

std::string report_html(const ReportContent& c) {
  std::string out = fmt::format(
      "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<meta "
      "name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>Lab report: "
      "the friction oscillator{}</title>\n<style>{}</style></head>\n<body>\n<header><h1>Lab "
      "report: the friction oscillator</h1>\n<p class=\"byline\">{}{}</p></header>\n",
      c.student.empty() ? "" : " — " + html_text(c.student), kStyle,
      c.student.empty() ? "" : "<span data-field=\"student\">" + html_text(c.student) + "</span>, ",
      html_text(c.date));
  out += method();
  int index = 0;
  for (const ReportPart& part : c.parts) out += part_section(part, ++index);
  out += comparison(c);
  out += stopwatch(c);
  out += fmt::format(
      "<footer>Made with {}: the simulation and the estimator of the rig's "
      "Arduino code; the method of {}.</footer>\n</body></html>\n",
      html_text(c.lab_version), kCitation);
  return out;
}

}  // namespace fl
