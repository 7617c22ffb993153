#include "lab/report/report_parts.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "hall_log/measurement_file.hpp"
#include "io/csv_table.hpp"
#include "text/decimal.hpp"

namespace fl {
namespace {

using nlohmann::json;

// A column of a run's CSV by its header's name, as numbers (NaN for a cell that is none).
std::vector<double> column(const CsvTable& table, std::string_view name, const std::string& file) {
  std::size_t c = 0;
  while (c < table.header.size() && table.header[c].text != name) ++c;
  if (c == table.header.size())
    throw std::invalid_argument(
        fmt::format("{}: expected a column {}, found none: is it a run's file?", file, name));
  std::vector<double> out;
  out.reserve(table.rows.size());
  for (const auto& row : table.rows) {
    const std::string& cell = row[c].text;
    double v = std::nan("");
    const auto read = read_decimal(cell.data(), cell.data() + cell.size(), v);
    if (read.ec != std::errc() || read.ptr != cell.data() + cell.size()) v = std::nan("");
    out.push_back(v);
  }
  return out;
}

ReportNumber field(const json& summary, const std::string& name) {
  const auto it = summary.find(name);
  if (it == summary.end() || !it->is_number()) return {std::nullopt, name};
  return {it->get<double>(), name};
}

std::string mm(double m) {
  return fmt::format("{:g} mm", std::round(m * 1e4) / 10.0);
}

// The paper's row the summary names (its material key, and the row whose T it holds).
std::optional<ReportPaperRow> paper_row(const json& summary, const PaperTable& table) {
  const auto paper = summary.find("paper");
  if (paper == summary.end() || !paper->is_object()) return std::nullopt;
  const PaperMaterial* material = table.find(paper->value("material", ""));
  if (!material) return std::nullopt;
  const double period = paper->value("period_s", 0.0);
  const PaperMeasurement& m = material->cold && std::fabs(material->cold->period.value - period) <
                                                    std::fabs(material->room.period.value - period)
                                  ? *material->cold
                                  : material->room;
  return ReportPaperRow{material->key,        material->name, m.temperature,     m.period.value,
                        m.period.uncertainty, m.mu_k.value,   m.mu_k.uncertainty};
}

}  // namespace

ReportPart simulation_part(const RunFiles& files, const std::string& source,
                           const PaperTable& table) {
  const std::optional<std::string> text = files("summary.json");
  if (!text)
    throw std::invalid_argument(fmt::format(
        "{}: expected a run's summary.json, found none: give the folder a run wrote its files "
        "into, or a measurement's file",
        source));
  const json summary = json::parse(*text, nullptr, false);
  if (!summary.is_object() || !summary.contains("period_s") || !summary.contains("spacing_m"))
    throw std::invalid_argument(fmt::format(
        "{}: its summary.json is not a run's summary (no period_s, no spacing_m)", source));
  ReportPart part;
  part.simulated = true;
  part.source = source;
  const std::string scene = summary.value("scene", "");
  part.title = scene.empty() ? source : scene;
  part.spacing_m = summary.at("spacing_m").get<double>();
  part.period = field(summary, "period_s");
  part.period_sd = field(summary, "period_std_s");
  part.period_se = field(summary, "period_std_error_s");
  part.periods_used = field(summary, "periods_used");
  part.mu_k = field(summary, "mu_k_estimator");
  part.mu_k_err = field(summary, "mu_k_err_quadrature");
  part.mu_k_err_worst = field(summary, "mu_k_err_worst");
  part.period_thin = field(summary, "period_thin_s");
  part.period_thick = field(summary, "period_thick_s");
  part.mu_k_set = field(summary, "mu_k_set");
  part.mu_k_thick = field(summary, "mu_k_recovered_thick");
  if (summary.contains("regime") && summary["regime"].is_string())
    part.regime = summary["regime"].get<std::string>();
  part.paper = paper_row(summary, table);

  part.set_up.push_back({"scene", scene, false});
  part.set_up.push_back({"spacing", mm(part.spacing_m)});
  if (const ReportNumber w = field(summary, "roller_speed_rad_s"); w.value)
    part.set_up.push_back({"speed", fmt::format("{:.0f} rpm", *w.value * 30.0 / std::numbers::pi)});
  if (part.paper)
    part.set_up.push_back({"plate", part.paper->material, false, "material-" + part.paper->key});
  if (part.mu_k_set.value)
    part.set_up.push_back({"mu-k-set", fmt::format("{:g}", *part.mu_k_set.value)});
  if (const ReportNumber h = field(summary, "h_c_m"); h.value)
    part.set_up.push_back({"h-c", mm(*h.value)});
  if (const ReportNumber m = field(summary, "plate_mass_kg"); m.value)
    part.set_up.push_back({"mass", fmt::format("{:.1f} g", *m.value * 1e3)});
  if (const ReportNumber d = field(summary, "duration_s"); d.value)
    part.set_up.push_back({"duration", fmt::format("{:g} s", *d.value)});
  if (const ReportNumber dt = field(summary, "time_step_s"); dt.value)
    part.set_up.push_back({"time-step", fmt::format("{:g} ms", *dt.value * 1e3)});
  if (const ReportNumber seed = field(summary, "seed"); seed.value)
    part.set_up.push_back({"seed", fmt::format("{:.0f}", *seed.value)});

  if (const auto csv_text = files("trajectory.csv")) {
    const CsvTable csv = parse_csv_table(*csv_text, "trajectory.csv");
    ReportCurve x{"x (mm)", column(csv, "t_s", "trajectory.csv"), {}};
    for (double v : column(csv, "x_m", "trajectory.csv")) x.value.push_back(v * 1e3);
    part.position = std::move(x);
  }
  if (const auto csv_text = files("hall.csv")) {
    const CsvTable csv = parse_csv_table(*csv_text, "hall.csv");
    ReportCurve signal{"Hall sensor (ADC counts)", {}, column(csv, "adc", "hall.csv")};
    for (double us : column(csv, "t_us", "hall.csv")) signal.t_s.push_back(us * 1e-6);
    part.signal = std::move(signal);
  }
  if (const auto csv_text = files("periods.csv")) {
    const CsvTable csv = parse_csv_table(*csv_text, "periods.csv");
    const std::vector<double> start = column(csv, "start_s", "periods.csv");
    const std::vector<double> end = column(csv, "end_s", "periods.csv");
    const std::vector<double> period = column(csv, "period_s", "periods.csv");
    std::size_t status = 0;
    while (status < csv.header.size() && csv.header[status].text != "status") ++status;
    for (std::size_t i = 0; i < period.size(); ++i)
      part.periods.push_back(
          {start[i], end[i], period[i],
           status < csv.header.size() && csv.rows[i][status].text == "accepted"});
  }
  return part;
}

ReportPart measurement_part(const HallLog& log, const LogEstimate& estimate,
                            const std::optional<PaperComparison>& paper) {
  ReportPart part;
  part.source = log.path;
  part.title = log.path;
  const LogSetUp& s = estimate.set_up;
  part.spacing_m = s.spacing;
  part.spacing_err_m = s.spacing_err;
  part.gravity_m_s2 = s.gravity;
  const fl_estimator::Stats& st = estimate.stats;
  const bool measured = st.periods_used > 0;
  const bool spread = st.periods_used >= 2;
  const auto value = [](bool known, double v, const char* name) {
    return ReportNumber{known ? std::optional<double>(v) : std::nullopt, name};
  };
  part.period = value(measured, static_cast<double>(st.period_s), "period_s");
  part.period_sd = value(spread, static_cast<double>(st.period_std_s), "period_std_s");
  part.period_se = value(spread, static_cast<double>(st.period_sem_s), "period_std_error_s");
  part.periods_used = value(true, st.periods_used, "periods_used");
  part.mu_k = value(measured, static_cast<double>(st.mu_k), "mu_k");
  part.mu_k_err = value(spread, static_cast<double>(st.mu_k_err_quadrature), "mu_k_err_quadrature");
  part.mu_k_err_worst = value(spread, static_cast<double>(st.mu_k_err_worst), "mu_k_err_worst");
  part.period_thin.field = "period_thin_s";
  part.period_thick.field = "period_thick_s";
  part.mu_k_set.field = "mu_k_set";
  part.mu_k_thick =
      value(mu_k_thick(estimate).has_value(), mu_k_thick(estimate).value_or(0.0), "mu_k_thick");
  part.set_up.push_back(
      {"instrument",
       instrument_words(log.instrument) + (log.channel.empty() ? "" : ", " + log.channel), false});
  part.set_up.push_back({"file", log.path, false});
  part.set_up.push_back(
      {"spacing", fmt::format("{:g} ± {:g} mm", s.spacing * 1e3, s.spacing_err * 1e3)});
  part.set_up.push_back({"gravity", fmt::format("{:g} m/s²", s.gravity)});
  part.set_up.push_back({"samples", fmt::format("{}, {:.2f} s, {:.0f} Hz", log.t_s.size(),
                                                estimate.duration, estimate.sample_rate)});
  if (paper) {
    part.set_up.push_back({"plate", paper->name, false, "material-" + paper->key});
    part.paper = ReportPaperRow{paper->key,
                                paper->name,
                                paper->temperature,
                                paper->period.value,
                                paper->period.uncertainty,
                                paper->mu_k.value,
                                paper->mu_k.uncertainty};
  }
  ReportCurve signal{instrument_words(log.instrument) + " (as read)", log.t_s, {}};
  signal.value.assign(log.adc.begin(), log.adc.end());
  part.signal = std::move(signal);
  for (const EstimatedPeriod& p : estimate.periods)
    part.periods.push_back({p.start, p.end, p.period, p.status == fl_estimator::kAccepted});
  return part;
}

ReportPart measurement_part(const MeasuredSummary& m) {
  ReportPart part;
  part.source = m.file;
  part.title = m.file;
  part.spacing_m = m.spacing_m;
  const bool spread = m.periods_used >= 2;
  const auto known = [](bool yes, double v, const char* name) {
    return ReportNumber{yes ? std::optional<double>(v) : std::nullopt, name};
  };
  part.period = {m.period_s, "period_s"};
  part.period_sd = known(spread, m.period_std_s, "period_std_s");
  part.period_se = known(spread, m.period_sem_s, "period_sem_s");
  part.periods_used = {m.periods_used, "periods_used"};
  part.mu_k = {m.mu_k, "mu_k"};
  part.mu_k_err = known(spread, m.mu_k_err_quadrature, "mu_k_err_quadrature");
  part.mu_k_err_worst = known(spread, m.mu_k_err_worst, "mu_k_err_worst");
  part.period_thin.field = "period_thin_s";
  part.period_thick.field = "period_thick_s";
  part.mu_k_set.field = "mu_k_set";
  part.mu_k_thick.field = "mu_k_thick";
  part.set_up.push_back(
      {"instrument", m.instrument + (m.channel.empty() ? "" : ", " + m.channel), false});
  part.set_up.push_back({"file", m.file, false});
  part.set_up.push_back({"spacing", mm(m.spacing_m)});
  part.set_up.push_back({"samples", fmt::format("{:.0f}, {:.2f} s, {:.0f} Hz", m.samples,
                                                m.duration_s, m.sample_rate_hz)});
  return part;
}

}  // namespace fl
