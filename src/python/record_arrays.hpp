// A run's recordings as NumPy structured arrays over the recorded vectors themselves, moved into
// the array's owner (no copy): one row per entry, one named field per quantity, SI (the names
// carry the unit, as in trajectory.csv). result.trajectory["x_m"] is a view of one column.
#pragma once

#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>

#include "core/cycle_tracker.hpp"
#include "estimator/host_estimator.hpp"
#include "lab/run/experiment.hpp"
#include "lab/run/regime_monitor.hpp"
#include "sensor/hall_signal.hpp"

namespace fl::python {

namespace py = pybind11;

// One field of a structured array's rows.
struct RecordField {
  std::string name;
  const char* format;  // NumPy's: "<f8", "?", "<u4", ...
  std::size_t offset;  // bytes from the row's start
};

py::dtype record_dtype(const std::vector<RecordField>& fields, std::size_t itemsize);

// Zeroes the bytes of each row that no field covers (padding, members left out), so that the
// array's bytes (tobytes, numpy.save) are as reproducible as its fields.
void clear_between_fields(void* rows, std::size_t count, std::size_t itemsize,
                          const std::vector<RecordField>& fields);

// The vector moves into a capsule the array holds; the array's rows are its elements.
template <typename Row>
py::array rows_array(std::vector<Row>&& rows, const std::vector<RecordField>& fields) {
  static_assert(std::is_standard_layout_v<Row>, "fields are found by offsetof");
  static_assert(std::is_trivially_copyable_v<Row>, "rows are bytes to NumPy");
  static_assert(sizeof(bool) == 1, "NumPy's bool is one byte");
  clear_between_fields(rows.data(), rows.size(), sizeof(Row), fields);
  auto* owned = new std::vector<Row>(std::move(rows));
  const py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<Row>*>(p); });
  const auto n = static_cast<py::ssize_t>(owned->size());
  return py::array(record_dtype(fields, sizeof(Row)), {n}, {static_cast<py::ssize_t>(sizeof(Row))},
                   owned->data(), owner);
}

// Shape (steps + 1,): the start and every step. Fields t_s, x_m, z_m, pitch_rad, vx_m_s, vz_m_s,
// pitch_rate_rad_s, y_m, yaw_rad (the plate's centre of mass), and for each roller i (0 at
// x = -l/2, 1 at +l/2) touching{i}, stuck{i} (bool), normal{i}_n, friction{i}_n (the forces on the
// plate over the step), penetration{i}_m and gap{i}_m (how far the plate is above the roller).
py::array trajectory_array(std::vector<TrajectoryRow>&& rows);

// Shape (samples,): t_us (uint32, the sensor board's microsecond clock) and adc (uint16, counts).
py::array hall_array(std::vector<HallSample>&& samples);

// Shape (samples,): a phone's, in its axes: t_s and bx_t, by_t, bz_t (a magnetometer) or
// ax_m_s2, ay_m_s2, az_m_s2 (an accelerometer).
py::array phone_array(std::vector<PhoneSample>&& samples, PhoneSensor sensor);

// Shape (cycles,): start_s, period_s, amplitude_m, x_min_m, x_max_m, surface_speed_m_s, stick_s.
py::array cycles_array(std::vector<CycleRecord>&& cycles);

// Shape (periods,): each period the rig's estimator judged, start_s, end_s, period_s and status
// (uint8: 0 accepted, 1 an outlier, 2 at a broken turning point).
py::array periods_array(std::vector<EstimatedPeriod>&& periods);

// Shape (jumps,): each time the plate left a roller, roller (0 or 1), start_s, end_s, height_m
// (the largest gap), roller_angle_rad (the roller's angle when it left), open (never came back).
py::array jumps_array(std::vector<PlateJump>&& jumps);

}  // namespace fl::python
