#include "lab/logs/log_table.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "core/utf8.hpp"
#include "io/csv_table.hpp"
#include "io/field_ref.hpp"
#include "io/input_error.hpp"
#include "io/json_value.hpp"
#include "lab/logs/checked_reading.hpp"
#include "lab/logs/geometry_check.hpp"

namespace fl {
namespace {

// A text for JSON: a file name that is not UTF-8 escaped (core/utf8.hpp).
nlohmann::json text_or_null(const std::string& text) {
  return text.empty() ? nlohmann::json(nullptr) : nlohmann::json(escape_invalid_utf8(text));
}

std::string number(const std::optional<double>& v) {
  return v ? fmt::format("{}", *v) : std::string();
}

}  // namespace

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
  std::string csv =
      "label,log,status,rollers.spacing,spacing_err,plate.material,friction.temperature,period,"
      "period_err,period_std,periods_used,periods_discarded,mu_k,mu_k_err_worst,"
      "mu_k_err_quadrature,error\n";
  for (const LogTableRow& r : rows) {
    csv += fmt::format("{},{},{},{} m,{} m,{},{},{},{},{},{},{},{},{},{},{}\n",
                       csv_cell(escape_invalid_utf8(r.label)), csv_cell(escape_invalid_utf8(r.log)),
                       r.status, r.set_up.spacing, r.set_up.spacing_err,
                       csv_cell(r.material.value_or("")),
                       r.temperature ? fmt::format("{} K", *r.temperature) : std::string(),
                       number(r.period), number(r.period_err), number(r.period_std),
                       r.periods_used ? std::to_string(*r.periods_used) : std::string(),
                       r.periods_discarded ? std::to_string(*r.periods_discarded) : std::string(),
                       number(r.mu_k), number(r.mu_k_err_worst), number(r.mu_k_err_quadrature),
                       csv_cell(escape_invalid_utf8(r.error)));
  }
  return csv;
}

nlohmann::json log_table_json(const std::vector<LogTableRow>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const LogTableRow& r : rows) {
    const auto maybe_int = [](const std::optional<int>& v) {
      return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
    };
    out.push_back({{"label", escape_invalid_utf8(r.label)},
                   {"log", escape_invalid_utf8(r.log)},
                   {"sidecar", text_or_null(r.sidecar)},
                   {"status", r.status},
                   {"error", text_or_null(r.error)},
                   {"spacing_m", r.set_up.spacing},
                   {"spacing_err_m", r.set_up.spacing_err},
                   {"gravity_m_s2", r.set_up.gravity},
                   {"material", text_or_null(r.material.value_or(""))},
                   {"temperature_k", json_or_null(r.temperature)},
                   {"geometry", text_or_null(r.geometry)},
                   {"periods_used", maybe_int(r.periods_used)},
                   {"periods_discarded", maybe_int(r.periods_discarded)},
                   {"period_s", json_or_null(r.period)},
                   {"period_err_s", json_or_null(r.period_err)},
                   {"period_std_s", json_or_null(r.period_std)},
                   {"mu_k", json_or_null(r.mu_k)},
                   {"mu_k_err_worst", json_or_null(r.mu_k_err_worst)},
                   {"mu_k_err_quadrature", json_or_null(r.mu_k_err_quadrature)}});
  }
  return out;
}

}  // namespace fl
