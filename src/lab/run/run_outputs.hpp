// A run's outputs as text: the summary as JSON, the trajectory and the Hall samples as CSV
// (hall.csv in the format `frictionlab estimate` reads), and the human summary.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "lab/run/experiment.hpp"
#include "lab/run/summary_fields.hpp"
#include "lab/run/summary_text.hpp"

namespace fl {

// summary_json (everything a run found, deterministic: the same scene and seed give the same
// bytes) and timing_json (what the run cost on this machine) are in lab/run/summary_fields.hpp;
// summary_text (for a person) in lab/run/summary_text.hpp.
inline constexpr std::string_view kTrajectoryCsvHeader =
    "t_s,x_m,z_m,pitch_rad,vx_m_s,vz_m_s,pitch_rate_rad_s,normal0_n,friction0_n,normal1_n,"
    "friction1_n\n";
inline constexpr std::string_view kHallCsvHeader = "t_us,adc\n";
// One row of trajectory.csv, of hall.csv, appended to `out` (each number the shortest text that
// reads back to it).
void append_trajectory_row(std::string& out, const TrajectoryRow& row);
void append_hall_row(std::string& out, const HallSample& sample);
std::string trajectory_csv(const RunRecording& recording);
std::string hall_csv(const RunRecording& recording);
// Each period the rig's estimator judged: start, end, length [s] and whether it was accepted.
std::string periods_csv(const RunRecording& recording);
// Each jump of the plate: the roller it left, when, how high, at which roller angle.
std::string jumps_csv(const RunRecording& recording);

// What a run records so that its files can be written: the steps, the Hall and phone samples and
// the cycles the scene's output part names (`run --out` and a live session ask the same).
RunOptions recording_for(const OutputDesc& output);

// Whether trajectory.csv, hall.csv and the phones' files are made from the recording, or were
// streamed to their files as the run went (lab/run/run_files.hpp) and are left out here.
enum class StepFiles { kFromRecording, kStreamed };

// The files of a run, by name, as the scene's output part asks: what write_run_outputs writes.
std::vector<std::pair<std::string, std::string>> run_output_files(
    const OutputDesc& output, const CompiledRig& rig, const RunSummary& summary,
    const RunRecording& recording, StepFiles steps = StepFiles::kFromRecording);

// Writes summary.json, timing.json, trajectory.csv, hall.csv, the phones' files (phone_csv.hpp),
// periods.csv, cycles.csv and (when the plate jumped) jumps.csv, as the scene's output part asks,
// into `folder`, each file atomically. All but timing.json are bit-identical between runs.
void write_run_outputs(const std::string& folder, const OutputDesc& output, const CompiledRig& rig,
                       const RunSummary& summary, const RunRecording& recording);

}  // namespace fl
