// A log's sidecar: a small YAML file beside a Hall-sensor log, with the same name and the
// extension .yaml (lego-l070.csv and lego-l070.yaml), saying what the log alone cannot: the rig's
// roller spacing and the plate's material, when several logs are estimated at once.
//
//   label: LEGO at 70 mm       # the row's name in the table (default: the log's file name)
//   spacing: 70 mm             # l, and its uncertainty dl
//   spacing_err: 1 mm
//   material: lego             # the plate's material and the rollers' temperature, carried to
//   temperature: 300 K         # the table for frictionlab compare --measured
//   gravity: 9.81 m/s^2
//   geometry: one              # pulses per period: auto, one or pair
#pragma once

#include <optional>
#include <string>

#include "core/paper_table.hpp"

namespace fl {

struct LogSidecar {
  std::string file;  // the sidecar read
  std::optional<std::string> label;
  std::optional<double> spacing;      // m
  std::optional<double> spacing_err;  // m
  std::optional<double> gravity;      // m/s^2
  std::optional<std::string> material;
  std::optional<double> temperature;    // K
  std::optional<std::string> geometry;  // "auto", "one" or "pair"
};

// The sidecar's path for a log: the log's path with its extension replaced by .yaml.
std::string log_sidecar_path(const std::string& log);

// The log's sidecar, or nothing when the log has none. Throws InputError located in the sidecar
// for an unknown key, a value of the wrong kind or beyond any bench, or (with `materials`) a
// material the paper's table does not have.
std::optional<LogSidecar> read_log_sidecar(const std::string& log,
                                           const PaperTable* materials = nullptr);

}  // namespace fl
