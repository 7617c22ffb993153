// What a lab report holds: one part per run or measurement (its set-up, its data, its period and
// mu_k with their uncertainties, the paper's Table I row and theory beside them), the student's
// stopwatch timings, and who handed it in. Filled from a run's files (run_report_part.hpp) or from
// a measurement's estimate; written as HTML by report_html.hpp.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace fl {

// One period as the estimator judged it.
struct ReportPeriod {
  double start_s = 0;
  double end_s = 0;
  double period_s = 0;
  bool accepted = false;
};

// A curve of the part's data: its times and values, in the unit its label says.
struct ReportCurve {
  std::string label;  // "x (mm)", "Hall sensor (ADC counts)"
  std::vector<double> t_s;
  std::vector<double> value;
};

// The paper's measurement for the part's material (Table I).
struct ReportPaperRow {
  std::string key;       // "lego": its words are the catalogues' material-KEY
  std::string material;  // "LEGO blocks", as Table I names it
  double temperature_k = 300;
  double period_s = 0;
  double period_err_s = 0;
  double mu_k = 0;
  double mu_k_err = 0;
};

// A value the report shows: its number (null where the lab did not measure it) and the summary's
// field it comes from, so the report's numbers are the files' (data-field, data-value).
struct ReportNumber {
  std::optional<double> value;
  std::string field;  // "period_s"
};

// A row of a part's set-up: what (the report's catalogue's message `report-setup-ID`) and its
// value with its unit, its numbers with a decimal point (shown in the report's language).
struct SetUpRow {
  std::string id;  // "spacing"
  std::string value;
  bool numeric = true;  // false: a name or a file, shown as it is
  // The catalogues' message that says the value in the report's language (material-lego); empty
  // for a value shown as it is.
  std::string message = {};
};

struct ReportPart {
  std::string title;  // the scene's name, or the measurement's file as given
  bool simulated = false;
  std::string source;  // the folder or file it was read from, as given
  std::vector<SetUpRow> set_up;
  double spacing_m = 0.089;
  double spacing_err_m = 0.002;  // dl, in mu_k's uncertainty
  double gravity_m_s2 = 9.81;
  std::optional<ReportCurve> position;  // x(t), the whole run
  std::optional<ReportCurve> signal;    // the Hall signal or the measurement's channel
  std::vector<ReportPeriod> periods;
  ReportNumber period;          // T: the mean of the accepted periods
  ReportNumber period_sd;       // their standard deviation
  ReportNumber period_se;       // its standard error, sd / sqrt(N)
  ReportNumber periods_used;    // N
  ReportNumber mu_k;            // 2 pi^2 l / (g T^2)
  ReportNumber mu_k_err;        // in quadrature: dl / l and 2 sd / T
  ReportNumber mu_k_err_worst;  // their sum
  ReportNumber period_thin;     // theory for the set mu_k (a simulation)
  ReportNumber period_thick;
  ReportNumber mu_k_set;    // what the simulation was given
  ReportNumber mu_k_thick;  // mu_k from T through the thick formula, with the plate's h_c
  std::string regime;       // what the trajectory showed (a simulation)
  std::optional<ReportPaperRow> paper;
};

// A measurement as the lab's estimate of it reported it (`estimate --json`'s numbers, the page's
// "Your measurement"): its part of a report, without its samples.
struct MeasuredSummary {
  std::string file;
  std::string instrument;
  std::string channel;  // "" : one
  double samples = 0;
  double sample_rate_hz = 0;
  double duration_s = 0;
  double periods_used = 0;
  double period_s = 0;
  double period_std_s = 0;
  double period_sem_s = 0;
  double mu_k = 0;
  double mu_k_err_quadrature = 0;
  double mu_k_err_worst = 0;
  double spacing_m = 0;
};

// The student's stopwatch: periods timed by hand between two presses.
struct StopwatchTiming {
  int periods = 10;
  double wall_s = 0;                  // between the presses, on the wall clock
  std::optional<double> simulated_s;  // the simulated time between them (a simulation)
};

struct ReportContent {
  std::string language = "en";  // the catalogue's (assets/locales/LANG.ftl)
  std::string student;          // "" : not given
  std::string lab_version;      // "frictionlab 1.2.0"
  std::string date;             // "2026-11-29"
  std::vector<ReportPart> parts;
  std::vector<StopwatchTiming> stopwatch;
};

}  // namespace fl
