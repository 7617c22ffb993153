// An estimate from a real rig's Hall signal, as every front end asks for it (`frictionlab
// estimate`, frictionlab.estimate_file and frictionlab.estimate): one log, several logs (a table),
// the rig's serial port followed live, or samples given as arrays; the rig they were taken on,
// how to read them, the plot and the Monte Carlo of mu_k. The defaults are the paper's rig, here
// once. prepare_estimate reads and checks every field (problems by field) and says which of the
// three jobs it is; estimate_one_log and estimate_log_table run the first two (the live one is
// the front end's, on the prepared settings).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hall_log/hall_log.hpp"
#include "hall_log/serial_port.hpp"
#include "lab/analytic/analytic_report.hpp"
#include "lab/logs/geometry_check.hpp"
#include "lab/logs/log_estimate.hpp"
#include "lab/logs/log_table.hpp"
#include "lab/logs/paper_comparison.hpp"
#include "lab/request/field_checks.hpp"
#include "lab/request/material_fields.hpp"
#include "lab/request/outcome.hpp"

namespace fl {

struct EstimateRequest {
  std::string assets;  // "assets": the lab's data folder (the paper's table; "" : the default)
  std::vector<std::string> logs;                      // "logs": files, folders, patterns, "-"
  std::optional<HallLog> samples;                     // instead of logs: a signal given as arrays
  QuantityInput spacing = std::string("89 mm");       // "spacing": l, the paper's rig
  QuantityInput spacing_err = std::string("2 mm");    // "spacing_err": dl
  QuantityInput gravity = std::string("9.81 m/s^2");  // "gravity"
  std::string geometry = "auto";                      // "geometry": auto, one or pair
  std::string columns;                                // "columns": the log's fields in order
  std::optional<QuantityInput> rate;                  // "rate": time samples by their count
  std::string time_unit;                              // "time_unit": us, ms or s
  std::string roi;                                    // "roi": a video's region, X,Y,W,H
  std::optional<double> scale;                        // "scale": a video's mm per pixel
  std::optional<QuantityInput> plate_length;          // "plate_length": or the plate's length
  std::string plot;                                   // "plot": one log's signal, a PNG
  std::string out;                                    // "out": several logs' table's folder
  std::optional<std::string> material;                // "material": several logs
  std::optional<QuantityInput> temperature;           // "temperature": several logs
  std::string follow_port;                            // "follow.port": the rig's serial port
  std::optional<QuantityInput> follow_baud;           // "follow.baud" (250000)
  std::string follow_raw_log;                         // "follow.raw_log": the lines received
  std::optional<QuantityInput> follow_duration;       // "follow.duration": stop after
  std::optional<std::int64_t> mc;                     // "monte_carlo.draws": one log's mu_k
  std::uint64_t seed = 1;                             // "seed"
  std::optional<QuantityInput> h_c;                   // "h_c": mu_k_thick (and with mc its draws)
  std::optional<QuantityInput> h_c_err;               // "h_c_err": with mc
  std::string mc_plot;                                // "mc_plot": with mc, the histogram
};

enum class EstimateJob { kOneLog, kLogTable, kFollow };

// A request read and checked, for the job it is.
struct PreparedEstimate {
  EstimateJob job = EstimateJob::kOneLog;
  LogSetUp set_up;
  HallLogOptions reading;
  std::string log;                 // one log ("-": standard input)
  std::optional<HallLog> samples;  // or its samples
  std::vector<std::string> logs;   // the table's logs, found
  std::string plot;
  std::string out;
  LogTableDefaults table;  // the table's defaults (set-up, material, temperature)
  std::optional<MonteCarloRequest> monte_carlo;
  double h_c_err = 0.0;  // m, for the Monte Carlo (h_c itself is set_up.h_c)
  std::string mc_plot;
  // One log's material (a key or name of the paper's Table I) and temperature [K], for the
  // paper's value beside its result; the log's sidecar may name them instead.
  MaterialChoice material;
  const PaperTable* paper = nullptr;
  std::string follow_port;
  double follow_baud = kFirmwareBaud;
  std::string follow_raw_log;
  std::optional<double> follow_duration;  // s
  std::vector<std::string> warnings;      // field_ref mentions, for the front end to spell
};

PreparedEstimate prepare_estimate(const EstimateRequest& request);

struct OneLogEstimate {
  HallLog log;
  LogEstimate estimate;
  GeometryCheck check;
  std::string sidecar_note;  // what the log's sidecar set, if it had one
  // What the front end says before the result: a geometry given that the log contradicts
  // (field_ref mentions, for the front end to spell).
  std::vector<std::string> warnings;
  std::optional<AnalyticReport> monte_carlo;
  std::string plot;  // the PNGs drawn
  std::string mc_plot;
  std::string plot_failure;  // why a plot could not be drawn (the estimate stands)
  // The paper's value for the log's material (the request's, or its sidecar's), when known.
  std::optional<PaperComparison> paper;

  // `frictionlab estimate --json`'s object (docs/cli.md).
  nlohmann::json json() const;
  Outcome outcome() const;
};

// One log (or the samples): read, with its sidecar over the request's rig, estimated, held to the
// geometry check, its mu_k by Monte Carlo when asked; throws InputError, located in the log, when
// it gives no T +- dT.
OneLogEstimate estimate_one_log(const PreparedEstimate& prepared);

struct LogTableResult {
  std::vector<LogTableRow> rows;
  std::vector<std::string> written;  // estimates.csv, estimates.json

  nlohmann::json json() const;  // {"logs": [...]}
  int failed() const;           // the logs that gave no period
  Outcome outcome() const;
};

LogTableResult estimate_log_table(const PreparedEstimate& prepared);

}  // namespace fl
