#include "lab/run/run_files.hpp"

#include <cmath>

#include "io/atomic_file.hpp"
#include "lab/run/phone_csv.hpp"
#include "lab/run/run_outputs.hpp"

namespace fl {

RunFiles::RunFiles(const std::string& folder, const OutputDesc& output, const CompiledRig& rig)
    : folder_(folder), output_(output), rig_(rig) {
  if (output.trajectory) {
    trajectory_.emplace(folder + "/trajectory.csv");
    trajectory_->pending() = kTrajectoryCsvHeader;
  }
  if (output.hall && rig.sensor) {
    hall_.emplace(folder + "/hall.csv");
    hall_->pending() = kHallCsvHeader;
  }
  for (std::size_t i = 0; output.phones && i < rig.phones.size(); ++i) {
    phones_.push_back(std::make_unique<StreamedFile>(folder + "/" + phone_csv_name(rig, i)));
    phones_.back()->pending() = phone_csv_header(rig.phones[i]);
  }
}

RunOptions RunFiles::options() {
  RunOptions options = recording_for(output_);
  options.stream = this;
  return options;
}

void RunFiles::trajectory_row(const TrajectoryRow& row) {
  if (!trajectory_) return;
  append_trajectory_row(trajectory_->pending(), row);
  trajectory_->wrote();
}

void RunFiles::hall_sample(const HallSample& sample) {
  if (!hall_) return;
  append_hall_row(hall_->pending(), sample);
  hall_->wrote();
}

void RunFiles::phone_sample(std::size_t phone, const PhoneSample& sample) {
  if (phone >= phones_.size()) return;
  append_phone_row(phones_[phone]->pending(), rig_.phones[phone], sample);
  phones_[phone]->wrote();
}

void RunFiles::restart() {
  if (trajectory_) {
    trajectory_->restart();
    trajectory_->pending() = kTrajectoryCsvHeader;
  }
  if (hall_) {
    hall_->restart();
    hall_->pending() = kHallCsvHeader;
  }
  for (std::size_t i = 0; i < phones_.size(); ++i) {
    phones_[i]->restart();
    phones_[i]->pending() = phone_csv_header(rig_.phones[i]);
  }
}

void RunFiles::finish(const RunSummary& summary, const RunRecording& recording) {
  for (const auto& [name, text] :
       run_output_files(output_, rig_, summary, recording, StepFiles::kStreamed))
    write_file_atomic(folder_ + "/" + name, text);
  if (trajectory_) trajectory_->commit();
  if (hall_) hall_->commit();
  for (const std::unique_ptr<StreamedFile>& phone : phones_) phone->commit();
}

double run_files_bytes_at_most(const OutputDesc& output, const CompiledRig& rig) {
  // A number's shortest round-trip text is at most 24 characters ("-1.2345678901234567e-308").
  constexpr double kTrajectoryRow = 11 * 25.0;
  constexpr double kHallRow = 10 + 1 + 5 + 1;  // microseconds up to 2^32, an ADC code
  const double steps = std::ceil(rig.world.duration / rig.world.time_step) + 1.0;
  double bytes = 1 << 20;  // the summary, the periods, the cycles and the jumps: small
  if (output.trajectory) bytes += steps * kTrajectoryRow;
  if (output.hall && rig.sensor)
    bytes += (rig.world.duration * rig.sensor->sample_rate * (1.0 + rig.sensor->clock_error) + 2) *
             kHallRow;
  for (std::size_t i = 0; output.phones && i < rig.phones.size(); ++i)
    bytes += phone_csv_bytes_at_most(rig.phones[i], rig.world.duration);
  return bytes;
}

}  // namespace fl
