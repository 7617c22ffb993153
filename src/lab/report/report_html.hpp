// A lab report as one self-contained HTML file a student hands in or prints to PDF: the method
// with the paper cited, each part's set-up, data (figures as inline SVG, the periods' table),
// T +- dT and mu_k +- d mu_k with where each uncertainty comes from, the comparison with the
// paper's Table I and with theory or the simulation, the stopwatch's timings. A print stylesheet
// lays it on A4 or Letter, whichever the printer has. Every number the lab measured carries its
// source field and exact value (data-field, data-value); one it did not is shown as "—".
#pragma once

#include <string>

#include "lab/report/report_content.hpp"

namespace fl {

std::string report_html(const ReportContent& content);

}  // namespace fl
