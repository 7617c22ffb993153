// frictionlab table: the paper's Table I, with mu_k recomputed from each measured period.
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "lab/request/table_request.hpp"

namespace fl::cli {
namespace {

struct TableOptions {
  std::string gravity = std::get<std::string>(TableRequest{}.gravity);
  std::string h_c = std::get<std::string>(TableRequest{}.h_c);
  bool json = false;
};

int run_table(const TableOptions& o, const GlobalOptions& global) {
  TableRequest request;
  request.gravity = o.gravity;
  request.h_c = o.h_c;
  request.assets = global.asset_dir;
  const TableResult result = paper_table_recomputed(request);
  if (o.json) {
    fmt::print("{}\n", result.json().dump(2));
    return 0;
  }
  fmt::print("The paper's Table I ({}), l = {:.0f} +- {:.0f} mm, g = {} m/s^2\n", result.file,
             result.table.spacing.value * 1e3, result.table.spacing.uncertainty * 1e3,
             result.gravity);
  fmt::print(
      "mu_k recomputed = 2 pi^2 l / (g T^2), +- worst case (dl/l + 2 dT/T) +- quadrature; "
      "thick: h_c = {:.1f} mm\n\n",
      result.h_c * 1e3);
  fmt::print("  {:<27} {:>6}  {:^18}  {:^16}  {:^31}  {:>7}\n", "material", "temp", "T measured",
             "mu_k printed", "mu_k recomputed", "thick");
  for (const TableRow& r : result.rows) {
    const PaperMeasurement& m = r.measured;
    std::string remark;
    if (!r.thin.mu_k_agrees) remark += fmt::format(" mu_k rounds to {}", r.thin.mu_k_rounded);
    if (!r.thin.uncertainty_agrees)
      remark += fmt::format(" d mu_k rounds to {}", r.thin.worst_rounded);
    fmt::print(
        "  {:<27} {:>4.0f} K  {:>5.2f} +- {:<4.2f} s  {:>6} +- {:<6}  {:>7.4f} +- {:<6.4f} "
        "+- {:<6.4f}  {:>7.4f}{}\n",
        r.material.name, m.temperature, m.period.value, m.period.uncertainty,
        fmt::format("{:.{}f}", m.mu_k.value, m.mu_k.decimals),
        fmt::format("{:.{}f}", m.mu_k.uncertainty, m.mu_k.uncertainty_decimals), r.thin.mu.mu_k,
        r.thin.mu.worst, r.thin.mu.quadrature, r.thick.mu_k, remark.empty() ? "" : "  <-" + remark);
  }
  fmt::print(
      "\n{} row(s) where the printed mu_k or its uncertainty is not what the printed T, dT, l "
      "and dl give (marked <-).\n",
      result.disagreements());
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
