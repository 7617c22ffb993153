// The paper's Table I with mu_k recomputed from each measured period, as every front end asks
// for it (`frictionlab table`, frictionlab.table): the rows with the paper's printed mu_k beside
// the thin formula's and the thick plate's for a given h_c, and which printed values the printed
// T, dT, l and dl do not give. The request owns its defaults and checks (problems by field).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/paper_table.hpp"
#include "lab/request/field_checks.hpp"

namespace fl {

struct TableRequest {
  QuantityInput gravity{"9.81 m/s^2"};  // "gravity": g for the recomputed mu_k
  QuantityInput h_c{"0 mm"};            // "h_c": the plate's, for the thick-plate column
  std::string assets;                   // "assets": the lab's data
};

struct TableRow {
  PaperMaterial material;
  PaperMeasurement measured;
  RecomputedRow thin;    // mu_k from T through the paper's formula, and whether it agrees
  MuKUncertainty thick;  // through the thick plate's, at the request's h_c
  bool disagrees() const { return !thin.mu_k_agrees || !thin.uncertainty_agrees; }
};

struct TableResult {
  std::string file;  // the table's file
  PaperTable table;
  double gravity = 9.81;       // m/s^2
  double h_c = 0.0;            // m
  std::vector<TableRow> rows;  // every measurement, 300 K then 77 K per material

  int disagreements() const;
  nlohmann::json json() const;  // `table --json`'s object (docs/cli.md)
};

TableResult paper_table_recomputed(const TableRequest& request);

}  // namespace fl
