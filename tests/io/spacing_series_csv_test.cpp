// A spacing series as a student writes it: columns in any order, units in the cells, comments,
// a spreadsheet's BOM and CRLF; and every way it can be wrong refused at the cell at fault.
#include "io/spacing_series_csv.hpp"

#include <string>

#include <gtest/gtest.h>

namespace fl {
namespace {

SpacingSeries parse(const std::string& text) {
  return parse_spacing_series(text, "s.csv");
}

// The message of the InputError the text raises, or a failure.
std::string refusal(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return "";
}

TEST(SpacingSeriesCsv, ColumnsInAnyOrderWithUnits) {
  const SpacingSeries s = parse(
      "\xEF\xBB\xBF# my rig, 2026-11-30\r\n"
      "label, period_err, PERIOD, spacing, spacing_err\r\n"
      "\r\n"
      "\"first, tight\",5ms,0.646 s,60 mm,1mm\r\n"
      "b,0.004,0.79,0.089,\r\n");
  ASSERT_EQ(s.rows.size(), 2u);
  EXPECT_EQ(s.header_line, 2);
  EXPECT_TRUE(s.has_label);
  EXPECT_TRUE(s.has_spacing_err);
  EXPECT_EQ(s.rows[0].label, "first, tight");
  EXPECT_EQ(s.rows[0].line, 4);
  EXPECT_DOUBLE_EQ(s.rows[0].measurement.spacing, 0.060);
  EXPECT_DOUBLE_EQ(s.rows[0].measurement.period, 0.646);
  EXPECT_DOUBLE_EQ(s.rows[0].measurement.period_err, 0.005);
  EXPECT_DOUBLE_EQ(*s.rows[0].measurement.spacing_err, 0.001);
  EXPECT_DOUBLE_EQ(s.rows[1].measurement.spacing, 0.089);
  EXPECT_FALSE(s.rows[1].measurement.spacing_err.has_value());  // empty: not given, not 0
  const SourceLocation at = s.at(1, SeriesColumn::kPeriod);
  EXPECT_EQ(at.line, 5);
  EXPECT_EQ(at.column, 9);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(SpacingSeriesCsv, APlainSpacingOfMetresIsReadAsSIAndSaidAloud) {
  const SpacingSeries s = parse("spacing,period,period_err\n2,2.8,0.01\n0.1,0.8,0.01\n");
  EXPECT_DOUBLE_EQ(s.rows[0].measurement.spacing, 2.0);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_EQ(s.warnings[0],
            "s.csv:2:1: warning: spacing: 2 read as 2 m (a plain number is SI); write 2 mm for "
            "millimetres");
}

// Beyond any bench (core/plausible_range.hpp): a plain number of millimetres read as metres, a
// period of milliseconds read as seconds, refused at the cell with the unit that was meant.
TEST(SpacingSeriesCsv, AValueBeyondAnyRigIsRefusedAtItsCell) {
  EXPECT_EQ(refusal("spacing,period,period_err\n89,0.79,0.01\n0.1,0.8,0.01\n"),
            "s.csv:2:1: error: spacing: expected the roller spacing l from 1 to 2000 mm (the "
            "paper's rig: 89 mm), found 89000 mm: a plain number is SI, so 89 was read as 89 m; "
            "write 89mm for millimetres");
  EXPECT_EQ(refusal("spacing,period,period_err\n60 mm,648,5 ms\n70 mm,0.7 s,5 ms\n"),
            "s.csv:2:7: error: period: expected the period T from 0.0044857 to 63.4374 s (the "
            "paper's rig: 0.3 to 1 s), found 648 s: a plain number is SI, so 648 was read as 648 "
            "s; write 648ms for milliseconds");
  EXPECT_EQ(refusal("spacing,period,period_err\n60 mm,1 h,5 ms\n70 mm,0.7 s,5 ms\n"),
            "s.csv:2:7: error: period: expected the period T from 0.0044857 to 63.4374 s (the "
            "paper's rig: 0.3 to 1 s), found 3600 s; check the row's value and unit");
}

TEST(SpacingSeriesCsv, RefusalsNameTheCellAndWhatToDo) {
  const std::string header = "spacing,period,period_err\n";
  EXPECT_EQ(refusal(header + "89 mm,0.79 s,5 ms\n"),
            "s.csv:2: error: expected at least 2 rows (a straight line T^2 against l needs two "
            "spacings), found 1; measure the period at other spacings and add a row for each");
  EXPECT_EQ(refusal(header),
            "s.csv:1: error: expected at least 2 rows (a straight line T^2 "
            "against l needs two spacings), found 0; measure the period at other "
            "spacings and add a row for each");
  EXPECT_EQ(refusal(header + "89 mm,0.79 s,5 ms\n89mm,0.80 s,5 ms\n"),
            "s.csv:3:1: error: expected at least two different spacings, found every row at 89 "
            "mm; T^2 against l needs the period at other spacings (move a roller and measure "
            "again)");
  EXPECT_NE(refusal(header + "89 mm,0.79 s,5 ms\n100 mm,-0.8 s,5 ms\n")
                .find("s.csv:3:8: error: period: expected the period T greater than 0, found "
                      "\"-0.8 s\""),
            std::string::npos);
  EXPECT_NE(refusal(header + "89 mm,0.79 s,0 ms\n100 mm,0.8 s,5 ms\n")
                .find("s.csv:2:14: error: period_err: expected the period's uncertainty dT "
                      "greater than 0, found \"0 ms\""),
            std::string::npos);
  EXPECT_NE(
      refusal(header + "89 mm,nan,5 ms\n100 mm,0.8 s,5 ms\n")
          .find("s.csv:2:7: error: period: expected a time (a number with one of the units: s, "
                "ms, us, µs, min, h), found \"nan\": the number is not finite"),
      std::string::npos);
  EXPECT_NE(refusal(header + "89 mm,0.79 kg,5 ms\n100 mm,0.8 s,5 ms\n")
                .find("s.csv:2:7: error: period: expected a time"),
            std::string::npos);
  EXPECT_NE(refusal(header + "89 mm,,5 ms\n100 mm,0.8 s,5 ms\n")
                .find("s.csv:2:7: error: period: expected the period T (e.g. \"0.79 s\"), found an "
                      "empty cell"),
            std::string::npos);
  EXPECT_NE(refusal("spacing,period\n89 mm,0.79 s\n100 mm,0.8 s\n")
                .find("s.csv:1:1: error: expected a header naming spacing, period and period_err, "
                      "found no period_err column; add it"),
            std::string::npos);
  EXPECT_NE(refusal("spacing,period,period_eror\n")
                .find("s.csv:1:16: error: expected a column named spacing, period, period_err, "
                      "spacing_err (optional), label (optional), found \"period_eror\" (did you "
                      "mean 'period_err'?)"),
            std::string::npos);
  EXPECT_NE(refusal("spacing,period,period_err,period\n")
                .find("s.csv:1:27: error: the column \"period\" is named twice in the header "
                      "(first at column 9)"),
            std::string::npos);
  EXPECT_NE(refusal(header + "89 mm,0.79 s\n").find("s.csv:2:13: error: expected 3 fields"),
            std::string::npos);
  EXPECT_NE(refusal(header + "89 mm,0.79 s,5 ms,x\n").find("s.csv:2:19: error: expected 3 fields"),
            std::string::npos);
  EXPECT_NE(refusal("spacing,period,period_err,spacing_err\n89 mm,0.79 s,5 ms,-1 mm\n")
                .find("s.csv:2:19: error: spacing_err: expected the spacing's uncertainty dl of 0 "
                      "or more"),
            std::string::npos);
  EXPECT_NE(refusal("# only a comment\n\n").find("s.csv: error: expected a header"),
            std::string::npos);
}

}  // namespace
}  // namespace fl
