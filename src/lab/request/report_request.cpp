#include "lab/request/report_request.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "io/text_file.hpp"
#include "lab/report/report_html.hpp"
#include "lab/request/lab_data.hpp"
#include "text/message_catalogue.hpp"

namespace fl {
namespace {

std::string today_utc() {
  const auto days = std::chrono::floor<std::chrono::days>(std::chrono::system_clock::now());
  const std::chrono::year_month_day ymd{days};
  return fmt::format("{:04d}-{:02d}-{:02d}", static_cast<int>(ymd.year()),
                     static_cast<unsigned>(ymd.month()), static_cast<unsigned>(ymd.day()));
}

// A run's folder: its files by name, read when asked (nullopt for one the run did not keep).
RunFiles folder_files(const std::string& folder) {
  return [folder](const std::string& name) -> std::optional<std::string> {
    const std::filesystem::path file = std::filesystem::path(folder) / name;
    std::error_code error;
    if (!std::filesystem::exists(file, error)) return std::nullopt;
    return read_text_file(file.string(), "the run's file");
  };
}

bool is_run_folder(const std::string& input) {
  std::error_code error;
  return std::filesystem::is_regular_file(std::filesystem::path(input) / "summary.json", error);
}

void check_request(const ReportRequest& r, FieldChecks& checks, bool inputs_needed) {
  const std::vector<std::string> languages = report_languages(asset_dir(r.assets));
  if (std::find(languages.begin(), languages.end(), r.language) == languages.end())
    checks.problem("language", r.language,
                   fmt::format("expected one of the languages the lab's data has ({}), found "
                               "\"{}\"",
                               fmt::join(languages, ", "), r.language));
  if (inputs_needed && r.inputs.empty())
    checks.problem(
        "inputs",
        "expected at least one folder a run wrote its files into, or a measurement file, found "
        "none");
  for (std::size_t i = 0; i < r.stopwatch.size(); ++i) {
    const StopwatchTiming& s = r.stopwatch[i];
    if (!(s.periods >= 1 && s.periods <= 1000) || !(s.wall_s > 0.0) || !std::isfinite(s.wall_s) ||
        (s.simulated_s && !(*s.simulated_s > 0.0 && std::isfinite(*s.simulated_s))))
      checks.problem("stopwatch",
                     fmt::format("timing {}: expected 1 to 1000 periods over a positive time, "
                                 "found {} periods over {} s",
                                 i + 1, s.periods, s.wall_s));
  }
  if (!r.out.empty() && std::filesystem::is_directory(r.out))
    checks.problem("out", r.out, "expected a file to write the report to, found a folder");
}

ReportResult finish(ReportContent content, const ReportRequest& r) {
  ReportResult result;
  result.html = report_html(content, report_texts(r.assets, r.language));
  result.content = std::move(content);
  if (!r.out.empty()) {
    write_file_atomic(r.out, result.html);
    result.written = r.out;
  }
  return result;
}

ReportContent content_of(const ReportRequest& r) {
  ReportContent c;
  c.language = r.language;
  c.student = r.student;
  c.lab_version = r.lab_version.empty() ? "frictionlab" : r.lab_version;
  c.date = r.date.empty() ? today_utc() : r.date;
  c.stopwatch = r.stopwatch;
  return c;
}

// A measurement file's part: read and estimated as `frictionlab estimate` reads it.
ReportPart file_part(const std::string& input, const ReportRequest& r) {
  EstimateRequest one = r.measurement;
  one.assets = r.assets;
  one.logs = {input};
  const OneLogEstimate estimate = estimate_one_log(prepare_estimate(one));
  return measurement_part(estimate.log, estimate.estimate, estimate.paper);
}

}  // namespace

ReportTexts report_texts(const std::string& assets, const std::string& language) {
  const std::filesystem::path locales = std::filesystem::path(asset_dir(assets)) / "locales";
  return {MessageCatalogue::parse(
              read_text_file((locales / (language + ".ftl")).string(), "the language's messages")),
          MessageCatalogue::parse(
              read_text_file((locales / "en.ftl").string(), "the English messages"))};
}

std::vector<std::string> report_languages(const std::string& assets) {
  std::vector<std::string> out;
  std::error_code error;
  const std::filesystem::path locales = std::filesystem::path(asset_dir(assets)) / "locales";
  for (const auto& entry : std::filesystem::directory_iterator(locales, error))
    if (entry.path().extension() == ".ftl") out.push_back(entry.path().stem().string());
  std::sort(out.begin(), out.end());
  return out;
}

nlohmann::json ReportResult::json() const {
  nlohmann::json parts = nlohmann::json::array();
  const auto value = [](const ReportNumber& n) {
    return n.value ? nlohmann::json(*n.value) : nlohmann::json(nullptr);
  };
  for (const ReportPart& p : content.parts)
    parts.push_back({{"title", p.title},
                     {"simulated", p.simulated},
                     {"source", p.source},
                     {"period_s", value(p.period)},
                     {"period_std_error_s", value(p.period_se)},
                     {"mu_k", value(p.mu_k)},
                     {"mu_k_err", value(p.mu_k_err)},
                     {"periods", p.periods.size()}});
  return {{"written", written.empty() ? nlohmann::json(nullptr) : nlohmann::json(written)},
          {"parts", parts}};
}

ReportResult make_report(const ReportRequest& r) {
  FieldChecks checks;
  check_request(r, checks, true);
  checks.throw_if_any();
  const PaperTable& table = paper_table_in(asset_dir(r.assets));
  ReportContent content = content_of(r);
  for (const std::string& input : r.inputs) {
    if (is_run_folder(input)) {
      try {
        content.parts.push_back(simulation_part(folder_files(input), input, table));
      } catch (const std::invalid_argument& e) {
        checks.problem("inputs", input, e.what());
        checks.throw_if_any();
      }
      continue;
    }
    content.parts.push_back(file_part(input, r));
  }
  return finish(std::move(content), r);
}

ReportResult report_of_runs(const std::vector<std::pair<std::string, RunFiles>>& runs,
                            const ReportRequest& r) {
  FieldChecks checks;
  check_request(r, checks, false);
  checks.throw_if_any();
  const PaperTable& table = paper_table_in(asset_dir(r.assets));
  ReportContent content = content_of(r);
  for (const auto& [source, files] : runs)
    content.parts.push_back(simulation_part(files, source, table));
  for (const std::string& input : r.inputs) content.parts.push_back(file_part(input, r));
  for (const MeasuredSummary& m : r.measured) content.parts.push_back(measurement_part(m));
  return finish(std::move(content), r);
}

}  // namespace fl
