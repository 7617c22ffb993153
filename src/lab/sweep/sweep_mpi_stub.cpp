// A build without MPI (FRICTIONLAB_WITH_MPI=OFF): the MPI runner fails clearly.
#include "io/field_ref.hpp"
#include "lab/sweep/sweep_run.hpp"

namespace fl {

bool sweep_has_mpi() {
  return false;
}

SweepOutcome run_sweep_mpi(const SweepSpec& /*spec*/, const SweepRunOptions& /*options*/) {
  throw InputError(SourceLocation{},
                   "this frictionlab was built without MPI (FRICTIONLAB_WITH_MPI=OFF): install "
                   "libopenmpi-dev and reconfigure, or use " +
                       field_ref("shard", "K/N") + " and merge the shards");
}

}  // namespace fl
