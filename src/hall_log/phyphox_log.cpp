#include "hall_log/phyphox_log.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "hall_log/instrument_signal.hpp"
#include "hall_log/measurement_table.hpp"
#include "hall_log/periodic_motion.hpp"
#include "io/input_error.hpp"
#include "text/text.hpp"

namespace fl {
namespace {

struct Channel {
  std::string name;    // "x", "y", "z", "|B|"
  std::string column;  // the header's name ("" for |B| computed)
  std::vector<double> values;
};

std::vector<Channel> field_channels(const MeasurementTable& t, const std::string& name) {
  std::array<std::optional<std::size_t>, 3> component;
  std::optional<std::size_t> absolute;
  for (std::size_t k = 0; k < t.names.size(); ++k) {
    const std::string lower = ascii_lower(t.names[k]);
    if (lower.rfind("absolute field", 0) == 0) absolute = k;
    for (std::size_t axis = 0; axis < 3; ++axis)
      if (lower.rfind(std::string("magnetic field ") + "xyz"[axis], 0) == 0) component[axis] = k;
  }
  std::vector<Channel> channels;
  for (std::size_t axis = 0; axis < 3; ++axis)
    if (component[axis])
      channels.push_back(
          {std::string(1, "xyz"[axis]), t.names[*component[axis]], t.columns[*component[axis]]});
  if (absolute) {
    channels.push_back({"|B|", t.names[*absolute], t.columns[*absolute]});
  } else if (component[0] && component[1] && component[2]) {
    Channel b{"|B|", "", {}};
    for (std::size_t i = 0; i < t.lines.size(); ++i)
      b.values.push_back(std::hypot(t.columns[*component[0]][i], t.columns[*component[1]][i],
                                    t.columns[*component[2]][i]));
    channels.push_back(std::move(b));
  }
  if (channels.empty())
    throw InputError(
        SourceLocation(name, t.header_line),
        "expected phyphox's magnetometer columns (\"Magnetic field x (\xC2\xB5T)\", ... or "
        "\"Absolute field (\xC2\xB5T)\") in the header, found none");
  return channels;
}

}  // namespace

HallLog read_phyphox_magnetometer(std::string_view text, const std::string& name) {
  const MeasurementTable table = read_measurement_table(text, name);
  const std::vector<Channel> channels = field_channels(table, name);
  std::vector<const std::vector<double>*> values;
  for (const Channel& c : channels) values.push_back(&c.values);
  const Channel& channel = channels[clearest(values)];
  const Series series = series_of(table, 0, channel.values);
  require_periodic_motion(series, SourceLocation(name, table.header_line),
                          instrument_said(MeasurementFile::kPhyphoxMagnetometer),
                          channel.column.empty()
                              ? said("column-field-magnitude")
                              : said("column-named", {arg("name", channel.column)}));
  HallLog log = log_of_signal(series, name);
  say_what_was_read(log, table, 0, MeasurementFile::kPhyphoxMagnetometer, channel.name, "phyphox",
                    channel.column.empty() ? "|B| of the three components" : channel.column);
  return log;
}

}  // namespace fl
