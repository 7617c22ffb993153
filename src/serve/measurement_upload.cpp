#include "serve/measurement_upload.hpp"

#include <cctype>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string_view>

#include "api/api_fields.hpp"
#include "io/input_error.hpp"
#include "lab/request/estimate_request.hpp"
#include "serve/api_json.hpp"
#include "serve/temporary_folder.hpp"
#include "serve/web_spelling.hpp"

namespace fl::serve {

std::string upload_name(const std::string& given) {
  std::string name = given.substr(
      given.find_last_of("/\\") == std::string::npos ? 0 : given.find_last_of("/\\") + 1);
  for (char& c : name) {
    const auto u = static_cast<unsigned char>(c);
    if (!(std::isalnum(u) != 0 || c == '.' || c == '-' || c == '_' || c == ' ' || c == '(' ||
          c == ')'))
      c = '_';
  }
  if (name.size() > 100) name.erase(0, name.size() - 100);
  if (name.empty() || name == "." || name == "..") name = "measurement";
  return name;
}

UploadAnswer estimate_upload(const MeasurementUpload& upload, const std::string& asset_dir) {
  const std::string name = upload_name(upload.name);
  try {
    const TemporaryFolder folder;
    const std::optional<std::filesystem::path> file = folder.keep(name, upload.bytes);
    if (!file)
      return {500, error_json("the server could not keep the file to read it (its disk may "
                              "be full); try again, or estimate it with frictionlab estimate")};
    const std::string prefix = folder.prefix();
    try {
      EstimateRequest request;
      request.assets = asset_dir;
      request.logs = {file->string()};
      if (upload.spacing) request.spacing = *upload.spacing;
      if (upload.h_c) request.h_c = *upload.h_c;
      const OneLogEstimate result = estimate_one_log(prepare_estimate(request));
      const nlohmann::json all = result.json();
      nlohmann::json body = nlohmann::json::object();
      // The keys the web API declares for it (api/api_fields.cpp), from the estimate's.
      for (const api::ApiObject& o : api::api_declaration().objects)
        if (std::string_view(o.name) == "MeasurementEstimate")
          for (const api::ApiKey& key : o.keys)
            body[key.name] = all.value(key.name, nlohmann::json());
      return {200, without_folder(std::move(body), prefix)};
    } catch (const RequestError& e) {
      // A field of the request (spacing, h_c): by field, beside its control.
      return {400, without_folder(problems_json(e), prefix)};
    } catch (const InputError& e) {
      // The file's own trouble, located in it.
      return {400, without_folder(file_problem_json(e), prefix)};
    } catch (const std::invalid_argument& e) {
      return {400, without_folder(problems_json(e), prefix)};
    } catch (const std::runtime_error& e) {
      return {400, without_folder(error_json(e.what()), prefix)};
    }
  } catch (const std::runtime_error& e) {
    return {500, error_json(e.what())};
  }
}

}  // namespace fl::serve
