#include "lab/sweep/sweep_run.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <mutex>

#include <fmt/format.h>

#include "io/atomic_file.hpp"
#include "io/field_ref.hpp"
#include "io/text_file.hpp"
#include "lab/sweep/sweep_pool.hpp"

namespace fl {
namespace {

namespace fs = std::filesystem;

std::string point_file_name(std::size_t index) {
  return fmt::format("{:08d}.json", index);
}

// Makes a rename in `dir` survive a power loss.
void sync_dir(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

// Why two plans differ, in words.
std::string plan_difference(const nlohmann::json& old_plan, const nlohmann::json& new_plan) {
  if (old_plan.value("sweep", "") != new_plan.value("sweep", ""))
    return "it is the sweep \"" + old_plan.value("sweep", "") + "\"";
  if (old_plan.value("scene_digest", "") != new_plan.value("scene_digest", ""))
    return "its base scene's text has changed since";
  if (old_plan.value("points", nlohmann::json::array()).size() != new_plan["points"].size())
    return fmt::format("it has {} points, this sweep {}", old_plan["points"].size(),
                       new_plan["points"].size());
  return "its axes or overrides differ";
}

// The temporary files a killed atomic write leaves behind; old ones are removed (recent ones
// may belong to a shard writing into the same folder right now).
void remove_stale_temporaries(const fs::path& dir) {
  std::error_code ec;
  const auto now = fs::file_time_type::clock::now();
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (entry.path().filename().string().find(".tmp.") == std::string::npos) continue;
    const auto written = entry.last_write_time(ec);
    if (!ec && now - written > std::chrono::hours(1)) fs::remove(entry.path(), ec);
  }
}

bool is_point_file_name(const std::string& name, std::size_t& index) {
  if (name.size() < 13 || !name.ends_with(".json")) return false;
  const std::string digits = name.substr(0, name.size() - 5);
  for (const char c : digits)
    if (c < '0' || c > '9') return false;
  index = std::stoull(digits);
  return true;
}

}  // namespace

SweepStore::SweepStore(std::string dir, nlohmann::json plan)
    : dir_(std::move(dir)), plan_(std::move(plan)), digest_(text_digest(plan_.dump())) {}

SweepStore SweepStore::create(const std::string& dir, const nlohmann::json& plan, bool fresh) {
  const fs::path root(dir);
  const fs::path plan_file = root / "plan.json";
  std::error_code ec;
  if (fresh) {
    for (const char* name : {"plan.json", "results.csv", "sweep.json", "timing.json"})
      fs::remove(root / name, ec);
    fs::remove_all(root / "points", ec);
    fs::remove_all(root / "cycles", ec);
  }
  SweepStore store(dir, plan);
  if (fs::exists(plan_file, ec)) {
    const nlohmann::json old =
        nlohmann::json::parse(read_text_file(plan_file.string()), nullptr, false);
    if (old.is_discarded() || text_digest(old.dump()) != store.digest_)
      throw InputError(SourceLocation{plan_file.string(), 0, 0},
                       "this folder holds the results of another sweep (" +
                           (old.is_discarded() ? std::string("its plan.json is damaged")
                                               : plan_difference(old, plan)) +
                           "); choose another " + field_ref("out") + ", or add " +
                           field_ref("fresh") + " to discard them");
  } else {
    write_file_atomic(plan_file.string(), plan.dump(1) + "\n");
  }
  fs::create_directories(root / "points");
  remove_stale_temporaries(root / "points");
  return store;
}

SweepStore SweepStore::open(const std::string& dir) {
  const fs::path plan_file = fs::path(dir) / "plan.json";
  std::error_code ec;
  if (!fs::is_regular_file(plan_file, ec))
    throw InputError(SourceLocation{dir, 0, 0},
                     "not a sweep folder: it has no plan.json (a sweep with " + field_ref("out") +
                         " writes one)");
  nlohmann::json plan = nlohmann::json::parse(read_text_file(plan_file.string()), nullptr, false);
  if (plan.is_discarded() || !plan.is_object() || !plan.contains("points") ||
      !plan.contains("axes"))
    throw InputError(SourceLocation{plan_file.string(), 0, 0}, "not a sweep plan (damaged?)");
  return SweepStore(dir, std::move(plan));
}

std::map<std::size_t, PointResult> SweepStore::load_points() const {
  std::map<std::size_t, PointResult> out;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(fs::path(dir_) / "points", ec)) {
    std::size_t index = 0;
    if (!is_point_file_name(entry.path().filename().string(), index)) continue;
    auto result = parse_point_file(read_text_file(entry.path().string()), digest_);
    if (result && result->index == index && index < point_count())
      out.emplace(index, std::move(*result));
  }
  return out;
}

