// frictionlab sweep SWEEP.yaml: every point of a sweep, in parallel on the local cores (or across
// MPI ranks under mpirun), resumable; and frictionlab merge DIR...: shards joined.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/scene_options.hpp"
#include "cli/stop_signals.hpp"
#include "lab/request/outcome.hpp"
#include "lab/request/output_paths.hpp"
#include "lab/request/plot_script.hpp"
#include "lab/request/sweep_request.hpp"
#include "lab/sweep/sweep_run.hpp"

namespace fl::cli {
namespace {

std::string clock_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  if (s >= 3600) return fmt::format("{}:{:02d}:{:02d}", s / 3600, (s / 60) % 60, s % 60);
  return fmt::format("{}:{:02d}", s / 60, s % 60);
}

// Progress on stderr: a bar redrawn in place on a terminal, plain lines (at most one a second)
// otherwise.
class ProgressReport {
 public:
  explicit ProgressReport(std::string name) : name_(std::move(name)), tty_(isatty(2) == 1) {}

  void operator()(const SweepProgress& p) {
    const std::size_t ran = p.done - p.resumed;
    const double rate = p.elapsed_s > 0.0 ? static_cast<double>(ran) / p.elapsed_s : 0.0;
    const std::size_t left = p.total - p.done;
    const std::string eta =
        rate > 0.0 ? clock_text(static_cast<double>(left) / rate) : std::string("?");
    const std::string failed = (p.failed ? fmt::format(", {} failed", p.failed) : "") +
                               (p.invalid ? fmt::format(", {} invalid", p.invalid) : "");
    const std::string stopping = p.stopping ? "  stopping: finishing the running points" : "";
    if (tty_) {
      constexpr int kWidth = 28;
      const int filled =
          p.total ? static_cast<int>(kWidth * static_cast<double>(p.done) / p.total) : kWidth;
      fmt::print(stderr, "\r\033[K{} [{}{}] {}/{} points  {:.1f} points/s  {} left{}{}", name_,
                 std::string(filled, '#'), std::string(kWidth - filled, '.'), p.done, p.total, rate,
                 eta, failed, stopping);
      drawn_ = true;
    } else if (p.done != last_done_ && p.done > p.resumed &&
               (p.done == p.total || p.elapsed_s - last_line_ >= 1.0)) {
      fmt::print(stderr, "sweep {}: {}/{} points, {:.1f} points/s, {} left{}{}\n", name_, p.done,
                 p.total, rate, eta, failed, stopping);
      last_line_ = p.elapsed_s;
      last_done_ = p.done;
    } else if (p.stopping && !said_stopping_) {
      fmt::print(stderr, "sweep {}: interrupted; finishing the running points\n", name_);
      said_stopping_ = true;
    }
    std::fflush(stderr);
  }
  void end() {
    if (tty_ && drawn_) fmt::print(stderr, "\n");
  }

