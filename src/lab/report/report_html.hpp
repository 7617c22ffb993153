// A lab report as one self-contained HTML file a student hands in or prints to PDF: the method
// with the paper cited, each part's set-up, data (figures as inline SVG, the periods' table),
// T +- dT and mu_k +- d mu_k with where each uncertainty comes from, the comparison with the
// paper's Table I and with theory or the simulation, the stopwatch's timings. A print stylesheet
// lays it on A4 or Letter, whichever the printer has. Every number the lab measured carries its
// source field and exact value (data-field, data-value); one it did not is shown as "—".
#pragma once

#include <map>
#include <string>

#include "lab/report/report_content.hpp"
#include "text/message_catalogue.hpp"

namespace fl {

// The report's words in its language: the language's catalogue, English's where it lacks one
// (assets/locales/LANG.ftl, its `report-*` messages).
struct ReportTexts {
  MessageCatalogue language;
  MessageCatalogue english;

  // The message, filled; English's where the language lacks it; the id itself where both do.
  std::string operator()(const std::string& id,
                         const std::map<std::string, std::string>& args = {}) const;
  // The message without values where a catalogue has it; else `given` (a name as the lab has it).
  std::string named(const std::string& id, const std::string& given) const;
  // "." or "," (the message report-decimal-sign).
  std::string decimal_sign() const;
};

std::string report_html(const ReportContent& content, const ReportTexts& texts);

}  // namespace fl