void SweepStore::save_point(const PointResult& result) const {
  // The cycles first: a point file says the point is done, cycles included.
  if (!result.cycles_csv.empty()) {
    const fs::path cycles = fs::path(dir_) / "cycles";
    fs::create_directories(cycles);
    write_file_atomic((cycles / fmt::format("{:08d}.csv", result.index)).string(),
                      result.cycles_csv);
    sync_dir(cycles);
  }
  const fs::path points = fs::path(dir_) / "points";
  write_file_atomic((points / point_file_name(result.index)).string(),
                    point_file_text(result, digest_));
  sync_dir(points);
}

std::vector<std::string> SweepStore::write_final(
    const std::map<std::size_t, PointResult>& points) const {
  std::vector<nlohmann::json> rows;
  rows.reserve(points.size());
  for (const auto& [index, result] : points) rows.push_back(result.row);
  const std::string csv = (fs::path(dir_) / "results.csv").string();
  const std::string json = (fs::path(dir_) / "sweep.json").string();
  write_file_atomic(csv, sweep_results_csv(plan_, rows));
  write_file_atomic(json, sweep_results_json(plan_, rows).dump(1) + "\n");
  return {csv, json};
}

std::vector<std::size_t> pending_points(std::size_t count, const std::optional<Shard>& shard,
                                        const std::map<std::size_t, PointResult>& done) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < count; ++i)
    if ((!shard || shard->contains(i)) && !done.contains(i)) out.push_back(i);
  return out;
}

void count_no_result(const nlohmann::json& row, SweepProgress& progress) {
  const std::string status = row.value("status", "failed");
  if (status == "invalid")
    ++progress.invalid;
  else if (status != "ok")
    ++progress.failed;
}

void finish_sweep(const SweepStore& store, SweepOutcome& outcome, double point_wall_sum) {
  const auto points = store.load_points();
  outcome.complete = points.size() == store.point_count();
  if (outcome.complete) {
    outcome.files = store.write_final(points);
    for (const auto& [index, result] : points) {
      ++outcome.status[result.row.value("status", "failed")];
      if (result.row.contains("regime") && result.row["regime"].is_string())
        ++outcome.regimes[result.row["regime"].get<std::string>()];
    }
  }
  const nlohmann::json timing{
      {"sweep", store.plan().value("sweep", "")},
      {"points", outcome.points},
      {"selected", outcome.selected},
      {"resumed", outcome.resumed},
      {"ran", outcome.ran},
      {"interrupted", outcome.interrupted},
      {"workers", outcome.workers},
      {"ranks", outcome.ranks},
      {"ran_by_rank", outcome.ran_by_rank},
      {"wall_s", outcome.wall_s},
      {"point_wall_s_sum", point_wall_sum},
      {"points_per_second", outcome.wall_s > 0.0 ? outcome.ran / outcome.wall_s : 0.0}};
  write_file_atomic((fs::path(store.dir()) / "timing.json").string(), timing.dump(1) + "\n");
}

int mpi_launch_size() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "MPI_LOCALNRANKS", "PMIX_SIZE"}) {
    if (const char* v = std::getenv(name); v != nullptr && *v != '\0')
      return std::max(1, std::atoi(v));
  }
  if (const char* v = std::getenv("PMIX_RANK"); v != nullptr && *v != '\0') return 1;
  return 0;
}

