#include "python/record_arrays.hpp"

#include <cstddef>
#include <string>
#include <utility>

namespace fl::python {

py::dtype record_dtype(const std::vector<RecordField>& fields, std::size_t itemsize) {
  py::list names, formats, offsets;
  for (const RecordField& f : fields) {
    names.append(f.name);
    formats.append(f.format);
    offsets.append(f.offset);
  }
  return py::dtype(names, formats, offsets, static_cast<py::ssize_t>(itemsize));
}

void clear_between_fields(void* rows, std::size_t count, std::size_t itemsize,
                          const std::vector<RecordField>& fields) {
  std::vector<bool> covered(itemsize, false);
  for (const RecordField& f : fields) {
    const std::size_t size = py::dtype(f.format).itemsize();
    for (std::size_t b = f.offset; b < f.offset + size && b < itemsize; ++b) covered[b] = true;
  }
  auto* bytes = static_cast<unsigned char*>(rows);
  for (std::size_t r = 0; r < count; ++r, bytes += itemsize)
    for (std::size_t b = 0; b < itemsize; ++b)
      if (!covered[b]) bytes[b] = 0;
}

py::array trajectory_array(std::vector<TrajectoryRow>&& rows) {
  constexpr std::size_t p = offsetof(TrajectoryRow, plate);
  std::vector<RecordField> fields{
      {"t_s", "<f8", offsetof(TrajectoryRow, t)},
      {"x_m", "<f8", p + offsetof(PlateState, x)},
      {"z_m", "<f8", p + offsetof(PlateState, z)},
      {"pitch_rad", "<f8", p + offsetof(PlateState, pitch)},
      {"vx_m_s", "<f8", p + offsetof(PlateState, vx)},
      {"vz_m_s", "<f8", p + offsetof(PlateState, vz)},
      {"pitch_rate_rad_s", "<f8", p + offsetof(PlateState, pitch_rate)},
      {"y_m", "<f8", p + offsetof(PlateState, y)},
      {"yaw_rad", "<f8", p + offsetof(PlateState, yaw)},
  };
  for (std::size_t i = 0; i < 2; ++i) {
    const std::size_t r = offsetof(TrajectoryRow, rollers) + i * sizeof(RollerContact);
    const std::string n = std::to_string(i);
    fields.push_back({"touching" + n, "?", r + offsetof(RollerContact, touching)});
    fields.push_back({"stuck" + n, "?", r + offsetof(RollerContact, stuck)});
    fields.push_back({"normal" + n + "_n", "<f8", r + offsetof(RollerContact, normal_force)});
    fields.push_back({"friction" + n + "_n", "<f8", r + offsetof(RollerContact, friction_force)});
    fields.push_back({"penetration" + n + "_m", "<f8", r + offsetof(RollerContact, penetration)});
    fields.push_back({"gap" + n + "_m", "<f8", r + offsetof(RollerContact, gap)});
  }
  return rows_array(std::move(rows), fields);
}

py::array hall_array(std::vector<HallSample>&& samples) {
  static_assert(sizeof(HallSample::t_us) == 4 && sizeof(HallSample::adc) == 2);
  const std::vector<RecordField> fields{{"t_us", "<u4", offsetof(HallSample, t_us)},
                                        {"adc", "<u2", offsetof(HallSample, adc)}};
  return rows_array(std::move(samples), fields);
}

py::array phone_array(std::vector<PhoneSample>&& samples, PhoneSensor sensor) {
  const bool field = sensor == PhoneSensor::kMagnetometer;
  const std::size_t value = offsetof(PhoneSample, value);
  const std::vector<RecordField> fields{
      {"t_s", "<f8", offsetof(PhoneSample, t)},
      {field ? "bx_t" : "ax_m_s2", "<f8", value},
      {field ? "by_t" : "ay_m_s2", "<f8", value + sizeof(double)},
      {field ? "bz_t" : "az_m_s2", "<f8", value + 2 * sizeof(double)}};
  return rows_array(std::move(samples), fields);
}

py::array cycles_array(std::vector<CycleRecord>&& cycles) {
  const std::vector<RecordField> fields{
      {"start_s", "<f8", offsetof(CycleRecord, start)},
      {"period_s", "<f8", offsetof(CycleRecord, period)},
      {"amplitude_m", "<f8", offsetof(CycleRecord, amplitude)},
      {"x_min_m", "<f8", offsetof(CycleRecord, x_min)},
      {"x_max_m", "<f8", offsetof(CycleRecord, x_max)},
      {"surface_speed_m_s", "<f8", offsetof(CycleRecord, surface_speed_mean)},
      {"stick_s", "<f8", offsetof(CycleRecord, stick_duration)},
  };
  return rows_array(std::move(cycles), fields);
}

py::array periods_array(std::vector<EstimatedPeriod>&& periods) {
  return rows_array(std::move(periods), {{"start_s", "<f8", offsetof(EstimatedPeriod, start)},
                                         {"end_s", "<f8", offsetof(EstimatedPeriod, end)},
                                         {"period_s", "<f8", offsetof(EstimatedPeriod, period)},
                                         {"status", "u1", offsetof(EstimatedPeriod, status)}});
}

py::array jumps_array(std::vector<PlateJump>&& jumps) {
  return rows_array(std::move(jumps),
                    {{"roller", "<i4", offsetof(PlateJump, roller)},
                     {"start_s", "<f8", offsetof(PlateJump, start)},
                     {"end_s", "<f8", offsetof(PlateJump, end)},
                     {"height_m", "<f8", offsetof(PlateJump, height)},
                     {"roller_angle_rad", "<f8", offsetof(PlateJump, roller_angle)},
                     {"open", "?", offsetof(PlateJump, open)}});
}

}  // namespace fl::python
