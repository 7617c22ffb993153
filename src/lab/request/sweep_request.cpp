#include "lab/request/sweep_request.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include "io/field_ref.hpp"
#include "lab/request/field_checks.hpp"
#include "lab/request/lab_data.hpp"
#include "lab/request/output_paths.hpp"
#include "lab/request/plot_script.hpp"

namespace fl {

std::vector<std::string> plot_sweep(const std::string& dir) {
  namespace fs = std::filesystem;
  run_plot_script("plot_sweep.py", {(fs::path(dir) / "results.csv").string(),
                                    (fs::path(dir) / "sweep.json").string(), dir});
  std::vector<std::string> pngs;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".png") pngs.push_back(entry.path().string());
  std::sort(pngs.begin(), pngs.end());
  return pngs;
}

PreparedSweep prepare_sweep(const SweepRequest& r) {
  FieldChecks checks;
  if (r.jobs && *r.jobs < 1)
    checks.problem("jobs", std::to_string(*r.jobs),
                   "expected a positive number of workers, found " + std::to_string(*r.jobs) +
                       "; leave it out for every core");
  std::optional<Shard> shard;
  if (!r.shard.empty()) {
    try {
      shard = parse_shard(r.shard);
    } catch (const InputError& e) {
      checks.problem("shard", r.shard, without_location(e.what()));
    }
  }
  const std::optional<double> accuracy =
      checks.quantity(r.accuracy, Dimension::kDimensionless, "accuracy");
  checks.throw_if_any();
  PreparedSweep p;
  p.options.inputs = scene_inputs(asset_dir(r.assets));
  p.spec = load_sweep_file(r.file, p.options.inputs);
  if (accuracy)
    set_sweep_accuracy(p.spec, *accuracy,
                       SourceLocation::of_field("accuracy", quantity_input_text(*r.accuracy)));
  p.options.out_dir = r.out.empty() ? "out/sweep/" + p.spec.name : r.out;
  refuse_overwriting_inputs(p.options.out_dir,
                            {"plan.json", "results.csv", "sweep.json", "timing.json"}, "out",
                            {{r.file, "the sweep file"}});
  prepare_output_folder(p.options.out_dir, "out");
  p.options.workers = r.jobs.value_or(0);
  p.options.shard = shard;
  p.options.fresh = r.fresh;
  p.plot = r.plot;
  return p;
}

namespace {

// Failed and invalid points: those that gave no result.
int without_result(const std::map<std::string, int>& status) {
  int n = 0;
  for (const char* key : {"failed", "invalid"})
    if (const auto it = status.find(key); it != status.end()) n += it->second;
  return n;
}

}  // namespace

int SweepResult::points_without_result() const {
  return outcome.complete ? without_result(outcome.status) : 0;
}

Outcome SweepResult::outcome_of() const {
  if (outcome.interrupted) return Outcome::kInterrupted;
  if (points_without_result() > 0) return Outcome::kFailed;
  if (!plot_failure.empty()) return Outcome::kIncomplete;
  return Outcome::kDone;
}

SweepResult execute_sweep(const PreparedSweep& sweep, const std::atomic<bool>* stop,
                          std::function<void(const SweepProgress&)> progress) {
  SweepRunOptions options = sweep.options;
  options.stop = stop;
  options.progress = std::move(progress);
  SweepResult result;
  result.outcome = run_sweep(sweep.spec, options);
  if (sweep.plot && result.outcome.root && result.outcome.complete) {
    try {
      result.plots = plot_sweep(options.out_dir);
    } catch (const std::runtime_error& e) {
      result.plot_failure = e.what();
    }
  }
  return result;
}

int MergeResult::points_without_result() const {
  return without_result(outcome.status);
}

Outcome MergeResult::outcome_of() const {
  if (points_without_result() > 0) return Outcome::kFailed;
  if (!plot_failure.empty()) return Outcome::kIncomplete;
  return Outcome::kDone;
}

nlohmann::json MergeResult::json() const {
  return {{"out", out},
          {"points", outcome.points},
          {"status", outcome.status},
          {"files", outcome.files},
          {"plots", plots}};
}

MergeResult merge_shards(const MergeRequest& r) {
  FieldChecks checks;
  if (r.dirs.empty())
    checks.problem("dirs", "",
                   "expected the folders of a sweep's shards (each written by a run with " +
                       field_ref("shard", "K/N") + "), found none; name them");
  checks.throw_if_any();
  MergeResult result;
  result.out = r.out.empty() ? r.dirs.front() : r.out;
  prepare_output_folder(result.out, "out");
  result.outcome = merge_sweeps(r.dirs, result.out);
  if (r.plot) {
    try {
      result.plots = plot_sweep(result.out);
    } catch (const std::runtime_error& e) {
      result.plot_failure = e.what();
    }
  }
  return result;
}

}  // namespace fl