SweepOutcome run_sweep(const SweepSpec& spec, const SweepRunOptions& given) {
  SweepRunOptions options = given;
  options.inputs.paper = shared_once(given.inputs.paper);
  options.inputs.parts = shared_once(given.inputs.parts);
  const int launched = mpi_launch_size();
  if (launched > 0 && sweep_has_mpi()) return run_sweep_mpi(spec, options);
  if (launched > 1)
    throw InputError(
        SourceLocation{},
        fmt::format("this frictionlab was built without MPI (FRICTIONLAB_WITH_MPI=OFF), "
                    "so the {} processes mpirun started would each run the whole "
                    "sweep; run it without mpirun, or use {}",
                    launched, field_ref("shard", "K/N")));

  const auto start = std::chrono::steady_clock::now();
  const SweepStore store = SweepStore::create(options.out_dir, sweep_plan(spec), options.fresh);
  const std::size_t count = spec.point_count();
  const auto done = store.load_points();
  const std::vector<std::size_t> pending = pending_points(count, options.shard, done);

  SweepOutcome outcome;
  outcome.points = count;
  for (std::size_t i = 0; i < count; ++i)
    if (!options.shard || options.shard->contains(i)) ++outcome.selected;
  outcome.resumed = outcome.selected - pending.size();
  outcome.workers = options.workers > 0 ? options.workers : hardware_workers();

  SweepProgress progress;
  progress.total = outcome.selected;
  progress.resumed = outcome.resumed;
  progress.done = outcome.resumed;
  double wall_sum = 0.0;
  {
    const int threads = std::max(
        1, std::min(outcome.workers, static_cast<int>(std::max<std::size_t>(1, pending.size()))));
    // The workers only compute; this thread writes each point's file as it arrives, so a
    // worker does not wait on the disk (each file is synced) while this thread mostly would.
    WorkPool<PointResult> pool(threads, [&](std::size_t index) {
      return run_sweep_point(spec, sweep_point(spec, index), options.inputs);
    });
    for (const std::size_t index : pending) pool.push(index);
    pool.close();
    while (!pool.finished()) {
      for (const PointResult& r : pool.take(std::chrono::milliseconds(250))) {
        store.save_point(r);
        ++outcome.ran;
        ++progress.done;
        wall_sum += r.wall_s;
        count_no_result(r.row, progress);
      }
      if (options.stop != nullptr && options.stop->load() && !progress.stopping) {
        progress.stopping = true;
        pool.drop_queued();
      }
      progress.elapsed_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (options.progress) options.progress(progress);
    }
    outcome.workers = threads;
  }
  outcome.interrupted = outcome.ran < pending.size();
  outcome.ran_by_rank = {outcome.ran};
  outcome.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  finish_sweep(store, outcome, wall_sum);
  return outcome;
}

MergeOutcome merge_sweeps(const std::vector<std::string>& dirs, const std::string& out_dir) {
  if (dirs.empty()) throw InputError(SourceLocation{}, "merge needs at least one sweep folder");
  std::vector<SweepStore> stores;
  for (const std::string& d : dirs) stores.push_back(SweepStore::open(d));
  const SweepStore& first = stores.front();
  for (const SweepStore& s : stores) {
    if (s.digest() != first.digest())
      throw InputError(SourceLocation{s.dir(), 0, 0}, "holds another sweep than " + first.dir() +
                                                          " (" +
                                                          plan_difference(s.plan(), first.plan()) +
                                                          "); merge joins the shards "
                                                          "of one sweep");
  }
  std::map<std::size_t, PointResult> points;
  std::map<std::size_t, std::string> from;
  for (const SweepStore& s : stores) {
    for (auto& [index, result] : s.load_points()) {
      const auto it = points.find(index);
      if (it == points.end()) {
        from[index] = s.dir();
        points.emplace(index, std::move(result));
      } else if (it->second.row != result.row) {
        throw InputError(SourceLocation{s.dir(), 0, 0},
                         fmt::format("point {} differs from the one in {} (a sweep's points are "
                                     "deterministic: were they run by different builds?)",
                                     index, from[index]));
      }
    }
  }
  const std::size_t count = first.point_count();
  if (points.size() != count) {
    std::string missing;
    int listed = 0;
    for (std::size_t i = 0; i < count && listed < 10; ++i)
      if (!points.contains(i)) {
        missing += (listed++ ? ", " : "") + std::to_string(i);
      }
    throw InputError(
        SourceLocation{},
        fmt::format("the folders hold {} of the sweep's {} points; missing: {}{} "
                    "(has every shard finished?)",
                    points.size(), count, missing, count - points.size() > 10 ? ", ..." : ""));
  }
  const SweepStore out = SweepStore::create(out_dir, first.plan(), false);
  const auto present = out.load_points();
  for (const auto& [index, result] : points)
    if (!present.contains(index)) out.save_point(result);
  MergeOutcome outcome;
  outcome.points = count;
  outcome.files = out.write_final(points);
  for (const auto& [index, result] : points) ++outcome.status[result.row.value("status", "failed")];
  return outcome;
}

}  // namespace fl
