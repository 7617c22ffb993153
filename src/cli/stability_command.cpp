// frictionlab stability: the catalogue of stiff and extreme cases, each diagnosed against theory.
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/stop_signals.hpp"
#include "lab/request/outcome.hpp"
#include "lab/request/study_requests.hpp"

namespace fl::cli {
namespace {

struct StabilityOptions {
  std::string dir = default_stability_dir();
  std::string out;
  std::string only;
  int jobs = 0;
  bool json = false;
};

int run_stability(const StabilityOptions& o, const GlobalOptions& global) {
  StabilityRequest request;
  request.dir = o.dir;
  request.only = o.only;
  if (o.jobs != 0) request.jobs = o.jobs;
  request.out = o.out;
  request.assets = global.asset_dir;
  const StopSignals signals;
  const StabilityResult result = study_stability(request, JobControl{&stop_requested(), {}});
  const std::vector<StabilityRow>& rows = result.rows;
  if (o.json) {
    fmt::print("{}\n", result.json().dump(2));
    return exit_status(result.outcome(), stop_signal());
  }
  fmt::print("frictionlab stability: {} cases from {}\n\n", rows.size(), result.dir);
  fmt::print(
      "| case | parameters | theory expects | found | largest trustworthy step | period error at "
      "the "
      "scene's step | d ln mu / d ln T, d ln h_c | run time |\n");
  fmt::print("| --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (const StabilityRow& r : rows) {
    fmt::print(
        "| {} | {} | {} | {}{} | {} | {} | {} | {:.2f} s |\n", r.name, r.parameters,
        regime_name(r.expected), regime_name(r.found), r.as_expected ? "" : " (UNEXPECTED)",
        r.largest_step ? fmt::format("{:.3g} ms", *r.largest_step * 1e3) : "none: " + r.step_note,
        r.period_error ? fmt::format("{:+.2e}", *r.period_error) : "-",
        r.condition_period > 0 ? fmt::format("{:.3f}, {:.3f}", r.condition_period, r.condition_h_c)
                               : std::string("-"),
        r.wall_s);
  }
  fmt::print("\n{} of {} cases end in the regime theory expects.\n",
             rows.size() - static_cast<std::size_t>(result.unexpected()), rows.size());
  for (const StabilityRow& r : rows) {
    if (!r.as_expected)
      fmt::print("  {}: expected {} ({}), found {}: {}\n", r.name, regime_name(r.expected),
                 r.expected_reason, regime_name(r.found), r.evidence);
  }
  if (result.not_run > 0)
    fmt::print(
        stderr, "frictionlab stability: interrupted; kept: the {} cases above{}, {} not run\n",
        rows.size(), result.written.empty() ? "" : " (and in " + o.out + "/)", result.not_run);
  return exit_status(result.outcome(), stop_signal());
}

}  // namespace

Command add_stability_command(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<StabilityOptions>();
  CLI::App* sub = app.add_subcommand(
      "stability",
      "Run the catalogue of stiff and extreme cases and check each regime against theory");
  sub->add_option("--dir", options->dir, "Folder of the catalogue's scenes")->capture_default_str();
  sub->add_option("--only", options->only, "Only the cases whose name contains this");
  sub->add_option("-j,--jobs", options->jobs, "Cases run at once (default: all cores)");
  sub->add_option("--out", options->out, "Folder for stability.csv and stability.json");
  sub->add_flag("--json", options->json, "Print the table as JSON");
  return Command{sub, [options, &global] { return run_stability(*options, global); }};
}

}  // namespace fl::cli
