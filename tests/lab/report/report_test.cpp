// The lab report against the files it reports: every number it marks (data-field, data-value) is
// the run's summary.json's value, exactly; every period of periods.csv is in its table; a
// measurement's T and mu_k are `estimate`'s; a number the lab did not measure is shown as "—"
// with a null value; what it cannot report is refused, naming the input.
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/input_error.hpp"
#include "lab/report/report_html.hpp"
#include "lab/request/field_checks.hpp"
#include "lab/request/report_request.hpp"
#include "lab/request/run_request.hpp"
#include "support/temp_folder.hpp"
#include "text/message_catalogue.hpp"

namespace fl {
namespace {

using nlohmann::json;

std::string read(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Each (data-field, data-value) the report marks.
std::vector<std::pair<std::string, std::string>> marked(const std::string& html) {
  std::vector<std::pair<std::string, std::string>> out;
  const std::string field = "data-field=\"", value = "\" data-value=\"";
  for (std::size_t at = html.find(field); at != std::string::npos; at = html.find(field, at + 1)) {
    const std::size_t name = at + field.size();
    const std::size_t end = html.find(value, name);
    if (end == std::string::npos) break;
    const std::size_t close = html.find('"', end + value.size());
    out.emplace_back(html.substr(name, end - name),
                     html.substr(end + value.size(), close - end - value.size()));
  }
  return out;
}

// Each `report-*` message of a catalogue, and the variables it uses ({ $name }).
std::map<std::string, std::set<std::string>> report_messages(const std::string& ftl) {
  std::map<std::string, std::set<std::string>> out;
  std::istringstream lines(ftl);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t equals = line.find(" = ");
    if (!line.starts_with("report-") || equals == std::string::npos) continue;
    std::set<std::string>& vars = out[line.substr(0, equals)];
    for (std::size_t at = line.find("{ $"); at != std::string::npos; at = line.find("{ $", at + 1))
      vars.insert(line.substr(at + 3, line.find(' ', at + 3) - at - 3));
  }
  return out;
}

class ReportTest : public test::TempFolderTest {
 protected:
  ReportTest() : TempFolderTest("report") {}

  // A run of the minimal scene into the test's folder: its files, as `run --out` writes them.
  std::string run_minimal(const std::string& duration) {
    RunRequest r;
    r.scene.file = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/minimal.yaml";
    r.scene.asset_dir = FRICTIONLAB_TEST_ASSET_DIR;
    r.duration = QuantityInput{duration};
    r.out = (dir_ / "run").string();
    r.set = {"output.periods=true"};
    execute_run(prepare_run(r), {});
    return r.out;
  }

  ReportRequest request(std::vector<std::string> inputs) {
    ReportRequest r;
    r.assets = FRICTIONLAB_TEST_ASSET_DIR;
    r.inputs = std::move(inputs);
    r.out = (dir_ / "report.html").string();
    r.date = "2026-11-29";
    return r;
  }
};

TEST_F(ReportTest, ItsNumbersAreTheRunsSummaryExactly) {
  const std::string run = run_minimal("6 s");
  const ReportResult result = make_report(request({run}));
  const std::string html = read(dir_ / "report.html");
  EXPECT_EQ(html, result.html);
  const json summary = json::parse(read(std::filesystem::path(run) / "summary.json"));
  int numbers = 0;
  std::set<std::string> fields;
  for (const auto& [field, value] : marked(html)) {
    ASSERT_TRUE(summary.contains(field)) << field;
    if (value == "null") {
      EXPECT_TRUE(summary[field].is_null()) << field;
      continue;
    }
    EXPECT_EQ(json::parse(value), summary[field]) << field;
    ++numbers;
    fields.insert(field);
  }
  for (const char* needed : {"period_s", "period_std_error_s", "period_std_s", "periods_used",
                             "mu_k_estimator", "mu_k_err_quadrature", "mu_k_err_worst",
                             "period_thin_s", "period_thick_s", "mu_k_set", "mu_k_recovered_thick"})
    EXPECT_TRUE(fields.count(needed)) << needed << " is not in the report";
  EXPECT_GE(numbers, 10);
  // Every word is a message of the catalogue: none is missing (a missing one shows its id).
  EXPECT_EQ(html.find("report-"), std::string::npos) << html.substr(html.find("report-"), 60);
  EXPECT_NE(html.find("<html lang=\"en\">"), std::string::npos);
  // The paper's Table I row for LEGO blocks at 300 K: 0.79 +- 0.03 s, mu_k 0.29 +- 0.03.
  EXPECT_NE(html.find("The paper's Table I: LEGO blocks, 300 K"), std::string::npos);
  EXPECT_NE(html.find("0.79 ± 0.03"), std::string::npos);
  EXPECT_NE(html.find("American Journal of Physics"), std::string::npos);
}

TEST_F(ReportTest, InFrenchItsWordsAndDecimalCommaAreFrenchAndItsNumbersTheSame) {
  const std::string run = run_minimal("6 s");
  ReportRequest r = request({run});
  r.language = "fr";
  r.stopwatch = {{10, 7.9, 7.765}};
  const std::string html = make_report(r).html;
  EXPECT_EQ(html.find("report-"), std::string::npos) << html.substr(html.find("report-"), 60);
  EXPECT_NE(html.find("<html lang=\"fr\">"), std::string::npos);
  EXPECT_NE(html.find("Compte rendu\u00a0: l’oscillateur à frottement"), std::string::npos);
  // The material by its French name (fr.ftl's material-lego), in Table I's row and the set-up.
  EXPECT_NE(html.find("Tableau I de l’article\u00a0: Blocs LEGO, 300 K"), std::string::npos);
  EXPECT_EQ(html.find("LEGO blocks"), std::string::npos);
  EXPECT_NE(html.find("0,79 ± 0,03"), std::string::npos);  // the paper's T, with a comma
  EXPECT_NE(html.find("<td class=\"n\">7,765</td>"), std::string::npos);  // the stopwatch's
  // The marked numbers are the summary's exactly, whatever the language shows.
  const json summary = json::parse(read(std::filesystem::path(run) / "summary.json"));
  for (const auto& [field, value] : marked(html))
    if (value != "null") {
      EXPECT_EQ(json::parse(value), summary[field]) << field;
    }
  // A language the lab's data has no catalogue for is refused, saying which it has.
  r.language = "xx";
  try {
    make_report(r);
    FAIL() << "a report in xx was written";
  } catch (const RequestError& e) {
    EXPECT_NE(std::string(e.what()).find("de, en, es, fr"), std::string::npos) << e.what();
  }
}

// The catalogues offer the same report messages with the same variables: a translator's file
// lacks none and invents none.
TEST(ReportCatalogues, EveryLanguageHasEveryReportMessageWithItsVariables) {
  const auto read_catalogue = [](const std::string& language) {
    return read(std::filesystem::path(FRICTIONLAB_TEST_ASSET_DIR) / "locales" /
                (language + ".ftl"));
  };
  const std::string english = read_catalogue("en");
  const auto wanted = report_messages(english);
  EXPECT_GE(wanted.size(), 50u);
  for (const std::string& language : report_languages(FRICTIONLAB_TEST_ASSET_DIR)) {
    const auto found = report_messages(read_catalogue(language));
    EXPECT_EQ(found, wanted) << language << ".ftl";
    // And the lab reads each of them (plain text and { $variable } only).
    const MessageCatalogue c = MessageCatalogue::parse(read_catalogue(language));
    for (const auto& [id, vars] : wanted) EXPECT_TRUE(c.has(id)) << language << ": " << id;
  }
}

TEST_F(ReportTest, EveryPeriodOfTheRunIsInItsTable) {
  const std::string run = run_minimal("6 s");
  const std::string html = make_report(request({run})).html;
  const std::string csv = read(std::filesystem::path(run) / "periods.csv");
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);  // the header
  int rows = 0;
  while (std::getline(lines, line)) {
    if (line.empty()) continue;
    std::vector<std::string> cells;
    std::stringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    const std::string value = json(std::stod(cells[2])).dump();
    EXPECT_NE(html.find("data-value=\"" + value + "\""), std::string::npos) << line;
    ++rows;
  }
  EXPECT_GE(rows, 4);
  // Two plots of the run's data and one of its periods, as vector graphics.
  std::size_t svgs = 0;
  for (std::size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1))
    ++svgs;
  EXPECT_EQ(svgs, 3u);
}

