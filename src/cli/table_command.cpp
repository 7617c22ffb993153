// frictionlab table: the paper's Table I, with mu_k recomputed from each measured period.
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/option_quantity.hpp"
#include "core/paper_table.hpp"
#include "io/paper_table_yaml.hpp"
#include "lab/request/field_checks.hpp"
#include "lab/request/lab_data.hpp"

namespace fl::cli {
namespace {

struct TableOptions {
  std::string gravity = "9.81 m/s^2";
  std::string h_c = "0 mm";
  bool json = false;
};

int run_table(const TableOptions& o, const GlobalOptions& global) {
  FieldChecks checks;
  const double gravity = checks.positive(o.gravity, Dimension::kAcceleration, "gravity", "g");
  const double h_c = checks.not_negative(o.h_c, Dimension::kLength, "h_c", "a height");
  checks.plausible(gravity, kGravityRange, "gravity", o.gravity);
  checks.plausible(h_c, kHcRange, "h_c", o.h_c);
  checks.throw_if_any();
  const std::string file = paper_table_path(asset_dir(global.asset_dir));
  const PaperTable table = load_paper_table(file);

  nlohmann::json rows = nlohmann::json::array();
  std::string text;
  int disagreements = 0;
  for (const PaperMaterial& material : table.materials) {
    for (const PaperMeasurement* m : {&material.room, material.cold ? &*material.cold : nullptr}) {
      if (m == nullptr) continue;
      const RecomputedRow r = recompute(*m, table.spacing, gravity);
      const MuKUncertainty thick =
          mu_k_with_uncertainty(m->period.value, m->period.uncertainty, table.spacing.value,
                                table.spacing.uncertainty, h_c, gravity);
      std::string remark;
      if (!r.mu_k_agrees) remark += fmt::format(" mu_k rounds to {}", r.mu_k_rounded);
      if (!r.uncertainty_agrees) remark += fmt::format(" d mu_k rounds to {}", r.worst_rounded);
      if (!remark.empty()) ++disagreements;
      nlohmann::json row{{"material", material.key},
                         {"name", material.name},
                         {"temperature_k", m->temperature},
                         {"period_s", m->period.value},
                         {"period_err_s", m->period.uncertainty},
                         {"mu_k_paper", m->mu_k.value},
                         {"mu_k_paper_err", m->mu_k.uncertainty},
                         {"mu_k_recomputed", r.mu.mu_k},
                         {"mu_k_err_worst", r.mu.worst},
                         {"mu_k_err_quadrature", r.mu.quadrature},
                         {"mu_k_thick", thick.mu_k},
                         {"mu_k_thick_err_worst", thick.worst},
                         {"printed_mu_k_agrees", r.mu_k_agrees},
                         {"printed_err_agrees", r.uncertainty_agrees}};
      if (material.literature && m->temperature > 100.0)
        row["literature"] = {material.literature->low, material.literature->high};
      rows.push_back(row);
      text += fmt::format(
          "  {:<27} {:>4.0f} K  {:>5.2f} +- {:<4.2f} s  {:>6} +- {:<6}  {:>7.4f} +- {:<6.4f} "
          "+- {:<6.4f}  {:>7.4f}{}\n",
          material.name, m->temperature, m->period.value, m->period.uncertainty,
          fmt::format("{:.{}f}", m->mu_k.value, m->mu_k.decimals),
          fmt::format("{:.{}f}", m->mu_k.uncertainty, m->mu_k.uncertainty_decimals), r.mu.mu_k,
          r.mu.worst, r.mu.quadrature, thick.mu_k, remark.empty() ? "" : "  <-" + remark);
    }
  }
  if (o.json) {
    const nlohmann::json out{{"source", table.source},
                             {"spacing_m", table.spacing.value},
                             {"spacing_err_m", table.spacing.uncertainty},
                             {"gravity_m_s2", gravity},
                             {"h_c_m", h_c},
                             {"rows", rows},
                             {"rows_disagreeing", disagreements}};
    fmt::print("{}\n", out.dump(2));
    return 0;
  }
  fmt::print("The paper's Table I ({}), l = {:.0f} +- {:.0f} mm, g = {} m/s^2\n", file,
             table.spacing.value * 1e3, table.spacing.uncertainty * 1e3, gravity);
  fmt::print(
      "mu_k recomputed = 2 pi^2 l / (g T^2), +- worst case (dl/l + 2 dT/T) +- quadrature; "
      "thick: h_c = {:.1f} mm\n\n",
      h_c * 1e3);
  fmt::print("  {:<27} {:>6}  {:^18}  {:^16}  {:^31}  {:>7}\n", "material", "temp", "T measured",
             "mu_k printed", "mu_k recomputed", "thick");
  fmt::print("{}", text);
  fmt::print(
      "\n{} row(s) where the printed mu_k or its uncertainty is not what the printed T, dT, l "
      "and dl give (marked <-).\n",
      disagreements);
  return 0;
}

}  // namespace

Command add_table_command(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<TableOptions>();
  CLI::App* sub =
      app.add_subcommand("table", "The paper's Table I with mu_k recomputed from each period");
  sub->add_option("--gravity", options->gravity, "Gravity g")->capture_default_str();
  sub->add_option("--h-c", options->h_c, "Centre-of-mass height for the thick-plate column")
      ->capture_default_str();
  sub->add_flag("--json", options->json, "Print one JSON object (SI units) instead of the table");
  return Command{sub, [options, &global] { return run_table(*options, global); }};
}

}  // namespace fl::cli
