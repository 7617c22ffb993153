#include "lab/request/table_request.hpp"

#include <algorithm>

#include "io/paper_table_yaml.hpp"
#include "lab/request/lab_data.hpp"

namespace fl {

int TableResult::disagreements() const {
  return static_cast<int>(
      std::count_if(rows.begin(), rows.end(), [](const TableRow& r) { return r.disagrees(); }));
}

nlohmann::json TableResult::json() const {
  nlohmann::json out_rows = nlohmann::json::array();
  for (const TableRow& r : rows) {
    const PaperMeasurement& m = r.measured;
    nlohmann::json row{{"material", r.material.key},
                       {"name", r.material.name},
                       {"temperature_k", m.temperature},
                       {"period_s", m.period.value},
                       {"period_err_s", m.period.uncertainty},
                       {"mu_k_paper", m.mu_k.value},
                       {"mu_k_paper_err", m.mu_k.uncertainty},
                       {"mu_k_recomputed", r.thin.mu.mu_k},
                       {"mu_k_err_worst", r.thin.mu.worst},
                       {"mu_k_err_quadrature", r.thin.mu.quadrature},
                       {"mu_k_thick", r.thick.mu_k},
                       {"mu_k_thick_err_worst", r.thick.worst},
                       {"printed_mu_k_agrees", r.thin.mu_k_agrees},
                       {"printed_err_agrees", r.thin.uncertainty_agrees}};
    if (r.material.literature && m.temperature > 100.0)
      row["literature"] = {r.material.literature->low, r.material.literature->high};
    out_rows.push_back(row);
  }
  return {{"source", table.source},
          {"spacing_m", table.spacing.value},
          {"spacing_err_m", table.spacing.uncertainty},
          {"gravity_m_s2", gravity},
          {"h_c_m", h_c},
          {"rows", out_rows},
          {"rows_disagreeing", disagreements()}};
}

TableResult paper_table_recomputed(const TableRequest& r) {
  FieldChecks checks;
  const double gravity = checks.positive(r.gravity, Dimension::kAcceleration, "gravity", "g");
  const double h_c = checks.not_negative(r.h_c, Dimension::kLength, "h_c", "a height");
  checks.plausible(gravity, kGravityRange, "gravity", r.gravity);
  checks.plausible(h_c, kHcRange, "h_c", r.h_c);
  checks.throw_if_any();
  TableResult out;
  out.file = paper_table_path(asset_dir(r.assets));
  out.table = load_paper_table(out.file);
  out.gravity = gravity;
  out.h_c = h_c;
  for (const PaperMaterial& material : out.table.materials) {
    for (const PaperMeasurement* m : {&material.room, material.cold ? &*material.cold : nullptr}) {
      if (m == nullptr) continue;
      out.rows.push_back(TableRow{
          material, *m, recompute(*m, out.table.spacing, gravity),
          mu_k_with_uncertainty(m->period.value, m->period.uncertainty, out.table.spacing.value,
                                out.table.spacing.uncertainty, h_c, gravity)});
    }
  }
  return out;
}

}  // namespace fl
