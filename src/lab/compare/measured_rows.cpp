#include "lab/compare/measured_rows.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/plausible_range.hpp"
#include "io/csv_table.hpp"
#include "io/estimate_table_columns.hpp"
#include "io/field_ref.hpp"
#include "io/suggest.hpp"
#include "io/text_file.hpp"

namespace fl {
namespace {

constexpr std::array<std::string_view, 7> kColumns = {
    "label", "period", "period_err", "mu_k", "mu_k_err", "spacing_err", "status"};

// A cell as a measured quantity; "+-" in the cell gives its uncertainty.
Measured measured_cell(const CsvCell& cell, Dimension dimension, std::string_view column) {
  try {
    return parse_measured(cell.text, dimension, column);
  } catch (const UnitError& e) {
    throw InputError(cell.where, e.what());
  }
}

// The uncertainty column's cell: finite, not negative.
Measured uncertainty_cell(const CsvCell& cell, Dimension dimension, std::string_view column) {
  const Measured m = measured_cell(cell, dimension, column);
  if (!(m.value >= 0.0) || !std::isfinite(m.value))
    throw InputError(cell.where, std::string(column) +
                                     ": expected an uncertainty (finite, not "
                                     "negative), found \"" +
                                     cell.text + "\"");
  return m;
}

}  // namespace

bool compare_sets_key(std::string_view scene_key) {
  return scene_key == "friction.mu_k" || scene_key == "world.duration";
}

namespace {

// Where each column of a measurements table is (-1: not there), and the scene keys' columns.
struct MeasuredColumns {
  int period = -1, period_err = -1, label = -1, mu_k = -1, mu_k_err = -1, spacing_err = -1;
  int status = -1;
  std::vector<int> keys;
};

// The header read: each column known, a scene key, or refused saying what was expected.
MeasuredColumns measured_columns(const CsvTable& table, const std::string& file) {
  MeasuredColumns m;
  int mu_k_err_worst = -1;
  for (std::size_t c = 0; c < table.header.size(); ++c) {
    const CsvCell& h = table.header[c];
    const int i = static_cast<int>(c);
    if (h.text == "period")
      m.period = i;
    else if (h.text == "period_err")
      m.period_err = i;
    else if (h.text == "label")
      m.label = i;
    else if (h.text == "mu_k")
      m.mu_k = i;
    else if (h.text == "mu_k_err")
      m.mu_k_err = i;
    else if (h.text == "spacing_err")
      m.spacing_err = i;
    else if (h.text == "status")
      m.status = i;
    else if (h.text == "mu_k_err_worst")
      mu_k_err_worst = i;
    else if (is_estimate_table_note_column(h.text))
      continue;
    else if (h.text.find('.') != std::string::npos) {
      if (compare_sets_key(h.text))
        throw InputError(h.where,
                         "expected a scene key the comparison leaves to the rows, found " + h.text +
                             ", which it sets itself (mu_k is what the refit finds, the run's "
                             "length is " +
                             field_ref("duration") +
                             "); give the reported mu_k as a column named mu_k, or drop the "
                             "column");
      m.keys.push_back(i);
    } else {
      const std::string near = closest_match(h.text, kColumns);
      throw InputError(h.where,
                       "expected label, period, period_err, mu_k, mu_k_err, spacing_err "
                       "or a scene key such as plate.material, found \"" +
                           h.text + "\"" + (near.empty() ? "" : "; did you mean " + near + "?"));
    }
  }
  if (m.period < 0)
    throw InputError({file, table.header.front().where.line, 0},
                     "expected a column named period (with period_err, or periods written "
                     "\"0.79 +- 0.03 s\"), found none in the header");
  if (m.mu_k_err < 0) m.mu_k_err = mu_k_err_worst;
  if (m.mu_k_err >= 0 && m.mu_k < 0)
    throw InputError(table.header[m.mu_k_err].where,
                     "mu_k_err needs a column named mu_k beside it; add it or drop mu_k_err");
  return m;
}

// One row of measurements, each cell checked where it stands.
MeasuredRow measured_row(const std::vector<CsvCell>& cells, const MeasuredColumns& m,
                         const CsvTable& table, const std::string& file) {
  MeasuredRow row;
  row.where = {file, cells.front().where.line, 0};
  row.label = m.label >= 0 && !cells[m.label].text.empty()
                  ? cells[m.label].text
                  : "line " + std::to_string(row.where.line);
  const CsvCell& t = cells[m.period];
  row.period = measured_cell(t, Dimension::kTime, "period");
  if (!(row.period.value > 0.0) || !std::isfinite(row.period.value))
    throw InputError(t.where, "period: expected a positive time, found \"" + t.text + "\"");
  // Beyond any bench (core/plausible_range.hpp): refused here, before any simulation of it.
  if (const std::optional<std::string> why = implausible(row.period.value, kPeriodRange)) {
    const std::string advice = plain_number_advice(row.period.value, t.text, kPeriodRange);
    throw InputError(
        t.where, "period: " + *why + (advice.empty() ? "; check the value and its unit" : advice));
  }
  row.period_cell = t.where;
  if (m.period_err >= 0 && !cells[m.period_err].text.empty()) {
    if (t.text.find("+-") != std::string::npos || t.text.find("\xC2\xB1") != std::string::npos)
      throw InputError(cells[m.period_err].where,
                       "the period's uncertainty is given twice, in the period (\"" + t.text +
                           "\") and here; keep one");
    const Measured err = uncertainty_cell(cells[m.period_err], Dimension::kTime, "period_err");
    row.period.uncertainty = err.value;
    row.period.uncertainty_decimals = err.decimals;
  }
  if (!(row.period.uncertainty > 0.0))
    throw InputError(m.period_err >= 0 ? cells[m.period_err].where : t.where,
                     "expected the period's uncertainty (a positive time under period_err, or "
                     "\"0.79 +- 0.03 s\"), found none: residuals are in units of it");
  if (m.mu_k >= 0 && !cells[m.mu_k].text.empty()) {
    Measured reported = measured_cell(cells[m.mu_k], Dimension::kDimensionless, "mu_k");
    if (!(reported.value > 0.0) || !std::isfinite(reported.value))
      throw InputError(cells[m.mu_k].where,
                       "mu_k: expected a positive number, found \"" + cells[m.mu_k].text + "\"");
    if (const std::optional<std::string> why = implausible(reported.value, kMuKRange))
      throw InputError(cells[m.mu_k].where, "mu_k: " + *why + "; check the value");
    if (m.mu_k_err >= 0 && !cells[m.mu_k_err].text.empty()) {
      const Measured err =
          uncertainty_cell(cells[m.mu_k_err], Dimension::kDimensionless, "mu_k_err");
      reported.uncertainty = err.value;
      reported.uncertainty_decimals = err.decimals;
    }
    row.mu_k = reported;
  }
  if (m.spacing_err >= 0 && !cells[m.spacing_err].text.empty())
    row.spacing_err =
        uncertainty_cell(cells[m.spacing_err], Dimension::kLength, "spacing_err").value;
  for (const int k : m.keys) {
    if (cells[k].text.empty()) continue;
    row.keys.push_back({table.header[k].text, cells[k].text});
    row.key_cells.push_back(cells[k].where);
  }
  return row;
}

}  // namespace

MeasuredRows parse_measured_rows(std::string_view text, const std::string& file) {
  const CsvTable table = parse_csv_table(text, file);
  const MeasuredColumns m = measured_columns(table, file);

  MeasuredRows out;
  out.file = file;
  for (const std::vector<CsvCell>& cells : table.rows) {
    // A row of `frictionlab estimate`'s table whose log gave no period.
    if (m.status >= 0 && cells[m.status].text != "ok") {
      SkippedRow skipped;
      skipped.label = m.label >= 0 ? cells[m.label].text : std::string();
      skipped.where = cells.front().where;
      skipped.where.column = 0;
      skipped.reason = "status " + cells[m.status].text;
      out.skipped.push_back(std::move(skipped));
      continue;
    }
    out.rows.push_back(measured_row(cells, m, table, file));
  }
  if (out.rows.empty())
    throw InputError({file, table.header.front().where.line, 0},
                     out.skipped.empty()
                         ? std::string("expected at least one row of measurements after the "
                                       "header, found none")
                         : "expected at least one row with status ok, found " +
                               std::to_string(out.skipped.size()) + " without a period");
  return out;
}

MeasuredRows read_measured_rows(const std::string& path) {
  return parse_measured_rows(read_text_file(path, "the measurements"), path);
}

}  // namespace fl
