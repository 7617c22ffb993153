// One run a live front end steps at the pace it shows (the browser's session): the run
// run_experiment makes (lab/run/experiment.hpp, the same RunLoop, monitors and estimator), read
// a frame at a time. Its summary and files, once it has ended, are those `run --out` writes for
// the same rig and options, byte for byte.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "estimator/host_estimator.hpp"
#include "lab/run/experiment.hpp"
#include "lab/run/run_summary.hpp"
#include "scene/compiled_rig.hpp"
#include "scene/scene.hpp"

namespace fl {

// What changed since the last frame, and the state at its end.
struct LiveFrame {
  double t = 0.0;  // s, simulated
  PlateState plate;
  // m: where the thick plate's theory has the plate now (scene/theory_motion.hpp), from where the
  // run started; none when the rollers do not restore the plate.
  std::optional<double> x_theory;
  std::array<double, 2> roller_angles{};  // rad about +y since the start
  std::array<RollerContact, 2> contacts{};
  std::vector<HallSample> hall;             // the Hall samples taken since the last frame
  std::vector<double> pulses;               // s, the pulses the estimator found since then
  std::vector<EstimatedPeriod> periods;     // the periods it judged since then
  std::optional<EstimatorReport> estimate;  // once it has accepted a period
  std::string regime;                       // the diagnosis so far ("" : none shown yet)
};

class LiveRun {
 public:
  // The rig (shared: it outlives the run) and the scene's output part (which files it keeps).
  LiveRun(std::shared_ptr<const CompiledRig> rig, const OutputDesc& output);
  LiveRun(const LiveRun&) = delete;
  LiveRun& operator=(const LiveRun&) = delete;
  ~LiveRun();

  // Steps until simulated time reaches `t` or the run ends; what changed since the last call.
  LiveFrame advance_to(double t);
  bool ended() const;
  double time() const;  // s
  const CompiledRig& rig() const;

  // Once it has ended: the run's summary (a run whose contact solver did not converge is run
  // again as run_experiment does, so the summary is the one `run` gives), and its files by name
  // as `run --out` writes them (summary.json, trajectory.csv, hall.csv, periods.csv, cycles.csv,
  // jumps.csv, as the output part asks). Throws std::logic_error before the end.
  const RunSummary& summary();
  std::vector<std::string> file_names();
  std::optional<std::string> file(const std::string& name);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fl
