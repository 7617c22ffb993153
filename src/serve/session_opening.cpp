#include "serve/session_opening.hpp"

#include <stdexcept>

#include "io/input_error.hpp"
#include "lab/request/lab_data.hpp"
#include "serve/api_json.hpp"

namespace fl::serve {

SessionOpening open_session(const SessionBody& asked, const std::string& scenes_dir,
                            const std::string& asset_dir, double most_recorded_seconds) {
  SessionOpening out;
  try {
    // Only a scene inside the folder is read: a link leading outside is as if absent.
    PreparedSession prepared = prepare_session(asked.request, scenes_dir, asset_dir);
    if (prepared.rig->world.duration > most_recorded_seconds) {
      prepared.output.trajectory = false;
      prepared.output.hall = false;
    }
    const std::vector<AcceptedRange> accepts = prepared.accepts;
    out.session =
        std::make_shared<LabSession>(asked.request.scene, std::move(prepared), asked.name);
    out.body = {{"rig", rig_json(asked.request.scene, out.session->rig(), accepts,
                                 paper_table_in(asset_dir))}};
  } catch (const InputError& e) {
    out.body = problems_json(e);
  } catch (const std::invalid_argument& e) {
    // UnitError, DomainError: a value the lab refused.
    out.body = problems_json(e);
  }
  return out;
}

}  // namespace fl::serve
