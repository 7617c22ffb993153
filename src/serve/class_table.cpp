#include "serve/class_table.hpp"

#include <string_view>

#include <fmt/format.h>

#include "api/api_fields.hpp"
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
                const std::optional<BoardFeedStatus>& rig) {
  json sessions = json::array();
  for (const ClassRow& row : rows) sessions.push_back(row_json(row, table));
  json live = nullptr;
  if (rig) live = {{"port", rig->port}, {"state", rig->state}, {"lines", rig->lines}};
  return {{"sessions", std::move(sessions)}, {"rig", std::move(live)}};
}

std::string class_csv(const std::vector<ClassRow>& rows, const PaperTable& table) {
  // The columns the web API declares for a class row (api/api_fields.hpp), in its order.
  std::vector<const api::ApiKey*> columns;
  for (const api::ApiObject& o : api::api_declaration().objects)
    if (std::string_view(o.name) == "ClassRow")
      for (const api::ApiKey& k : o.keys)
        if (k.csv != nullptr) columns.push_back(&k);
  std::string out;
  for (const api::ApiKey* k : columns) out += std::string(out.empty() ? "" : ",") + k->csv;
  out += '\n';
  const auto cell = [](const json& v, double scale) -> std::string {
    if (v.is_null()) return "";
    if (v.is_number()) return fmt::format("{:.10g}", v.get<double>() * scale);
    return csv_cell(v.get<std::string>());
  };
  for (const ClassRow& row : rows) {
    const json r = row_json(row, table);
    std::string line;
    for (const api::ApiKey* k : columns) {
      if (k != columns.front()) line += ',';
      line += cell(r.at(k->name), k->csv_scale);
    }
    out += line + '\n';
  }
  return out;
}

}  // namespace fl::serve
