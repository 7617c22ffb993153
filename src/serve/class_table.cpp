#include "serve/class_table.hpp"

#include <fmt/format.h>

#include "io/csv_table.hpp"
#include "io/json_value.hpp"

namespace fl::serve {
namespace {

using nlohmann::json;

// The paper's row for the rig's material, when its friction is the paper's.
const PaperMaterial* paper_row(const CompiledRig& rig, const PaperTable& table) {
  const FrictionSource& source = rig.friction_source;
  return source.paper_material ? table.find(*source.paper_material) : nullptr;
}

std::optional<double> paper_value(const std::optional<Measured>& m) {
  return m ? std::optional<double>(m->value) : std::nullopt;
}

json row_json(const ClassRow& row, const PaperTable& table) {
  const CompiledRig& rig = *row.rig;
  const PaperMaterial* paper = paper_row(rig, table);
  const SessionStanding& s = row.standing;
  return {{"session", row.session},
          {"name", row.name.empty() ? json(nullptr) : json(row.name)},
          {"scene", row.scene},
          {"material", paper != nullptr ? json(paper->name) : json(nullptr)},
          {"temperature_k", rig.friction_source.temperature},
          {"spacing", rig.rollers.spacing},
          {"h_c", rig.plate.h_c},
          {"state", s.state},
          {"t", s.t},
          {"period", json_or_null(s.period)},
          {"period_err", json_or_null(s.period_err)},
          {"period_from", s.period_from.empty() ? json(nullptr) : json(s.period_from)},
          {"mu_k", json_or_null(s.mu_k)},
          {"mu_k_err", json_or_null(s.mu_k_err)},
          {"paper_period", json_or_null(paper_value(rig.friction_source.paper_period))},
          {"paper_mu_k", json_or_null(paper_value(rig.friction_source.paper_mu_k))}};
}

}  // namespace

json class_json(const std::vector<ClassRow>& rows, const PaperTable& table,
                const std::optional<RigFeedStatus>& rig) {
  json sessions = json::array();
  for (const ClassRow& row : rows) sessions.push_back(row_json(row, table));
  json live = nullptr;
  if (rig) live = {{"port", rig->port}, {"state", rig->state}, {"lines", rig->lines}};
  return {{"sessions", std::move(sessions)}, {"rig", std::move(live)}};
}

std::string class_csv(const std::vector<ClassRow>& rows, const PaperTable& table) {
  static const char* const kColumns[] = {
      "session",       "name",       "scene",          "material",
      "temperature_k", "spacing_mm", "h_c_mm",         "state",
      "t_s",           "period_s",   "period_err_s",   "period_from",
      "mu_k",          "mu_k_err",   "paper_period_s", "paper_mu_k"};
  std::string out;
  for (const char* column : kColumns) out += std::string(out.empty() ? "" : ",") + column;
  out += '\n';
  const auto cell = [](const json& v, double scale = 1.0) -> std::string {
    if (v.is_null()) return "";
    if (v.is_number()) return fmt::format("{:.10g}", v.get<double>() * scale);
    return csv_cell(v.get<std::string>());
  };
  for (const ClassRow& row : rows) {
    const json r = row_json(row, table);
    out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", cell(r["session"]),
                       cell(r["name"]), cell(r["scene"]), cell(r["material"]),
                       cell(r["temperature_k"]), cell(r["spacing"], 1e3), cell(r["h_c"], 1e3),
                       cell(r["state"]), cell(r["t"]), cell(r["period"]), cell(r["period_err"]),
                       cell(r["period_from"]), cell(r["mu_k"]), cell(r["mu_k_err"]),
                       cell(r["paper_period"]), cell(r["paper_mu_k"]));
  }
  return out;
}

}  // namespace fl::serve
