// Measurements files for compare --measured: the CSV table under them (quotes, a byte-order mark,
// comments, located errors), the rows' columns and scene keys, and the paper's Table I as such a
// file, row for row the same numbers as the paper's data file table1.yaml.
#include <gtest/gtest.h>

#include "io/csv_table.hpp"
#include "io/paper_table_yaml.hpp"
#include "lab/compare/compare.hpp"
#include "lab/compare/measured_rows.hpp"

namespace fl {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_measured_rows(text, "m.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CsvTable, QuotesCommentsAndAByteOrderMark) {
  const CsvTable t = parse_csv_table(
      "\xEF\xBB\xBF# a comment\nlabel , period\n\n\"a, \"\"b\"\"\", 0.79 s\r\n# more\nc,1\n",
      "t.csv");
  ASSERT_EQ(t.header.size(), 2u);
  EXPECT_EQ(t.header[0].text, "label");
  EXPECT_EQ(t.header[1].where.line, 2);
  EXPECT_EQ(t.header[1].where.column, 9);
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0][0].text, "a, \"b\"");
  EXPECT_EQ(t.rows[0][1].text, "0.79 s");
  EXPECT_EQ(t.rows[0][1].where.line, 4);
  EXPECT_EQ(t.rows[1][1].text, "1");
}

