// The numerics' two studies, as every front end asks for them: the work-precision study of one
// scene (`frictionlab accuracy`) and the stability catalogue (`frictionlab stability`). Each
// request owns its defaults, reads and checks its fields before any run (problems by field), runs,
// writes its files, and says how it ended (lab/request/outcome.hpp): a study's plot that cannot be
// drawn leaves it incomplete, a case that ends in another regime than theory's fails the
// catalogue.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lab/request/field_checks.hpp"
#include "lab/request/outcome.hpp"
#include "lab/request/scene_source.hpp"
#include "lab/studies/accuracy_study.hpp"
#include "lab/studies/stability_study.hpp"

namespace fl {

struct AccuracyRequest {
  SceneSource scene;                      // "scene"
  std::vector<std::string> set;           // "set": overrides, but not what the grid sets
  std::optional<QuantityInput> duration;  // "duration": refused, the grid's length is `periods`
  int periods = 10;                       // "periods": simulated per point, 3 to 1000
  std::string out = "out/accuracy";       // "out"
  bool plot = false;                      // "plot": out/accuracy.png
};

struct AccuracyResult {
  std::string scene;
  int periods = 0;
  AccuracyStudy study;
  std::vector<std::string> written;
  std::string plot_failure;

  nlohmann::json json() const;  // accuracy.json's object
  Outcome outcome() const;      // interrupted when the study was asked to stop
};

// Asked to stop (control), it writes the points finished and ends interrupted.
AccuracyResult study_accuracy(const AccuracyRequest& request, const JobControl& control = {});

struct StabilityRequest {
  std::string dir;          // "dir": the catalogue's folder (the source tree's scenes/extreme)
  std::string only;         // "only": the cases whose name holds this
  std::optional<int> jobs;  // "jobs": cases at once (every core)
  std::string out;          // "out": stability.csv and stability.json
  std::string assets;       // "assets"
};

struct StabilityResult {
  std::string dir;
  std::vector<StabilityRow> rows;  // the cases run, in the catalogue's order
  std::vector<std::string> written;
  int not_run = 0;  // cases left when the catalogue was asked to stop

  int unexpected() const;       // cases that ended in another regime than theory's
  nlohmann::json json() const;  // {"cases": [...], "unexpected": N}
  Outcome outcome() const;
};

// Asked to stop (control), it starts no more cases, finishes those running, writes them and ends
// interrupted.
StabilityResult study_stability(const StabilityRequest& request, const JobControl& control = {});

// The catalogue's folder when a request names none.
std::string default_stability_dir();

}  // namespace fl
