// A build without minizip (FRICTIONLAB_WITH_ZIP=OFF) reads no zip: it names it and says what to
// do instead.
#include "hall_log/measurement_zip.hpp"
#include "io/input_error.hpp"

namespace fl {

ZipMeasurement measurement_in_zip(std::string_view bytes, const std::string& name) {
  throw InputError(SourceLocation(name), not_a_rig_log(recognise_measurement_file(bytes)) +
                                             " (this build was made without minizip: apt-get "
                                             "install libminizip-dev and build again)");
}

bool reads_zips() {
  return false;
}

}  // namespace fl
