// frictionlab.track: a phone's video of the rig with its plate followed without clicks, as
// `frictionlab track --json` reports it (lab/request/track_request.hpp), its track.csv and
// track.png written into `out`.
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "lab/request/track_request.hpp"
#include "python/arguments.hpp"
#include "python/bindings.hpp"
#include "python/json_values.hpp"

namespace fl::python {

void bind_track(py::module_& m) {
  m.def(
      "track",
      [](const Path& video, const Path& out, const std::string& roi,
         const std::optional<double>& scale, const std::optional<Quantity>& plate_length) {
        TrackRequest r;
        r.video = video.string();
        r.out = out.string();
        r.roi = roi;
        r.scale = scale;
        if (plate_length) r.plate_length = *plate_length;
        return python_value(track_video(r).json());
      },
      py::arg("video"), py::kw_only(), py::arg("out"), py::arg("roi") = "",
      py::arg("scale") = py::none(), py::arg("plate_length") = py::none(),
      R"(Follows the plate in a phone's video of the rig (MP4, MOV, WebM, MKV, AVI) without
clicks, as `frictionlab track --json` does: writes track.csv (the plate's position at each
frame, a table estimate_file reads) and track.png (what was followed) into `out`, and returns
the report as a dict (video, tracked, unit, mm_per_px, amplitude, period_s, ...). roi="X,Y,W,H"
chooses the region in the video's pixels; scale (mm per pixel) or plate_length gives
millimetres. Bad input raises InputError.)");
}

}  // namespace fl::python