 private:
  std::string name_;
  bool tty_ = false;
  bool drawn_ = false;
  bool said_stopping_ = false;
  double last_line_ = -1e9;
  std::size_t last_done_ = static_cast<std::size_t>(-1);
};

std::string counts_text(const std::map<std::string, int>& counts) {
  std::string out;
  for (const auto& [key, n] : counts)
    if (n > 0) out += fmt::format("{}{} {}", out.empty() ? "" : ", ", n, key);
  return out.empty() ? "none" : out;
}

// Says on stderr how many of the points in a sweep's results gave no result (failed: a guard
// stopped the run; invalid: the scene refused the point's overrides) and where their errors are;
// returns that number.
int report_failed_points(const std::string& command, const std::map<std::string, int>& status,
                         std::size_t points, const std::vector<std::string>& files) {
  const auto count = [&](const char* key) {
    const auto it = status.find(key);
    return it == status.end() ? 0 : it->second;
  };
  const int failed = count("failed");
  const int invalid = count("invalid");
  if (failed + invalid == 0) return 0;
  std::string where;
  for (const std::string& f : files) where += (where.empty() ? "" : " and ") + f;
  fmt::print(stderr,
             "frictionlab {}: {} of {} points gave no result ({} failed, {} invalid); every "
             "point's row, with its error, is in {}\n",
             command, failed + invalid, points, failed, invalid, where);
  return failed + invalid;
}

struct SweepCommandOptions {
  std::string file;
  int workers = 0;
  std::string out;
  bool plot = false;
  std::string shard;
  bool json = false;
  bool fresh = false;
  std::string accuracy;
};

int run_sweep_command(const SweepCommandOptions& o, const GlobalOptions& global) {
  SweepRequest request;
  request.file = o.file;
  if (o.workers != 0) request.jobs = o.workers;
  request.out = o.out;
  request.plot = o.plot;
  request.shard = o.shard;
  request.fresh = o.fresh;
  if (!o.accuracy.empty()) request.accuracy = o.accuracy;
  request.assets = global.asset_dir;
  const PreparedSweep prepared = prepare_sweep(request);
  const SweepSpec& spec = prepared.spec;
  const SweepRunOptions& options = prepared.options;
  const std::string label =
      options.shard ? fmt::format("{} (shard {}/{})", spec.name, options.shard->k, options.shard->n)
                    : spec.name;
  ProgressReport report(label);

  SweepResult result;
  {
    StopSignals signals;
    result = execute_sweep(prepared, &stop_requested(),
                           [&report](const SweepProgress& p) { report(p); });
  }
  report.end();
  const SweepOutcome& outcome = result.outcome;
  if (!outcome.root) return 0;
  const std::vector<std::string>& pngs = result.plots;
  if (o.json) {
    nlohmann::json j{{"sweep", spec.name},
                     {"out", options.out_dir},
                     {"points", outcome.points},
                     {"selected", outcome.selected},
                     {"resumed", outcome.resumed},
                     {"ran", outcome.ran},
                     {"interrupted", outcome.interrupted},
                     {"complete", outcome.complete},
                     {"status", outcome.status},
                     {"regimes", outcome.regimes},
                     {"workers", outcome.workers},
                     {"ranks", outcome.ranks},
                     {"wall_s", outcome.wall_s},
                     {"files", outcome.files},
                     {"plots", pngs}};
    fmt::print("{}\n", j.dump(2));
  } else {
    fmt::print(
        "frictionlab sweep: {} ({} points{}; {} worker{} x {} rank{})\n", spec.name, outcome.points,
        options.shard
            ? fmt::format(", shard {}/{}: {}", options.shard->k, options.shard->n, outcome.selected)
            : "",
        outcome.workers, outcome.workers == 1 ? "" : "s", outcome.ranks,
        outcome.ranks == 1 ? "" : "s");
    fmt::print("  ran {} point{} in {:.2f} s ({:.2f} points/s){}\n", outcome.ran,
               outcome.ran == 1 ? "" : "s", outcome.wall_s,
               outcome.wall_s > 0 ? outcome.ran / outcome.wall_s : 0.0,
               outcome.resumed ? fmt::format("; {} were already done", outcome.resumed) : "");
    if (outcome.interrupted)
      fmt::print(
          "  interrupted: {} of the {} points are done; run the same command again to "
          "finish\n",
          outcome.resumed + outcome.ran, outcome.selected);
    if (outcome.complete) {
      fmt::print("  status: {}\n", counts_text(outcome.status));
      fmt::print("  regimes: {}\n", counts_text(outcome.regimes));
      for (const std::string& f : outcome.files) fmt::print("  written: {}\n", f);
      for (const std::string& f : pngs) fmt::print("  plot: {}\n", f);
    } else if (!outcome.interrupted) {
      fmt::print(
          "  this shard is done; when every shard is, join them: frictionlab merge DIR...\n");
    }
  }
  if (outcome.interrupted) return stop_exit_status();
  if (outcome.complete)
    report_failed_points("sweep", outcome.status, outcome.points, outcome.files);
  if (!result.plot_failure.empty())
    fmt::print(stderr, "error: no plots: {}; the results above are complete\n",
               result.plot_failure);
  return exit_status(result.outcome_of());
}

struct MergeCommandOptions {
  std::vector<std::string> dirs;
  std::string out;
  bool plot = false;
  bool json = false;
};

int run_merge_command(const MergeCommandOptions& o) {
  MergeRequest request;
  request.dirs = o.dirs;
  request.out = o.out;
  request.plot = o.plot;
  const MergeResult result = merge_shards(request);
  const MergeOutcome& outcome = result.outcome;
  if (o.json) {
    fmt::print("{}\n", result.json().dump(2));
  } else {
    fmt::print("frictionlab merge: {} folder{} -> {} ({} points; {})\n", o.dirs.size(),
               o.dirs.size() == 1 ? "" : "s", result.out, outcome.points,
               counts_text(outcome.status));
    for (const std::string& f : outcome.files) fmt::print("  written: {}\n", f);
    for (const std::string& f : result.plots) fmt::print("  plot: {}\n", f);
  }
  report_failed_points("merge", outcome.status, outcome.points, outcome.files);
  if (!result.plot_failure.empty())
    fmt::print(stderr, "error: no plots: {}; the results above are complete\n",
               result.plot_failure);
  return exit_status(result.outcome_of());
}

}  // namespace

Command add_sweep_command(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<SweepCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "sweep", "Run every point of a sweep file in parallel (resumable; MPI under mpirun)");
  sub->add_option("sweep", options->file, "Sweep file (scenes/sweeps/*.yaml)")->required();
  sub->add_option("-j,--jobs", options->workers,
                  "Worker threads (default: every core; under MPI: the cores per rank)")
      ->check(CLI::PositiveNumber);
  sub->add_option(
      "--out", options->out,
      "Folder for plan.json, points/, results.csv, sweep.json (default out/sweep/NAME)");
  sub->add_flag("--plot", options->plot, "Draw the sweep's PNG plots (python3 + matplotlib)");
  sub->add_option("--shard", options->shard,
                  "Run shard K of N (points whose index % N == K-1), e.g. 2/8; join with merge");
  sub->add_flag("--json", options->json, "Print one JSON object instead of the summary");
  sub->add_flag("--fresh", options->fresh, "Discard the folder's earlier results and start over");
  sub->add_option("--accuracy", options->accuracy,
                  "Run each point at the largest step whose predicted period error stays within "
                  "this, e.g. 0.01% (over the file's accuracy:)");
  return Command{sub, [options, &global] { return run_sweep_command(*options, global); }};
}

Command add_merge_command(CLI::App& app, const GlobalOptions& /*global*/) {
  auto options = std::make_shared<MergeCommandOptions>();
  CLI::App* sub =
      app.add_subcommand("merge", "Join the shards of a sweep (folders of --shard runs)");
  sub->add_option("dirs", options->dirs, "Sweep folders (each with plan.json and points/)")
      ->required();
  sub->add_option("--out", options->out, "Folder for the joined results (default: the first)");
  sub->add_flag("--plot", options->plot, "Draw the sweep's PNG plots (python3 + matplotlib)");
  sub->add_flag("--json", options->json, "Print one JSON object instead of the summary");
  return Command{sub, [options] { return run_merge_command(*options); }};
}

}  // namespace fl::cli
