#include "io/spacing_series_csv.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "core/plausible_range.hpp"
#include "core/units.hpp"
#include "io/csv_table.hpp"
#include "io/estimate_table_columns.hpp"
#include "io/suggest.hpp"
#include "io/text_file.hpp"
#include "text/decimal.hpp"
#include "text/text.hpp"

namespace fl {
namespace {

struct ColumnInfo {
  SeriesColumn column;
  std::string_view name;
  Dimension dimension;
  std::string_view what;     // "the period", for messages
  std::string_view example;  // "0.79 s"
  bool required;
};

constexpr std::array<ColumnInfo, 5> kColumns{{
    {SeriesColumn::kSpacing, "spacing", Dimension::kLength, "the roller spacing l", "89 mm", true},
    {SeriesColumn::kPeriod, "period", Dimension::kTime, "the period T", "0.79 s", true},
    {SeriesColumn::kPeriodErr, "period_err", Dimension::kTime, "the period's uncertainty dT",
     "5 ms", true},
    {SeriesColumn::kSpacingErr, "spacing_err", Dimension::kLength, "the spacing's uncertainty dl",
     "1 mm", false},
    {SeriesColumn::kLabel, "label", Dimension::kDimensionless, "a label", "run 3", false},
}};

const ColumnInfo& info(SeriesColumn column) {
  return kColumns[static_cast<std::size_t>(column)];
}

std::string known_names() {
  std::string out;
  for (const ColumnInfo& c : kColumns)
    out += fmt::format("{}{}{}", out.empty() ? "" : ", ", c.name, c.required ? "" : " (optional)");
  return out;
}

// The header: which column of the file holds which quantity (none for a column read past: the
// notes and the status of frictionlab estimate's table; `status` is where that column is, or -1).
// A sweep's results.csv (docs/sweep-format.md): its columns are the run's, SI, with the axes
// between `index` and `seed`. Its spacing is spacing_m, its period the estimator's period_s with
// the standard error of its mean as dT (period_std_error_s), its label the point's index; every
// other column is read past. A sweep that varies anything but the spacing is refused: its rows
// are not one rig's series.
bool sweep_results_header(const std::vector<CsvCell>& cells) {
  const auto has = [&](std::string_view name) {
    return std::any_of(cells.begin(), cells.end(),
                       [&](const CsvCell& c) { return ascii_lower(c.text) == name; });
  };
  return has("index") && has("seed") && has("status") && has("spacing_m") && has("period_s") &&
         has("period_std_error_s");
}

std::vector<std::optional<SeriesColumn>> read_sweep_header(const std::vector<CsvCell>& cells,
                                                           int* status) {
  std::vector<std::optional<SeriesColumn>> order;
  bool axes = false;
  for (const CsvCell& cell : cells) {
    const std::string name = ascii_lower(cell.text);
    if (name == "index") {
      axes = true;
      order.push_back(SeriesColumn::kLabel);
      continue;
    }
    if (name == "seed") axes = false;
    if (axes && name != "rollers.spacing")
      throw InputError(cell.where,
                       fmt::format("this sweep varies {} besides the roller spacing, so its rows "
                                   "are not one rig's series; fit a sweep whose only axis is "
                                   "rollers.spacing (or a CSV of one value of {})",
                                   cell.text, cell.text));
    if (name == "status") *status = static_cast<int>(order.size());
    order.push_back(name == "spacing_m"            ? std::optional(SeriesColumn::kSpacing)
                    : name == "period_s"           ? std::optional(SeriesColumn::kPeriod)
                    : name == "period_std_error_s" ? std::optional(SeriesColumn::kPeriodErr)
                                                   : std::nullopt);
  }
  return order;
}

std::vector<std::optional<SeriesColumn>> read_header(const std::vector<CsvCell>& cells,
                                                     const std::string& file, int* status) {
  if (sweep_results_header(cells)) return read_sweep_header(cells, status);
  std::vector<std::optional<SeriesColumn>> order;
  std::array<int, 5> seen{};  // column of the file (1-based) where each was named, 0 if not
  *status = -1;
  for (const CsvCell& cell : cells) {
    std::string name = ascii_lower(cell.text);
    if (name == "rollers.spacing") name = "spacing";  // the table frictionlab estimate writes
    if (name == "status") *status = static_cast<int>(order.size());
    if (name == "status" || is_estimate_table_note_column(name) || name == "mu_k" ||
        name == "mu_k_err" || name.find('.') != std::string::npos) {
      // Scene keys (plate.material, ...) say which rig a row is, and a row's own mu_k is what the
      // fit replaces: it does not need them.
      order.push_back(std::nullopt);
      continue;
    }
    const auto found = std::find_if(kColumns.begin(), kColumns.end(),
                                    [&](const ColumnInfo& c) { return c.name == name; });
    if (found == kColumns.end()) {
      std::vector<std::string_view> names;
      for (const ColumnInfo& c : kColumns) names.push_back(c.name);
      const std::string near = closest_match(name, names);
      throw InputError(cell.where,
                       fmt::format("expected a column named {}, found \"{}\"{}; rename or remove "
                                   "the column (units go in the cells: 89 mm, 0.79 s)",
                                   known_names(), cell.text,
                                   near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near)));
    }
    int& first = seen[static_cast<std::size_t>(found->column)];
    if (first != 0)
      throw InputError(cell.where, fmt::format("the column {} is named twice (first at column "
                                               "{}); keep one",
                                               found->name, first));
    first = cell.where.column;
    order.push_back(found->column);
  }
  std::vector<std::string> missing;
  for (const ColumnInfo& c : kColumns)
    if (c.required && seen[static_cast<std::size_t>(c.column)] == 0)
      missing.push_back(std::string(c.name));
  if (!missing.empty()) {
    std::string list;
    for (const std::string& m : missing) list += (list.empty() ? "" : ", ") + m;
    throw InputError(
        SourceLocation{file, cells.front().where.line, 1},
        fmt::format("expected a header naming spacing, period and period_err, found "
                    "no {} column{}; add {} (e.g. a header \"spacing,period,"
                    "period_err\" and rows \"89 mm,0.79 s,5 ms\")",
                    list, missing.size() > 1 ? "s" : "", missing.size() > 1 ? "them" : "it"));
  }
  return order;
}

bool plain_number(std::string_view text) {
  double ignored = 0.0;
  const auto [ptr, ec] = read_decimal(text.data(), text.data() + text.size(), ignored);
  return ec == std::errc{} && ptr == text.data() + text.size();
}

double read_value(const CsvCell& field, const ColumnInfo& c, const SourceLocation& where) {
  if (field.text.empty())
    throw InputError(where, fmt::format("{}: expected {} (e.g. \"{}\"), found an empty cell; fill "
                                        "it in or remove the row",
                                        c.name, c.what, c.example));
  double value = 0.0;
  try {
    value = parse_quantity(field.text, c.dimension, c.name);
  } catch (const UnitError& e) {
    throw InputError(where, e.what());
  }
  if (!std::isfinite(value))
    throw InputError(where, fmt::format("{}: expected {} as a finite number, found \"{}\"", c.name,
                                        c.what, field.text));
  const bool error_column =
      c.column == SeriesColumn::kSpacingErr || c.column == SeriesColumn::kPeriodErr;
  const bool ok = c.column == SeriesColumn::kSpacingErr ? value >= 0.0 : value > 0.0;
  if (!ok)
    throw InputError(
        where,
        fmt::format("{}: expected {} {}, found \"{}\"; {}", c.name, c.what,
                    c.column == SeriesColumn::kSpacingErr ? "of 0 or more" : "greater than 0",
                    field.text,
                    c.column == SeriesColumn::kPeriodErr
                        ? "give each period's standard deviation (a period known exactly would "
                          "outweigh every other row)"
                    : error_column ? "give the uncertainty as a positive length"
                                   : "check the row's value and unit"));
  // Beyond any bench (core/plausible_range.hpp): a slip of the unit, refused where it stands.
  const PlausibleRange* range = c.column == SeriesColumn::kSpacing  ? &kSpacingRange
                                : c.column == SeriesColumn::kPeriod ? &kPeriodRange
                                                                    : nullptr;
  if (range != nullptr) {
    if (const std::optional<std::string> why = implausible(value, *range)) {
      const std::string advice =
          plain_number(field.text) ? plain_number_advice(value, field.text, *range) : "";
      throw InputError(where,
                       fmt::format("{}: {}{}", c.name, *why,
                                   advice.empty() ? "; check the row's value and unit" : advice));
    }
  }
  return value;
}

// "file:line:column: warning: what", as format_diagnostic writes an error.
std::string warning_at(const SourceLocation& where, std::string_view what) {
  std::string out = format_diagnostic(where, what);
  out.replace(out.find("error: "), 7, "warning: ");
  return out;
}

}  // namespace