TEST(CsvTable, ErrorsAreLocated) {
  const auto error = [](const std::string& text) {
    try {
      parse_csv_table(text, "t.csv");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("a,b\n1,2,3\n").find("t.csv:2:5: error: expected 2 fields"), std::string::npos);
  EXPECT_NE(error("a,b\n\"1,2\n").find("t.csv:2:1: error: expected a closing quote"),
            std::string::npos);
  EXPECT_NE(error("a,a\n").find("t.csv:1:3: error: the column \"a\" is named twice"),
            std::string::npos);
  EXPECT_NE(error("# only a comment\n").find("expected a header line"), std::string::npos);
}

TEST(MeasuredRows, ColumnsKeysAndUnits) {
  const MeasuredRows m = parse_measured_rows(
      "label,rollers.spacing,plate.material,period,period_err,mu_k\n"
      "near,70 mm,lego,686.5 ms,0.2 ms,0.30\n"
      "far,,,0.82 +- 0.01 s,,\n",
      "m.csv");
  ASSERT_EQ(m.rows.size(), 2u);
  const MeasuredRow& a = m.rows[0];
  EXPECT_EQ(a.label, "near");
  EXPECT_DOUBLE_EQ(a.period.value, 0.6865);
  EXPECT_DOUBLE_EQ(a.period.uncertainty, 0.0002);
  ASSERT_EQ(a.keys.size(), 2u);
  EXPECT_EQ(a.keys[0].path, "rollers.spacing");
  EXPECT_EQ(a.keys[0].value, "70 mm");
  EXPECT_EQ(a.key_cells[1].column, 12);  // "lego" in "near,70 mm,lego,..."
  ASSERT_TRUE(a.mu_k);
  EXPECT_DOUBLE_EQ(a.mu_k->value, 0.30);
  // Empty cells leave the keys to the scene; "+-" in the period gives its uncertainty.
  const MeasuredRow& b = m.rows[1];
  EXPECT_TRUE(b.keys.empty());
  EXPECT_FALSE(b.mu_k);
  EXPECT_DOUBLE_EQ(b.period.uncertainty, 0.01);
}

TEST(MeasuredRows, BadFilesAreRefusedAtTheCellWithWhatToDo) {
  EXPECT_NE(error_of("label,perod,period_err\na,1,0.1\n").find("m.csv:1:7: error:"),
            std::string::npos);
  EXPECT_NE(error_of("label,perod,period_err\na,1,0.1\n").find("did you mean period?"),
            std::string::npos);
  EXPECT_NE(error_of("period,period_err,friction.mu_k\n1,0.1,0.3\n")
                .find("m.csv:1:19: error: expected a scene key the comparison leaves"),
            std::string::npos);
  EXPECT_NE(error_of("label,period\na,0.79 s\n")
                .find("m.csv:2:3: error: expected the period's "
                      "uncertainty"),
            std::string::npos);
  EXPECT_NE(error_of("period,period_err\n-0.79 s,0.01 s\n")
                .find("m.csv:2:1: error: period: "
                      "expected a positive time"),
            std::string::npos);
  EXPECT_NE(error_of("period,period_err\n0.79 kg,0.01 s\n").find("m.csv:2:1: error:"),
            std::string::npos);
  EXPECT_NE(error_of("period,period_err\n0.79 s,-1 s\n").find("m.csv:2:8: error:"),
            std::string::npos);
  EXPECT_NE(error_of("period,period_err\n").find("expected at least one row"), std::string::npos);
}

// The table `frictionlab estimate` writes for several logs: rows whose log gave no period are
// skipped (and listed), the columns that say how a row was measured are read past.
TEST(MeasuredRows, ReadsTheTableOfSeveralLogs) {
  const MeasuredRows m = parse_measured_rows(
      "label,log,status,rollers.spacing,spacing_err,plate.material,friction.temperature,period,"
      "period_err,period_std,periods_used,periods_discarded,mu_k,mu_k_err_worst,"
      "mu_k_err_quadrature,error\n"
      "a,a.csv,ok,0.07 m,0.001 m,lego,300 K,0.6865,2e-05,7e-05,12,0,0.2989,0.0043,0.0042,\n"
      "b,b.csv,failed,0.089 m,0.001 m,,,,,,,,,,,\"b.csv:2:1: error: no pulse\"\n",
      "estimates.csv");
  ASSERT_EQ(m.rows.size(), 1u);
  ASSERT_EQ(m.skipped.size(), 1u);
  EXPECT_EQ(m.skipped[0].label, "b");
  EXPECT_EQ(m.skipped[0].where.line, 3);
  ASSERT_TRUE(m.rows[0].spacing_err);
  EXPECT_DOUBLE_EQ(*m.rows[0].spacing_err, 0.001);
  EXPECT_DOUBLE_EQ(m.rows[0].mu_k->uncertainty, 0.0043);  // the worst case stands for mu_k_err
  EXPECT_EQ(m.rows[0].keys.size(), 3u);                   // spacing, material, temperature
}

// The paper's Table I as a measurements file carries the numbers of its data file, as printed.
TEST(MeasuredRows, TableOneFileMatchesThePapersDataFile) {
  const PaperTable table = load_paper_table(paper_table_path(FRICTIONLAB_TEST_ASSET_DIR));
  const MeasuredRows m = read_measured_rows(paper_measurements_path(FRICTIONLAB_TEST_ASSET_DIR));
  std::size_t expected = 0;
  for (const PaperMaterial& material : table.materials) expected += material.cold ? 2 : 1;
  ASSERT_EQ(m.rows.size(), expected);
  for (const MeasuredRow& row : m.rows) {
    SCOPED_TRACE(row.label);
    ASSERT_EQ(row.keys.size(), 2u);
    EXPECT_EQ(row.keys[0].path, "plate.material");
    const PaperMaterial* material = table.find(row.keys[0].value);
    ASSERT_NE(material, nullptr);
    EXPECT_EQ(row.label, material->name);
    const double temperature = row.keys[1].value == "77 K" ? 77.0 : 300.0;
    const PaperMeasurement* at = PaperTable::at(*material, temperature);
    ASSERT_NE(at, nullptr);
    EXPECT_DOUBLE_EQ(row.period.value, at->period.value);
    EXPECT_DOUBLE_EQ(row.period.uncertainty, at->period.uncertainty);
    EXPECT_EQ(row.period.decimals, at->period.decimals);
    ASSERT_TRUE(row.mu_k);
    EXPECT_DOUBLE_EQ(row.mu_k->value, at->mu_k.value);
    EXPECT_DOUBLE_EQ(row.mu_k->uncertainty, at->mu_k.uncertainty);
    ASSERT_TRUE(row.spacing_err);
    EXPECT_DOUBLE_EQ(*row.spacing_err, table.spacing.uncertainty);
  }
}

}  // namespace
}  // namespace fl
