#include "lab/report/report_html.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "io/plus_minus.hpp"
#include "lab/report/svg_plot.hpp"
#include "text/html_text.hpp"

namespace fl {

std::string ReportTexts::operator()(const std::string& id,
                                    const std::map<std::string, std::string>& args) const {
  if (std::optional<std::string> text = language.format(id, args)) return *text;
  if (std::optional<std::string> text = english.format(id, args)) return *text;
  return id;
}

std::string ReportTexts::named(const std::string& id, const std::string& given) const {
  if (std::optional<std::string> text = language.format(id)) return *text;
  if (std::optional<std::string> text = english.format(id)) return *text;
  return given;
}

std::string ReportTexts::decimal_sign() const {
  const std::string sign = (*this)("report-decimal-sign");
  return sign == "," ? "," : ".";
}

namespace {

// The paper, as its journal prints it (a citation is not translated).
constexpr const char* kCitation =
    "R. Henaff, G. Le Doudic, B. Pilette, C. Even, J.-M. Fischbach, F. Bouquet, J. Bobroff, "
    "M. Monteverde and C. A. Marrache-Kikuchi, “A study of kinetic friction: The Timoshenko "
    "oscillator”, American Journal of Physics 86, 174 (2018)";

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
.rejected { color: #8a1c00; }
footer { margin-top: 2em; font-size: 9pt; color: #444; }
@page { margin: 15mm; }
@media print {
  body { margin: 0; padding: 0; max-width: none; font-size: 10pt; }
  h2 { break-after: avoid; }
  table, figure, .result { break-inside: avoid; }
  thead { display: table-header-group; }
}
)";

// What the report's pieces share: its texts, and numbers in its language.
class Writer {
 public:
  explicit Writer(const ReportTexts& texts) : t(texts), sign_(texts.decimal_sign()) {}

  const ReportTexts& t;

  // A number's text in the report's language (its decimal sign).
  std::string shown(std::string text) const {
    if (sign_ != ".") std::replace(text.begin(), text.end(), '.', sign_[0]);
    return text;
  }
  std::string fixed(double v, int decimals) const {
    return shown(fmt::format("{:.{}f}", v, decimals));
  }
  std::string both(double value, double error, int decimals) const {
    return shown(plus_minus(value, error, decimals, "±"));
  }
  std::string sign() const { return sign_; }

 private:
  std::string sign_;
};

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

std::string value_with_error(const Writer& w, const ReportNumber& value, const ReportNumber& error,
                             int decimals, const std::string& unit) {
  if (!value.value) return number(value, "");
  if (!error.value)
    return number(value, w.fixed(*value.value, decimals)) + " ± " + number(error, "") + unit +
           " (" + html_text(w.t("report-no-spread")) + ")";
  const std::string text = w.both(*value.value, *error.value, decimals);
  const std::size_t at = text.find(" ± ");
  return number(value, text.substr(0, at)) + " ± " + number(error, text.substr(at + 4)) + unit;
}

std::string title_of(const Writer& w, const ReportPart& part) {
  return w.t(part.simulated ? "report-simulation-title" : "report-measurement-title",
             {{"name", part.title}});
}

std::string set_up_table(const Writer& w, const ReportPart& part) {
  std::string out = "<table class=\"set-up\"><tbody>\n";
  for (const SetUpRow& row : part.set_up)
    out += fmt::format("<tr><th scope=\"row\">{}</th><td>{}</td></tr>\n",
                       html_text(w.t("report-setup-" + row.id)),
                       html_text(row.numeric           ? w.shown(row.value)
                                 : row.message.empty() ? row.value
                                                       : w.t.named(row.message, row.value)));
  return out + "</tbody></table>\n";
}

std::string figure(const Writer& w, SvgPlot plot, const std::string& caption) {
  plot.decimal_sign = w.sign();
  return "<figure>\n" + svg_line_plot(plot) +
         fmt::format("<figcaption>{}</figcaption></figure>\n", html_text(caption));
}

std::string figures(const Writer& w, const ReportPart& part) {
  std::string out;
  const std::string time = w.t("report-axis-time");
  if (part.position) {
    const std::string label = w.t("report-axis-position");
    out += figure(w, {label, time, label, {{part.position->t_s, part.position->value, "", kBlue}}},
                  w.t("report-position-caption"));
  }
  if (part.signal) {
    const std::string label =
        part.simulated ? w.t("report-axis-hall") : part.signal->label;  // the instrument's words
    out += figure(w, {label, time, label, {{part.signal->t_s, part.signal->value, "", kBlue}}},
                  w.t(part.simulated ? "report-hall-caption" : "report-measurement-caption"));
  }
  if (!part.periods.empty()) {
    SvgSeries accepted{{}, {}, w.t("report-accepted"), kBlue, true};
    SvgSeries rejected{{}, {}, w.t("report-discarded"), kOrange, true};
    for (const ReportPeriod& p : part.periods) {
      SvgSeries& into = p.accepted ? accepted : rejected;
      into.x.push_back(p.start_s);
      into.y.push_back(p.period_s);
    }
    SvgPlot plot{w.t("report-periods-plot"),
                 w.t("report-axis-start"),
                 w.t("report-axis-period"),
                 {accepted}};
    if (!rejected.x.empty()) plot.series.push_back(rejected);
    out += figure(w, plot, w.t("report-periods-caption"));
  }
  return out;
}

std::string periods_table(const Writer& w, const ReportPart& part) {
  if (part.periods.empty()) return "<p>" + html_text(w.t("report-no-period")) + "</p>\n";
  std::string out = fmt::format(
      "<table class=\"periods-table\"><thead><tr><th>#</th><th>{}</th><th>{}</th><th>{}</th>"
      "<th>{}</th></tr></thead><tbody>\n",
      html_text(w.t("report-column-start")), html_text(w.t("report-column-end")),
      html_text(w.t("report-axis-period")), html_text(w.t("report-column-accepted")));
  int i = 0;
  for (const ReportPeriod& p : part.periods)
    out += fmt::format(
        "<tr{}><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td "
        "class=\"n\" data-value=\"{}\">{}</td><td>{}</td></tr>\n",
        p.accepted ? "" : " class=\"rejected\"", ++i, w.fixed(p.start_s, 4), w.fixed(p.end_s, 4),
        exact(p.period_s), w.fixed(p.period_s, 4),
        html_text(w.t(p.accepted ? "report-yes" : "report-no-beyond-median")));
  return out + "</tbody></table>\n";
}

std::string results(const Writer& w, const ReportPart& part) {
  std::string out;
  out += "<p class=\"result\">T = " + value_with_error(w, part.period, part.period_se, 4, " s") +
         "</p>\n";
  // The messages' own text is escaped; the numbers' marks are added after.
  const std::string count = "\x01", sd = "\x02";
  std::string why = html_text(w.t("report-period-why", {{"count", count}, {"sd", sd}}));
  const auto put = [&why](const std::string& mark, const std::string& html) {
    if (const std::size_t at = why.find(mark); at != std::string::npos) why.replace(at, 1, html);
  };
  put(count,
      number(part.periods_used,
             part.periods_used.value ? fmt::format("{:.0f}", *part.periods_used.value) : ""));
  put(sd, number(part.period_sd, part.period_sd.value ? w.fixed(*part.period_sd.value, 5) : ""));
  out += "<p class=\"why\">" + why + "</p>\n";
  out += "<p class=\"result\">μ<sub>k</sub> = " +
         value_with_error(w, part.mu_k, part.mu_k_err, 3, "") + "</p>\n";
  const std::string worst = "\x03";
  std::string mu_why =
      html_text(w.t("report-mu-k-why", {{"spacing", w.fixed(part.spacing_m * 1e3, 1)},
                                        {"gravity", w.fixed(part.gravity_m_s2, 2)},
                                        {"dl", w.fixed(part.spacing_err_m * 1e3, 1)},
                                        {"worst", worst}}));
  if (const std::size_t at = mu_why.find(worst); at != std::string::npos)
    mu_why.replace(at, 1,
                   number(part.mu_k_err_worst,
                          part.mu_k_err_worst.value ? w.fixed(*part.mu_k_err_worst.value, 4) : ""));
  out += "<p class=\"why\">" + mu_why + "</p>\n";
  return out;
}

std::string part_section(const Writer& w, const ReportPart& part, int index) {
  std::string out = fmt::format("<section class=\"part\" id=\"part-{}\"><h2>{}</h2>\n", index,
                                html_text(title_of(w, part)));
  out += "<h3>" + html_text(w.t("report-set-up")) + "</h3>\n" + set_up_table(w, part);
  out += "<h3>" + html_text(w.t("report-data")) + "</h3>\n" + figures(w, part);
  out += "<h3>" + html_text(w.t("report-result")) + "</h3>\n" + results(w, part);
  if (!part.regime.empty()) {
    std::string id =
        "report-regime-" + part.regime;  // "no restoring force": ...-no-restoring-force
    std::replace(id.begin(), id.end(), ' ', '-');
    const std::string regime = w.t(id);
    out += "<p>" +
           html_text(w.t("report-regime", {{"regime", regime == id ? part.regime : regime}})) +
           "</p>\n";
  }
  out += "<h3>" + html_text(w.t("report-periods")) + "</h3>\n" + periods_table(w, part);
  return out + "</section>\n";
}

std::string comparison(const Writer& w, const ReportContent& c) {
  std::string out = fmt::format(
      "<section id=\"comparison\"><h2>{}</h2>\n<table><thead><tr><th>{}</th><th>T "
      "(s)</th><th>μ<sub>k</sub></th></tr></thead><tbody>\n",
      html_text(w.t("report-comparison")), html_text(w.t("report-source")));
  const auto row = [&out](const std::string& what, const std::string& period,
                          const std::string& mu) {
    out += fmt::format("<tr><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td></tr>\n",
                       html_text(what), period, mu);
  };
  for (const ReportPart& part : c.parts) {
    row(title_of(w, part), value_with_error(w, part.period, part.period_se, 4, ""),
        value_with_error(w, part.mu_k, part.mu_k_err, 3, ""));
    if (part.period_thin.value && part.mu_k_set.value)
      row(w.t("report-theory-row", {{"mu", w.fixed(*part.mu_k_set.value, 3)}}),
          number(part.period_thin, w.fixed(*part.period_thin.value, 4)) + "; " +
              (part.period_thick.value
                   ? number(part.period_thick, w.fixed(*part.period_thick.value, 4))
                   : number(part.period_thick, "")),
          number(part.mu_k_set, w.fixed(*part.mu_k_set.value, 3)));
    if (part.mu_k_thick.value)
      row(w.t("report-thick-row", {{"name", title_of(w, part)}}), "",
          number(part.mu_k_thick, w.fixed(*part.mu_k_thick.value, 3)));
  }
  const auto paper = std::find_if(c.parts.begin(), c.parts.end(),
                                  [](const ReportPart& p) { return p.paper.has_value(); });
  if (paper != c.parts.end()) {
    const ReportPaperRow& p = *paper->paper;
    row(w.t("report-paper-row", {{"material", w.t.named("material-" + p.key, p.material)},
                                 {"kelvin", fmt::format("{:.0f}", p.temperature_k)}}),
        w.both(p.period_s, p.period_err_s, 2), w.both(p.mu_k, p.mu_k_err, 2));
  }
  out += "</tbody></table>\n";
  if (paper == c.parts.end()) out += "<p>" + html_text(w.t("report-no-paper-row")) + "</p>\n";
  return out + "</section>\n";
}

std::string stopwatch(const Writer& w, const ReportContent& c) {
  if (c.stopwatch.empty()) return "";
  std::string out = fmt::format(
      "<section id=\"stopwatch\"><h2>{}</h2>\n<table><thead><tr><th>{}</th><th>{}</th><th>{}"
      "</th><th>{}</th></tr></thead><tbody>\n",
      html_text(w.t("report-stopwatch")), html_text(w.t("report-column-periods")),
      html_text(w.t("report-column-wall")), html_text(w.t("report-column-simulated")),
      html_text(w.t("report-column-by-hand")));
  for (const StopwatchTiming& s : c.stopwatch) {
    const double timed = s.simulated_s.value_or(s.wall_s);
    out += fmt::format(
        "<tr><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td "
        "class=\"n\">{}</td></tr>\n",
        s.periods, w.fixed(s.wall_s, 2), s.simulated_s ? w.fixed(*s.simulated_s, 3) : "—",
        w.fixed(timed / s.periods, 3));
  }
  return out + "</tbody></table>\n<p class=\"why\">" + html_text(w.t("report-stopwatch-why")) +
         "</p></section>\n";
}

}  // namespace

std::string report_html(const ReportContent& c, const ReportTexts& texts) {
  const Writer w(texts);
  const std::string title = w.t("report-title");
  std::string out = fmt::format(
      "<!doctype html>\n<html lang=\"{}\"><head><meta charset=\"utf-8\">\n<meta "
      "name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>{}{}</title>\n"
      "<style>{}</style></head>\n<body>\n<header><h1>{}</h1>\n<p class=\"byline\">{}{}</p>"
      "</header>\n",
      html_text(c.language), html_text(title),
      c.student.empty() ? "" : " — " + html_text(c.student), kStyle, html_text(title),
      c.student.empty() ? "" : "<span data-field=\"student\">" + html_text(c.student) + "</span>, ",
      html_text(c.date));
  out += fmt::format("<section id=\"method\"><h2>{}</h2>\n<p>{}</p></section>\n",
                     html_text(w.t("report-method")),
                     html_text(w.t("report-method-text", {{"citation", kCitation}})));
  int index = 0;
  for (const ReportPart& part : c.parts) out += part_section(w, part, ++index);
  out += comparison(w, c);
  out += stopwatch(w, c);
  out += fmt::format(
      "<footer>{}</footer>\n</body></html>\n",
      html_text(w.t("report-footer", {{"version", c.lab_version}, {"citation", kCitation}})));
  return out;
}

}  // namespace fl
