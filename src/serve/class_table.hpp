// The class's table (docs/web-api.md, "The class's table"): every open session's set-up and
// result, like the paper's Table I filled by a class, as JSON for the teacher's page and as CSV.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/paper_table.hpp"
#include "scene/compiled_rig.hpp"
#include "serve/board_feed.hpp"

namespace fl::serve {

// Where a session's run stands: the estimate so far, or the summary's once it is done.
struct SessionStanding {
  std::string state;                 // "paused", "playing" or "done"
  double t = 0.0;                    // s, simulated
  std::optional<double> period;      // s, mean of the accepted periods
  std::optional<double> period_err;  // s, the standard error of that mean (two periods on)
  // "sensor" (the Hall sensor's estimator) or "trajectory" (fitted to the plate's motion, for a
  // rig without a sensor, once done); "" : no period yet.
  std::string period_from;
  std::optional<double> mu_k;      // the paper's (thin) formula
  std::optional<double> mu_k_err;  // in quadrature (two periods on)
};

struct ClassRow {
  std::string session;
  std::string name;  // "" : not given
  std::string scene;
  std::shared_ptr<const CompiledRig> rig;
  SessionStanding standing;
};

nlohmann::json class_json(const std::vector<ClassRow>& rows, const PaperTable& table,
                          const std::optional<BoardFeedStatus>& rig);

// The columns the web API declares for a class row (api/api_fields.hpp, docs/web-api.md), in its
// order; an empty cell for a value that is null in the JSON.
std::string class_csv(const std::vector<ClassRow>& rows, const PaperTable& table);

}  // namespace fl::serve
