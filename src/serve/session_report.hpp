// A session's lab report (POST /api/sessions/ID/report): its finished run's files reported as
// `frictionlab report` reports a run's folder (lab/request/report_request.hpp), with the student's
// name and the stopwatch's timings the page sends. The same answer over HTTP and in the page's
// worker.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "serve/lab_session.hpp"

namespace fl::serve {

struct ReportAnswer {
  int status = 200;
  std::string html;     // 200: the report
  nlohmann::json body;  // otherwise: the error's body
};

// 409 before the run has ended, 400 for a body it cannot take. `version`: "frictionlab 1.2.0".
ReportAnswer session_report(LabSession& session, std::string_view body,
                            const std::string& asset_dir, const std::string& version);

}  // namespace fl::serve
