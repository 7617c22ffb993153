// A run's summary for a person to read (what `frictionlab run` prints): a line a finding, each
// with its label in the left column. The lines are declared once, in order, each with the run's
// fields it shows (their summary.json keys, lab/run/summary_fields.hpp); a test holds the two
// declarations to each other: every line shows declared fields, and every field summary.json
// carries is shown by a line or said to be left out of the text.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lab/run/run_summary.hpp"

namespace fl {

struct SummaryLine {
  const char* label = "";          // the left column ("regime", "period (Hall estimator)")
  std::vector<const char*> shows;  // the summary.json keys of the fields it shows
  // What follows the label; none when the run has nothing for this line.
  std::optional<std::string> (*text)(const RunSummary&) = nullptr;
  // Printed for every run, saying so when its fields were not measured ("none measured").
  bool always = false;
};

// Every line, in the order printed.
const std::vector<SummaryLine>& summary_lines();

// The summary.json keys the text leaves out, each with why (the JSON and the files carry them).
struct TextOmission {
  const char* key = "";
  const char* why = "";
};
const std::vector<TextOmission>& summary_text_omissions();

// The summary: its first line names the scene and seed, then every line the run has.
std::string summary_text(const RunSummary& summary);

}  // namespace fl
