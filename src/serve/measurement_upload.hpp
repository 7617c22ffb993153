// A measurement file a page sends (POST /api/estimate): written whole to a private temporary
// folder under the name the page gave it, read by the readers `frictionlab estimate` uses (a rig's
// Hall log, phyphox's CSVs and zip, Tracker's data, a table, a phone's video), estimated with the
// page's spacing, and answered with the keys the page shows (MeasurementEstimate in
// docs/web-api.md). The folder goes when the answer is made; messages name the file as the page
// named it, never the server's folder.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace fl::serve {

struct MeasurementUpload {
  std::string name;                    // ?name=: the file's name on the student's machine
  std::string bytes;                   // the body: the file
  std::optional<std::string> spacing;  // ?spacing=: l (a quantity; plain: metres)
  std::optional<std::string> h_c;      // ?h_c=: the plate's centre of mass, for mu_k_thick
};

struct UploadAnswer {
  int status = 200;
  nlohmann::json body;
};

// The file's name as the answer and the messages give it: its last part, characters other than
// letters, digits, ".", "-", "_", " ", "(" and ")" as "_", at most 100; "measurement" for none.
std::string upload_name(const std::string& given);

// 200 with the estimate; 400 with the reader's located message (a file that gives no period, one
// of another experiment) or the field's problem; 500 when the file cannot be written here.
UploadAnswer estimate_upload(const MeasurementUpload& upload, const std::string& asset_dir);

}  // namespace fl::serve
