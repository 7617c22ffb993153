// A run's files (`run --out DIR`) written as the run goes: trajectory.csv, hall.csv and the
// phones' files stream to
// temporary files beside their places as the steps and samples come, so a run keeps none of its
// steps in memory, however long; finish() writes the rest (summary.json, periods.csv, ...) and
// moves every file into place, each whole. A run that throws before finish() leaves the folder's
// files as they were.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/streamed_file.hpp"
#include "lab/run/experiment.hpp"
#include "scene/scene.hpp"

namespace fl {

class RunFiles final : public RecordSink {
 public:
  RunFiles(const std::string& folder, const OutputDesc& output, const CompiledRig& rig);

  // What the run keeps for these files: the scene's output part's recording, streamed here.
  RunOptions options();

  void trajectory_row(const TrajectoryRow& row) override;
  void hall_sample(const HallSample& sample) override;
  void phone_sample(std::size_t phone, const PhoneSample& sample) override;
  void restart() override;

  // Writes the files the recording holds (cycles, periods, jumps) and the summary's, then moves
  // the streamed ones into place. Throws std::runtime_error naming a file it cannot write.
  void finish(const RunSummary& summary, const RunRecording& recording);

 private:
  std::string folder_;
  OutputDesc output_;
  const CompiledRig& rig_;
  std::optional<StreamedFile> trajectory_;
  std::optional<StreamedFile> hall_;
  std::vector<std::unique_ptr<StreamedFile>> phones_;  // each phone's, in the rig's order
};

// The most bytes a run's files take on disk (the steps' and samples' rows at their widest, and
// room for the rest), for a check that the disk holds them before the run starts.
double run_files_bytes_at_most(const OutputDesc& output, const CompiledRig& rig);

}  // namespace fl
