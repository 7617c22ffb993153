#include "lab/logs/log_table.hpp"

#include <filesystem>
#include <type_traits>
#include <variant>

#include <fmt/format.h>

#include "io/csv_table.hpp"
#include "io/field_ref.hpp"
#include "io/input_error.hpp"
#include "io/json_value.hpp"
#include "lab/logs/checked_reading.hpp"
#include "lab/logs/geometry_check.hpp"
#include "lab/logs/log_table_fields.hpp"
#include "text/utf8.hpp"

namespace fl {

LogSetUp set_up_for_log(const std::string& log_file, const LogSetUp& set_up, std::string* note,
                        std::optional<LogSidecar>* sidecar, const PaperTable* materials) {
  LogSetUp out = set_up;
  const std::optional<LogSidecar> side = read_log_sidecar(log_file, materials);
  if (sidecar != nullptr) *sidecar = side;
  if (side) {
    apply_log_sidecar(*side, out);
    if (note != nullptr)
      *note = fmt::format("the rig from {}: l = {:.1f} +- {:.1f} mm, g = {} m/s^2", side->file,
                          out.spacing * 1e3, out.spacing_err * 1e3, out.gravity);
  }
  return out;
}

void apply_log_sidecar(const LogSidecar& side, LogSetUp& set_up) {
  if (side.spacing) set_up.spacing = *side.spacing;
  if (side.spacing_err) set_up.spacing_err = *side.spacing_err;
  if (side.gravity) set_up.gravity = *side.gravity;
  // The sidecar reader accepts only the names geometry_from_option knows.
  if (side.geometry)
    set_up.geometry = geometry_from_option(*side.geometry).value_or(fl_estimator::kAutoGeometry);
}

LogTableRow estimate_log_row(const std::string& log, const LogTableDefaults& defaults) {
  LogTableRow row;
  row.log = log;
  row.label =
      log == "-" ? "<stdin>" : escape_invalid_utf8(std::filesystem::path(log).filename().string());
  row.set_up = defaults.set_up;
  row.material = defaults.material;
  row.temperature = defaults.temperature;
  try {
    if (const std::optional<LogSidecar> side = read_log_sidecar(log, defaults.paper)) {
      row.sidecar = side->file;
      if (side->label) row.label = *side->label;
      apply_log_sidecar(*side, row.set_up);
      if (side->material) row.material = side->material;
      if (side->temperature) row.temperature = side->temperature;
    }
    const HallLog hall = read_hall_log_checked(log, defaults.reading, defaults.set_up);
    const LogEstimate est = estimate_log(hall, row.set_up, false);
    require_periods(hall, est, "");
    require_geometry(hall, est, check_geometry(hall, est), "");
    require_plausible(hall, est, "");
    const fl_estimator::Stats& s = est.stats;
    row.status = "ok";
    row.geometry = geometry_name(est.geometry);
    row.periods_used = static_cast<int>(s.periods_used);
    row.periods_discarded = static_cast<int>(s.periods_discarded);
    row.period = s.period_s;
    row.period_err = s.period_sem_s;
    row.period_std = s.period_std_s;
    row.mu_k = s.mu_k;
    row.mu_k_err_worst = s.mu_k_err_worst;
    row.mu_k_err_quadrature = s.mu_k_err_quadrature;
  } catch (const std::exception& e) {
    // InputError (the log, its sidecar) and what reading a file can throw: the row says it.
    row.status = "failed";
    row.error = plain_fields(e.what());
  }
  return row;
}

std::string log_table_csv(const std::vector<LogTableRow>& rows) {
  std::string csv;
  for (const LogTableField& f : log_table_fields())
    if (f.csv != nullptr) csv += std::string(csv.empty() ? "" : ",") + f.csv;
  csv += '\n';
  for (const LogTableRow& r : rows) {
    std::string line;
    bool first = true;
    for (const LogTableField& f : log_table_fields()) {
      if (f.csv == nullptr) continue;
      if (!first) line += ',';
      first = false;
      line += std::visit(
          [&f](const auto& v) -> std::string {
            using V = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<V, std::monostate>)
              return "";
            else if constexpr (std::is_same_v<V, double>)
              return fmt::format("{}{}", v, f.csv_unit);
            else if constexpr (std::is_same_v<V, std::string>)
              return csv_cell(v);
            else if constexpr (std::is_same_v<V, std::int64_t> || std::is_same_v<V, std::uint64_t>)
              return std::to_string(v);
            else
              return nlohmann::json(v).dump();
          },
          f.get(r).value());
    }
    csv += line + '\n';
  }
  return csv;
}

nlohmann::json log_table_json(const std::vector<LogTableRow>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const LogTableRow& r : rows) {
    nlohmann::json row = nlohmann::json::object();
    for (const LogTableField& f : log_table_fields())
      if (f.json != nullptr) row[f.json] = f.get(r).json();
    out.push_back(std::move(row));
  }
  return out;
}

}  // namespace fl
