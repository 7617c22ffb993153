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

MeasuredRows parse_measured_rows(std::string_view text, const std::string& file) {
  const CsvTable table = parse_csv_table(text, file);
  int period = -1, period_err = -1, label = -1, mu_k = -1, mu_k_err = -1, spacing_err = -1;
  int status = -1, mu_k_err_worst = -1;
  std::vector<int> keys;
  for (std::size_t c = 0; c < table.header.size(); ++c) {
    const CsvCell& h = table.header[c];
    const int i = static_cast<int>(c);
    if (h.text == "period")
      period = i;
    else if (h.text == "period_err")
      period_err = i;
    else if (h.text == "label")
      label = i;
    else if (h.text == "mu_k")
      mu_k = i;
    else if (h.text == "mu_k_err")
      mu_k_err = i;
    else if (h.text == "spacing_err")
      spacing_err = i;
    else if (h.text == "status")
      status = i;
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
      keys.push_back(i);
    } else {
      const std::string near = closest_match(h.text, kColumns);
      throw InputError(h.where,
                       "expected label, period, period_err, mu_k, mu_k_err, spacing_err "
                       "or a scene key such as plate.material, found \"" +
                           h.text + "\"" + (near.empty() ? "" : "; did you mean " + near + "?"));
    }
  }
  if (period < 0)
    throw InputError({file, table.header.front().where.line, 0},
                     "expected a column named period (with period_err, or periods written "
                     "\"0.79 +- 0.03 s\"), found none in the header");
  if (mu_k_err < 0) mu_k_err = mu_k_err_worst;
  if (mu_k_err >= 0 && mu_k < 0)
    throw InputError(table.header[mu_k_err].where,
                     "mu_k_err needs a column named mu_k beside it; add it or drop mu_k_err");

  MeasuredRows out;
  out.file = file;
  for (const std::vector<CsvCell>& cells : table.rows) {
    // A row of `frictionlab estimate`'s table whose log gave no period.
    if (status >= 0 && cells[status].text != "ok") {
      SkippedRow skipped;
      skipped.label = label >= 0 ? cells[label].text : std::string();
      skipped.where = cells.front().where;
      skipped.where.column = 0;
      skipped.reason = "status " + cells[status].text;
      out.skipped.push_back(std::move(skipped));
      continue;
    }
    MeasuredRow row;
    row.where = {file, cells.front().where.line, 0};
    row.label = label >= 0 && !cells[label].text.empty() ? cells[label].text
                                                         : "line " + std::to_string(row.where.line);
    const CsvCell& t = cells[period];
    row.period = measured_cell(t, Dimension::kTime, "period");
    if (!(row.period.value > 0.0) || !std::isfinite(row.period.value))
      throw InputError(t.where, "period: expected a positive time, found \"" + t.text + "\"");
    // Beyond any bench (core/plausible_range.hpp): refused here, before any simulation of it.
    if (const std::optional<std::string> why = implausible(row.period.value, kPeriodRange)) {
      const std::string advice = plain_number_advice(row.period.value, t.text, kPeriodRange);
      throw InputError(t.where, "period: " + *why +
                                    (advice.empty() ? "; check the value and its unit" : advice));
    }
    row.period_cell = t.where;
    if (period_err >= 0 && !cells[period_err].text.empty()) {
      if (t.text.find("+-") != std::string::npos || t.text.find("\xC2\xB1") != std::string::npos)
        throw InputError(cells[period_err].where,
                         "the period's uncertainty is given twice, in the period (\"" + t.text +
                             "\") and here; keep one");
      const Measured err = uncertainty_cell(cells[period_err], Dimension::kTime, "period_err");
      row.period.uncertainty = err.value;
      row.period.uncertainty_decimals = err.decimals;
    }
    if (!(row.period.uncertainty > 0.0))
      throw InputError(period_err >= 0 ? cells[period_err].where : t.where,
                       "expected the period's uncertainty (a positive time under period_err, or "
                       "\"0.79 +- 0.03 s\"), found none: residuals are in units of it");
    if (mu_k >= 0 && !cells[mu_k].text.empty()) {
      Measured m = measured_cell(cells[mu_k], Dimension::kDimensionless, "mu_k");
      if (!(m.value > 0.0) || !std::isfinite(m.value))
        throw InputError(cells[mu_k].where,
                         "mu_k: expected a positive number, found \"" + cells[mu_k].text + "\"");
      if (const std::optional<std::string> why = implausible(m.value, kMuKRange))
        throw InputError(cells[mu_k].where, "mu_k: " + *why + "; check the value");
      if (mu_k_err >= 0 && !cells[mu_k_err].text.empty()) {
        const Measured err =
            uncertainty_cell(cells[mu_k_err], Dimension::kDimensionless, "mu_k_err");
        m.uncertainty = err.value;
        m.uncertainty_decimals = err.decimals;
      }
      row.mu_k = m;
    }
    if (spacing_err >= 0 && !cells[spacing_err].text.empty())
      row.spacing_err =
          uncertainty_cell(cells[spacing_err], Dimension::kLength, "spacing_err").value;
    for (const int k : keys) {
      if (cells[k].text.empty()) continue;
      row.keys.push_back({table.header[k].text, cells[k].text});
      row.key_cells.push_back(cells[k].where);
    }
    out.rows.push_back(std::move(row));
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
