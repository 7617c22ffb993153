// frictionlab report: the lab report a student hands in, from runs and measurements.
#include <memory>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/log_options.hpp"
#include "lab/request/report_request.hpp"

namespace fl::cli {
namespace {

struct ReportOptions {
  std::vector<std::string> inputs;
  std::string out = "report.html";
  std::string student;
  std::string language = "en";
  std::string spacing = quantity_input_text(EstimateRequest{}.spacing);
  std::string spacing_err = quantity_input_text(EstimateRequest{}.spacing_err);
  std::string material;
  std::string temperature;
  LogReadingOptions reading;
  bool json = false;
};

int run_report(const ReportOptions& o, const GlobalOptions& global) {
  ReportRequest request;
  request.assets = global.asset_dir;
  request.inputs = o.inputs;
  request.out = o.out;
  request.student = o.student;
  request.language = o.language;
  request.lab_version = "frictionlab " FRICTIONLAB_VERSION;
  EstimateRequest& m = request.measurement;
  m.spacing = o.spacing;
  m.spacing_err = o.spacing_err;
  if (!o.material.empty()) m.material = o.material;
  if (!o.temperature.empty()) m.temperature = o.temperature;
  m.columns = o.reading.columns;
  if (!o.reading.rate.empty()) m.rate = o.reading.rate;
  m.time_unit = o.reading.time_unit;
  const ReportResult result = make_report(request);
  if (o.json) {
    fmt::print("{}\n", result.json().dump(2));
    return 0;
  }
  fmt::print("frictionlab report: {}\n", result.written);
  for (const ReportPart& p : result.content.parts)
    fmt::print("  {:<40} T = {} s, mu_k = {}\n", p.title,
               p.period.value ? fmt::format("{:.4f}", *p.period.value) : "none",
               p.mu_k.value ? fmt::format("{:.3f}", *p.mu_k.value) : "none");
  fmt::print("  open it in a browser; print it to PDF from there (A4 or Letter)\n");
  return 0;
}

}  // namespace

Command add_report_command(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<ReportOptions>();
  CLI::App* sub = app.add_subcommand(
      "report",
      "A lab report to hand in (HTML, prints to PDF): runs and measurements, their data, T and "
      "mu_k with their uncertainties, against the paper's Table I");
  sub->add_option("inputs", options->inputs,
                  "Run folders (run --out) and measurement files (Hall logs, phone files, videos)")
      ->required();
  sub->add_option("--out", options->out, "The report's file")->capture_default_str();
  sub->add_option("--student", options->student, "Who hands it in");
  sub->add_option("--lang", options->language,
                  "The report's language: a catalogue of the lab's data (en, fr, es, de)")
      ->capture_default_str();
  sub->add_option("--spacing", options->spacing, "A measurement's roller spacing l")
      ->capture_default_str();
  sub->add_option("--spacing-err", options->spacing_err, "Uncertainty dl of the spacing")
      ->capture_default_str();
  sub->add_option("--material", options->material,
                  "A measurement's plate material (the paper's Table I), for the comparison");
  sub->add_option("--temperature", options->temperature,
                  "With --material: the rollers' temperature (300 K, or 77 K)");
  add_log_reading_options(*sub, options->reading, "");
  sub->add_flag("--json", options->json, "Print what the report says as one JSON object");
  return Command{sub, [options, &global] { return run_report(*options, global); }};
}

}  // namespace fl::cli
