#include "serve/session_report.hpp"

#include <stdexcept>

#include "io/input_error.hpp"
#include "lab/request/report_request.hpp"
#include "serve/api_json.hpp"
#include "serve/api_requests.hpp"

namespace fl::serve {

ReportAnswer session_report(LabSession& session, std::string_view body,
                            const std::string& asset_dir, const std::string& version) {
  const auto read = read_report_body(body);
  if (const auto* refusal = std::get_if<BodyRefusal>(&read))
    return {400, "", refusal_json(*refusal)};
  const ReportBody& asked = std::get<ReportBody>(read);
  if (!session.file("summary.json"))
    return {409, "",
            error_json("the run has not ended: its report comes once it has (play it to its "
                       "end)")};
  ReportRequest request;
  request.assets = asset_dir;
  request.student = asked.student.value_or(session.name());
  request.stopwatch = asked.stopwatch;
  request.language = asked.language;
  if (asked.measured) request.measured.push_back(*asked.measured);
  request.lab_version = version;
  const RunFiles files = [&session](const std::string& name) { return session.file(name); };
  try {
    return {200, report_of_runs({{session.scene(), files}}, request).html, nullptr};
  } catch (const RequestError& e) {
    return {400, "", problems_json(e)};
  } catch (const InputError& e) {
    return {400, "", problems_json(e)};
  } catch (const std::invalid_argument& e) {
    return {400, "", error_json(e.what())};
  }
}

}  // namespace fl::serve
