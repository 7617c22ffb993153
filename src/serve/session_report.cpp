#include "serve/session_report.hpp"

#include <filesystem>
#include <optional>
#include <stdexcept>

#include "io/input_error.hpp"
#include "lab/request/report_request.hpp"
#include "serve/api_json.hpp"
#include "serve/api_requests.hpp"
#include "serve/measurement_upload.hpp"
#include "serve/temporary_folder.hpp"

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
  request.lab_version = version;
  // The measurement's file, read again as POST /api/estimate read it (at its spacing), gives the
  // report its signal and periods; without it, its numbers as the page was answered.
  std::optional<TemporaryFolder> folder;
  if (asked.measurement_file) {
    folder.emplace();
    const std::optional<std::filesystem::path> file =
        folder->keep(upload_name(asked.measurement_file->name), asked.measurement_file->bytes);
    if (!file)
      return {500, "",
              error_json("the server could not keep the measurement's file to read it (its disk "
                         "may be full); try again")};
    request.inputs = {file->string()};
    request.measurement.spacing = asked.measured->spacing_m;
  } else if (asked.measured) {
    request.measured.push_back(*asked.measured);
  }
  const std::string prefix = folder ? folder->prefix() : std::string();
  const auto scrubbed = [&prefix](nlohmann::json answer) {
    return prefix.empty() ? answer : without_folder(std::move(answer), prefix);
  };
  const RunFiles files = [&session](const std::string& name) { return session.file(name); };
  try {
    std::string html = report_of_runs({{session.scene(), files}}, request).html;
    return {200, prefix.empty() ? std::move(html) : without_folder(std::move(html), prefix),
            nullptr};
  } catch (const RequestError& e) {
    return {400, "", scrubbed(problems_json(e))};
  } catch (const InputError& e) {
    return {400, "", scrubbed(folder ? file_problem_json(e) : problems_json(e))};
  } catch (const std::invalid_argument& e) {
    return {400, "", scrubbed(error_json(e.what()))};
  }
}

}  // namespace fl::serve