TEST_F(ReportTest, AMeasurementsNumbersAreTheEstimates) {
  const std::string file = std::string(FRICTIONLAB_TEST_SOURCE_DIR) +
                           "/assets/examples/instruments/phone-magnetometer.csv";
  ReportRequest r = request({file});
  r.measurement.material = "lego";
  const ReportResult result = make_report(r);
  EstimateRequest e;
  e.assets = FRICTIONLAB_TEST_ASSET_DIR;
  e.logs = {file};
  const json estimate = estimate_one_log(prepare_estimate(e)).json();
  const json said = result.json()["parts"][0];
  EXPECT_EQ(said["period_s"], estimate["period_s"]);
  EXPECT_EQ(said["mu_k"], estimate["mu_k"]);
  EXPECT_NE(result.html.find("The paper's Table I: LEGO blocks, 300 K"), std::string::npos);
}

TEST_F(ReportTest, ANumberNotMeasuredIsADashWithANullValue) {
  ReportContent c;
  ReportPart part;
  part.title = "one period";
  part.period = {0.78, "period_s"};
  part.period_se = {std::nullopt, "period_std_error_s"};
  part.mu_k = {0.29, "mu_k"};
  part.mu_k_err = {std::nullopt, "mu_k_err_quadrature"};
  c.parts.push_back(part);
  const std::string html = report_html(c, report_texts(FRICTIONLAB_TEST_ASSET_DIR, "en"));
  EXPECT_NE(html.find("data-field=\"period_std_error_s\" data-value=\"null\">—"),
            std::string::npos);
  EXPECT_NE(html.find("no spread: one period"), std::string::npos);
  EXPECT_EQ(html.find(">0<"), std::string::npos);
}

TEST_F(ReportTest, WhatItCannotReportIsRefusedNamingTheInput) {
  EXPECT_THROW(make_report(request({})), RequestError);
  // A folder with a summary that is not a run's.
  write("broken/summary.json", "{\"hello\": 1}");
  try {
    make_report(request({(dir_ / "broken").string()}));
    FAIL() << "a broken summary was reported";
  } catch (const RequestError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_NE(e.problems()[0].message.find("not a run's summary"), std::string::npos);
  }
  // A file that is no measurement: the reader's own error, located in it.
  const std::string junk = write("junk.csv", "hello\nworld\n");
  EXPECT_THROW(make_report(request({junk})), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "report.html")) << "a refused report was written";
  // A stopwatch timing of no time.
  ReportRequest r = request({});
  r.stopwatch = {{10, 0.0, std::nullopt}};
  EXPECT_THROW(make_report(r), RequestError);
}

}  // namespace
}  // namespace fl
