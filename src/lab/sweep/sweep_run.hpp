// Running a sweep: its folder (the plan, one small file per finished point, the final files), the
// points run in parallel on local worker threads or across MPI ranks, resume, shards and merge.
//
// A sweep folder holds
//   plan.json            every point's overrides; a folder belongs to one plan
//   points/NNNNNNNN.json one per finished point, written atomically (temporary file, fsync,
//                        rename, fsync of the folder) as soon as the point finishes
//   results.csv          the rows in point order, once every point is done  } deterministic:
//   sweep.json           the same as JSON, with counts by status and regime  } bit-identical
//   timing.json          what this run cost (wall time, workers, ranks)        (not deterministic)
// A run that finds point files of its plan skips those points, so a killed sweep started again
// with the same command finishes the rest and writes the same final files.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lab/sweep/sweep_results.hpp"
#include "lab/sweep/sweep_spec.hpp"

namespace fl {

class SweepStore {
 public:
  // Creates `dir` for the plan (writing plan.json), or checks that the plan.json already there
  // is the same plan; `fresh` first removes earlier point files and final files. Throws
  // InputError if the folder holds another sweep's results.
  static SweepStore create(const std::string& dir, const nlohmann::json& plan, bool fresh);
  // An existing sweep folder (merge); throws InputError if it is not one.
  static SweepStore open(const std::string& dir);

  const std::string& dir() const { return dir_; }
  const nlohmann::json& plan() const { return plan_; }
  const std::string& digest() const { return digest_; }
  std::size_t point_count() const { return plan_.at("points").size(); }

  // The finished points in the folder (damaged files or other plans' files are skipped).
  std::map<std::size_t, PointResult> load_points() const;
  // Writes a point's file atomically and durably. Safe from several threads at once.
  void save_point(const PointResult& result) const;
  // Writes results.csv and sweep.json from every point; returns their paths.
  std::vector<std::string> write_final(const std::map<std::size_t, PointResult>& points) const;

 private:
  SweepStore(std::string dir, nlohmann::json plan);
  std::string dir_;
  nlohmann::json plan_;
  std::string digest_;
};

struct SweepProgress {
  std::size_t total = 0;    // points this run answers for (its shard)
  std::size_t done = 0;     // of those, finished, counting those found done
  std::size_t resumed = 0;  // found done when the run started
  std::size_t failed = 0;   // run now, and a guard stopped the run (status "failed")
  std::size_t invalid = 0;  // run now, and the scene refused the point's values ("invalid")
  double elapsed_s = 0.0;   // since this run started
  bool stopping = false;    // an interrupt: running points finish, no new ones start
};

struct SweepRunOptions {
  std::string out_dir;
  int workers = 0;  // threads per process; 0: every core (under MPI: the cores per rank)
  std::optional<Shard> shard;
  bool fresh = false;  // discard the folder's earlier results
  // Set (e.g. by a SIGINT handler) to stop handing out points; the running ones finish.
  const std::atomic<bool>* stop = nullptr;
  // Called on the process's main thread (rank 0's under MPI) as points finish, and at least
  // every quarter second.
  std::function<void(const SweepProgress&)> progress;
  SceneInputs inputs;  // the runner makes them safe to call from several threads
};

struct SweepOutcome {
  bool root = true;          // false on MPI ranks other than 0 (they report nothing)
  std::size_t points = 0;    // in the sweep
  std::size_t selected = 0;  // in this run's shard
  std::size_t resumed = 0;   // found done
  std::size_t ran = 0;       // run now
  bool interrupted = false;
  bool complete = false;  // every point of the sweep is done: the final files are written
  std::map<std::string, int> status;   // ok, invalid, failed (final rows, when complete)
  std::map<std::string, int> regimes;  // (final rows, when complete)
  int workers = 0;                     // threads per process
  int ranks = 1;
  std::vector<std::size_t> ran_by_rank;  // points each MPI rank ran (rank 0 first)
  double wall_s = 0.0;
  std::vector<std::string> files;  // final files written
};

// Runs the sweep's points that are not done yet (of its shard), locally or, when the process was
// started by mpirun, across the MPI ranks; writes the final files when every point is done.
SweepOutcome run_sweep(const SweepSpec& spec, const SweepRunOptions& options);

// Joins sweep folders (shards of one plan, e.g. one per job of a batch array) into `out_dir`
// (which may be one of them): copies their point files and writes the final files. Throws
// InputError if the folders hold different plans, disagree on a point, or miss points.
struct MergeOutcome {
  std::size_t points = 0;
  std::map<std::string, int> status;
  std::vector<std::string> files;
};
MergeOutcome merge_sweeps(const std::vector<std::string>& dirs, const std::string& out_dir);

// ---- shared by the local and the MPI runners ----

// The indices of the shard's points not yet in `done`, ascending.
std::vector<std::size_t> pending_points(std::size_t count, const std::optional<Shard>& shard,
                                        const std::map<std::size_t, PointResult>& done);
// Fills `outcome` from the folder's points; writes the final files (and sets complete) when
// every point is there; writes timing.json.
void finish_sweep(const SweepStore& store, SweepOutcome& outcome, double point_wall_sum);
// Counts a point just run in `progress` by its row's status: failed or invalid (ok counts in
// neither).
void count_no_result(const nlohmann::json& row, SweepProgress& progress);

// Whether this process was started by mpirun (or another MPI launcher), and with how many ranks
// (0 when not).
int mpi_launch_size();
// Whether this build has MPI (FRICTIONLAB_WITH_MPI).
bool sweep_has_mpi();
// The MPI runner (sweep_mpi.cpp); in a build without MPI it throws InputError.
SweepOutcome run_sweep_mpi(const SweepSpec& spec, const SweepRunOptions& options);

}  // namespace fl