std::vector<SpacingPeriod> SpacingSeries::measurements() const {
  std::vector<SpacingPeriod> out;
  out.reserve(rows.size());
  for (const SpacingSeriesRow& row : rows) out.push_back(row.measurement);
  return out;
}

SourceLocation SpacingSeries::at(std::size_t row, SeriesColumn column) const {
  const SpacingSeriesRow& r = rows.at(row);
  return SourceLocation{file, r.line, r.columns[static_cast<std::size_t>(column)]};
}

SpacingSeries parse_spacing_series(std::string_view text, const std::string& file) {
  const CsvTable table = parse_csv_table(text, file);
  SpacingSeries series;
  series.file = file;
  series.header_line = table.header.front().where.line;
  int status = -1;
  const std::vector<std::optional<SeriesColumn>> order = read_header(table.header, file, &status);
  series.sweep_results = sweep_results_header(table.header);
  for (const auto& c : order) {
    series.has_spacing_err = series.has_spacing_err || c == SeriesColumn::kSpacingErr;
    series.has_label = series.has_label || c == SeriesColumn::kLabel;
  }
  for (const std::vector<CsvCell>& fields : table.rows) {
    const int line_number = fields.front().where.line;
    // A row of frictionlab estimate's table whose log gave no period, or a sweep's point that
    // failed or whose estimator accepted no period.
    if (status >= 0 && fields[static_cast<std::size_t>(status)].text != "ok") {
      ++series.rows_left_out;
      continue;
    }
    if (series.sweep_results) {
      bool no_period = false;
      for (std::size_t i = 0; i < fields.size(); ++i)
        no_period = no_period ||
                    ((order[i] == SeriesColumn::kPeriod || order[i] == SeriesColumn::kPeriodErr) &&
                     fields[i].text.empty());
      if (no_period) {
        ++series.rows_left_out;
        continue;
      }
    }
    SpacingSeriesRow row;
    row.line = line_number;
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (!order[i]) continue;
      const ColumnInfo& c = info(*order[i]);
      row.columns[static_cast<std::size_t>(c.column)] = fields[i].where.column;
      const SourceLocation& where = fields[i].where;
      switch (c.column) {
        case SeriesColumn::kLabel:
          row.label = fields[i].text;
          break;
        case SeriesColumn::kSpacingErr:
          // An empty cell: this row's spacing taken as exact, like a file without the column.
          if (!fields[i].text.empty())
            row.measurement.spacing_err = read_value(fields[i], c, where);
          break;
        case SeriesColumn::kSpacing:
          row.measurement.spacing = read_value(fields[i], c, where);
          if (plain_number(fields[i].text) && row.measurement.spacing >= 2.0)
            series.warnings.push_back(
                warning_at(where, fmt::format("spacing: {} read as {} m (a plain number is SI); "
                                              "write {} mm for millimetres",
                                              fields[i].text, fields[i].text, fields[i].text)));
          break;
        case SeriesColumn::kPeriod:
          row.measurement.period = read_value(fields[i], c, where);
          break;
        case SeriesColumn::kPeriodErr:
          row.measurement.period_err = read_value(fields[i], c, where);
          break;
      }
    }
    series.rows.push_back(std::move(row));
  }
  if (series.rows.size() < 2)
    throw InputError(
        SourceLocation{file, series.rows.empty() ? series.header_line : series.rows.back().line, 0},
        fmt::format("expected at least 2 rows (a straight line T^2 against l needs two "
                    "spacings), found {}; measure the period at other spacings and add a row "
                    "for each",
                    series.rows.size()));
  const double l0 = series.rows.front().measurement.spacing;
  if (std::all_of(series.rows.begin(), series.rows.end(),
                  [l0](const SpacingSeriesRow& r) { return r.measurement.spacing == l0; }))
    throw InputError(
        series.at(series.rows.size() - 1, SeriesColumn::kSpacing),
        fmt::format("expected at least two different spacings, found every row at {:g} mm; T^2 "
                    "against l needs the period at other spacings (move a roller and measure "
                    "again)",
                    l0 * 1e3));
  return series;
}

SpacingSeries read_spacing_series(const std::string& path) {
  return parse_spacing_series(read_text_file(path, "the spacing series"), path);
}

}  // namespace fl
