#include "lab/live/live_run.hpp"

#include <stdexcept>

#include "lab/run/hall_estimator.hpp"
#include "lab/run/regime_monitor.hpp"
#include "lab/run/run_outputs.hpp"
#include "lab/run/solver_convergence.hpp"
#include "scene/theory_motion.hpp"

namespace fl {

struct LiveRun::Impl {
  std::shared_ptr<const CompiledRig> rig;
  OutputDesc output;
  RunOptions options;
  RunRecording recording;
  std::optional<RunLoop> loop;
  LiveFrame frame;                           // what the observer gathered since the last frame
  std::size_t pulses_seen = 0;               // the estimator's pulses already handed out
  std::size_t periods_seen = 0;              // and its judged periods
  double next_regime_t = 0.0;                // s, when the diagnosis is read again
  int first_direction = 0;                   // the plate's first way (+1, -1; 0: not moved yet)
  bool turned = false;                       // it has come back: a turning point was seen
  const HallEstimator* estimator = nullptr;  // the run's, live (none without a sensor)
  std::optional<HarmonicMotion> theory;      // from the plate at the start (scene/theory_motion)
  bool started = false;
  std::optional<RunSummary> summary;
  std::vector<std::pair<std::string, std::string>> files;

  void observe(const StepView& view);
  void end();
};

void LiveRun::Impl::observe(const StepView& view) {
  if (!started) {
    started = true;
    theory = theory_motion(*rig, view.plate.x, view.plate.vx);
  }
  frame.t = view.t;
  frame.plate = view.plate;
  if (theory) frame.x_theory = theory->at(view.t);
  frame.roller_angles = view.roller_angles;
  frame.contacts = view.contacts;
  frame.hall.insert(frame.hall.end(), view.new_samples.begin(), view.new_samples.end());
  estimator = view.estimator;
  if (view.estimator != nullptr) {
    const std::vector<double>& pulses = view.estimator->pulse_times();
    for (; pulses_seen < pulses.size(); ++pulses_seen) frame.pulses.push_back(pulses[pulses_seen]);
    const std::vector<EstimatedPeriod>& judged = view.estimator->judged_periods();
    for (; periods_seen < judged.size(); ++periods_seen)
      frame.periods.push_back(judged[periods_seen]);
  }
  const int direction = view.plate.vx > 0.0 ? 1 : view.plate.vx < 0.0 ? -1 : 0;
  if (first_direction == 0) first_direction = direction;
  if (direction != 0 && direction != first_direction) turned = true;
  // The diagnosis, read every 10 ms of simulated time (a frame's worth at most), as a video does.
  // The monitor says "oscillates" until it has evidence of another regime; the trajectory shows an
  // oscillation only once the plate has turned: before that, no regime is said ("").
  if (view.monitor != nullptr && (frame.regime.empty() || view.t >= next_regime_t)) {
    const RegimeFinding finding = view.monitor->finding(std::nullopt);
    const bool shown = turned || finding.regime != Regime::kOscillates || finding.jumps > 0;
    frame.regime = shown ? regime_so_far(finding) : "";
    next_regime_t = view.t + 0.01;
  }
}

void LiveRun::Impl::end() {
  std::optional<SolverResidual> unconverged;
  RunSummary out = loop->finish(unconverged);
  if (unconverged) {
    // run_experiment runs such a rig again at more solver iterations, unseen: so does this, so
    // that the summary is the one `run` gives.
    recording = RunRecording{};
    RunOptions unseen = options;
    unseen.observer = nullptr;
    out = run_experiment(*rig, unseen, &recording);
  }
  summary = std::move(out);
  files = run_output_files(output, *rig, *summary, recording);
}

LiveRun::LiveRun(std::shared_ptr<const CompiledRig> rig, const OutputDesc& output)
    : impl_(std::make_unique<Impl>()) {
  Impl& r = *impl_;
  r.rig = std::move(rig);
  r.output = output;
  // What `run --out` records, so the files are its files.
  r.options = recording_for(output);
  r.options.observer = [&r](const StepView& view) { r.observe(view); };
  r.loop.emplace(*r.rig, r.options, &r.recording);
}

LiveRun::~LiveRun() = default;

LiveFrame LiveRun::advance_to(double t) {
  Impl& r = *impl_;
  while (!r.loop->ended() && r.loop->time() < t) r.loop->step();
  if (r.loop->ended() && !r.summary) r.end();
  LiveFrame out = r.frame;
  // The estimator's figures once it has accepted a period: live, then the summary's.
  std::optional<EstimatorReport> report;
  if (r.summary)
    report = r.summary->estimator;
  else if (r.estimator != nullptr)
    report = r.estimator->report();
  if (report && report->periods_used > 0) out.estimate = report;
  r.frame.hall.clear();
  r.frame.pulses.clear();
  r.frame.periods.clear();
  return out;
}

bool LiveRun::ended() const {
  return impl_->loop->ended();
}

double LiveRun::time() const {
  return impl_->loop->time();
}

const CompiledRig& LiveRun::rig() const {
  return *impl_->rig;
}

const RunSummary& LiveRun::summary() {
  if (!impl_->summary) throw std::logic_error("the live run has not ended");
  return *impl_->summary;
}

std::vector<std::string> LiveRun::file_names() {
  summary();
  std::vector<std::string> names;
  for (const auto& [name, text] : impl_->files) names.push_back(name);
  return names;
}

std::optional<std::string> LiveRun::file(const std::string& name) {
  summary();
  for (const auto& [file_name, text] : impl_->files)
    if (file_name == name) return text;
  return std::nullopt;
}

}  // namespace fl
