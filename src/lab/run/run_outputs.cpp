#include "lab/run/run_outputs.hpp"

#include <cmath>

#include <fmt/compile.h>
#include <fmt/format.h>

#include "core/units.hpp"
#include "io/atomic_file.hpp"
#include "lab/run/cycle_report.hpp"
#include "lab/run/phone_csv.hpp"
#include "lab/run/summary_fields.hpp"

namespace fl {

void append_trajectory_row(std::string& out, const TrajectoryRow& row) {
  fmt::format_to(std::back_inserter(out), FMT_COMPILE("{},{},{},{},{},{},{},{},{},{},{}\n"), row.t,
                 row.plate.x, row.plate.z, row.plate.pitch, row.plate.vx, row.plate.vz,
                 row.plate.pitch_rate, row.rollers[0].normal_force, row.rollers[0].friction_force,
                 row.rollers[1].normal_force, row.rollers[1].friction_force);
}

void append_hall_row(std::string& out, const HallSample& sample) {
  fmt::format_to(std::back_inserter(out), FMT_COMPILE("{},{}\n"), sample.t_us, sample.adc);
}

std::string trajectory_csv(const RunRecording& r) {
  std::string out(kTrajectoryCsvHeader);
  for (const TrajectoryRow& row : r.trajectory) append_trajectory_row(out, row);
  return out;
}

std::string hall_csv(const RunRecording& r) {
  std::string out(kHallCsvHeader);
  for (const HallSample& s : r.hall) append_hall_row(out, s);
  return out;
}

std::string periods_csv(const RunRecording& r) {
  std::string out = "start_s,end_s,period_s,status\n";
  for (const EstimatedPeriod& p : r.periods) {
    const char* status = p.status == fl_estimator::kAccepted          ? "accepted"
                         : p.status == fl_estimator::kRejectedOutlier ? "rejected: outlier"
                                                                      : "rejected: broken pulse";
    fmt::format_to(std::back_inserter(out), "{},{},{},{}\n", p.start, p.end, p.period, status);
  }
  return out;
}

std::string jumps_csv(const RunRecording& r) {
  std::string out = "roller,start_s,end_s,height_m,roller_angle_rad\n";
  for (const PlateJump& j : r.jumps)
    fmt::format_to(std::back_inserter(out), "{},{},{},{},{}\n", j.roller, j.start, j.end, j.height,
                   j.roller_angle);
  return out;
}

RunOptions recording_for(const OutputDesc& output) {
  RunOptions options;
  options.record_trajectory = output.trajectory;
  options.record_hall = output.hall;
  options.record_cycles = output.cycles;
  options.record_phones = output.phones;
  return options;
}

std::vector<std::pair<std::string, std::string>> run_output_files(const OutputDesc& output,
                                                                  const CompiledRig& rig,
                                                                  const RunSummary& summary,
                                                                  const RunRecording& recording,
                                                                  StepFiles steps) {
  std::vector<std::pair<std::string, std::string>> files;
  if (output.cycles) files.emplace_back("cycles.csv", cycles_csv(rig, recording.cycles));
  // The steps and samples, unless they were streamed to their files (lab/run/run_files.hpp).
  if (steps == StepFiles::kFromRecording) {
    if (output.trajectory) files.emplace_back("trajectory.csv", trajectory_csv(recording));
    if (output.hall && rig.sensor) files.emplace_back("hall.csv", hall_csv(recording));
    for (std::size_t i = 0; output.phones && i < rig.phones.size(); ++i)
      files.emplace_back(
          phone_csv_name(rig, i),
          phone_csv(rig.phones[i], i < recording.phones.size() ? recording.phones[i]
                                                               : std::vector<PhoneSample>{}));
  }
  if (output.periods && output.hall && rig.sensor)
    files.emplace_back("periods.csv", periods_csv(recording));
  if (output.jumps && !recording.jumps.empty())
    files.emplace_back("jumps.csv", jumps_csv(recording));
  if (output.summary) {
    files.emplace_back("summary.json", summary_json(summary).dump(2) + "\n");
    files.emplace_back("timing.json", timing_json(summary).dump(2) + "\n");
  }
  return files;
}

void write_run_outputs(const std::string& folder, const OutputDesc& output, const CompiledRig& rig,
                       const RunSummary& summary, const RunRecording& recording) {
  for (const auto& [name, text] : run_output_files(output, rig, summary, recording))
    write_file_atomic(folder + "/" + name, text);
}

}  // namespace fl
