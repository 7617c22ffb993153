// A lab report, as every front end asks for it (`frictionlab report`, frictionlab.report, the
// page's "Lab report"): the runs and measurements it reports, who hands it in, the stopwatch's
// timings, and where to write it. A run is a folder `run --out` wrote (its summary.json); anything
// else is a measurement, read and estimated as `estimate` reads it, with `measurement`'s rig.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lab/report/report_content.hpp"
#include "lab/report/report_html.hpp"
#include "lab/report/report_parts.hpp"
#include "lab/request/estimate_request.hpp"

namespace fl {

struct ReportRequest {
  std::string assets;                      // "assets": the lab's data folder ("" : the default)
  std::vector<std::string> inputs;         // "inputs": run folders and measurement files, in order
  std::string out;                         // "out": the HTML file ("" : not written)
  std::string student;                     // "student": who hands it in
  std::vector<StopwatchTiming> stopwatch;  // "stopwatch": periods timed by hand
  std::vector<MeasuredSummary> measured;   // measurements, as their estimates reported them
  EstimateRequest measurement;  // the measurements' rig and reading (spacing, material, ...)
  std::string lab_version;      // the front end's version, in the report's footer
  std::string date;             // "YYYY-MM-DD" ("" : today, UTC)
  std::string language = "en";  // "language": a catalogue of assets/locales (en, fr, ...)
};

struct ReportResult {
  std::string html;
  std::string written;  // the file written ("" : none)
  ReportContent content;

  // {"written", "parts": [{"title", "period_s", "mu_k", ...}]}: what the report says, in numbers.
  nlohmann::json json() const;
};

// The languages the lab's data offers a report in: each assets/locales/LANG.ftl, by name.
std::vector<std::string> report_languages(const std::string& asset_dir);

// The report's words in `language`, English's beside them (assets/locales/LANG.ftl).
ReportTexts report_texts(const std::string& assets, const std::string& language);

// Throws RequestError (every problem by field) or InputError located in the file at fault.
ReportResult make_report(const ReportRequest& request);

// A report of runs already in hand (a session's), by their files, then of the request's measurement
// files (its inputs, read at its measurement's spacing) and measured summaries.
ReportResult report_of_runs(const std::vector<std::pair<std::string, RunFiles>>& runs,
                            const ReportRequest& request);

}  // namespace fl
