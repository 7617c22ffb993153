// A spacing series' fit, as every front end asks for it (`frictionlab fit`, frictionlab.fit): the
// series, g, where its files and plot go, the Monte Carlo, and the refit through simulations of a
// rig, and the plate's material for the paper's value. fit_series reads and checks every field
// before any work (problems by field), fits, writes and plots; the result says how it ended
// (lab/request/outcome.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lab/compare/spacing_fit_report.hpp"
#include "lab/logs/paper_comparison.hpp"
#include "lab/request/field_checks.hpp"
#include "lab/request/outcome.hpp"
#include "lab/request/scene_source.hpp"

namespace fl {

struct FitRequest {
  std::string series;                                 // "series": the CSV
  QuantityInput gravity = std::string("9.81 m/s^2");  // "gravity"
  std::string out;                                    // "out": folder for fit.csv, fit.json
  // "plot": a PNG of T^2 against l; "" draws it to out/fit.png.
  std::optional<std::string> plot;
  std::optional<std::int64_t> mc;  // "mc": Monte Carlo draws
  std::uint64_t seed = 1;          // "seed": the Monte Carlo's
  bool through_rig = false;        // "through_rig": refit through simulations of `scene`
  SceneSource scene;               // "scene": its file empty, scenes/minimal.yaml
  std::vector<std::string> set;    // "set": the rig's overrides
  int jobs = 0;                    // "jobs": rows simulated in parallel (0: every core)
  // "material", "temperature": the plate's, for the paper's value beside the fitted mu_k.
  std::optional<std::string> material;
  std::optional<QuantityInput> temperature;
  std::string assets;  // "assets": the lab's data folder (the paper's table; "": the default)
};

struct FitResult {
  SpacingFitReport report;
  nlohmann::json json;                // fit.json's object (docs/cli.md)
  std::vector<std::string> written;   // the files written, the plot among them
  std::string plot;                   // the PNG drawn, if any
  std::string plot_failure;           // why the plot could not be drawn
  std::string rig_failure;            // why the refit through the rig failed (the fit stands)
  std::vector<std::string> warnings;  // the series reader's, and the fields' (field_ref mentions)
  // The paper's value for the material named, beside the fitted mu_k (in json as "paper").
  std::optional<PaperComparison> paper;

  Outcome outcome() const;
};

// Reads and checks the request (RequestError by field; InputError located in the series), then
// fits and writes.
FitResult fit_series(const FitRequest& request);

}  // namespace fl
