// The compiled firmware runs on a simulated ATmega328P (simavr): its ADC reads a synthetic Hall
// signal, and what it prints over serial must agree with the host build of the same estimator
// header on the same samples, to the firmware's printed resolution. At 10 kHz the run also
// measures the cycles of the sampling interrupt and of the estimator, and shows the firmware
// keeps up (16 MHz: 1600 cycles per sample).
#include <algorithm>
#include <cstdint>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "estimator/fixed_format.h"
#include "estimator/period_estimator.h"
#include "estimator/synthetic_hall.hpp"
#include "simulated_uno.hpp"

namespace fl {
namespace {

constexpr uint64_t kCpuHz = 16000000;
constexpr uint64_t kExtraSamples = 20;  // after the signal: the last value again

struct Case {
  const char* name;
  const char* elf;
  double rate_hz;
  int raw_every;
  test::HallSignal signal;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.name;
}

std::string fixed(float v, uint8_t decimals) {
  char buf[24];
  fl_estimator::format_fixed(buf, v, decimals);
  return buf;
}

const char* status_name(uint8_t status) {
  return status == fl_estimator::kAccepted          ? "accepted"
         : status == fl_estimator::kRejectedOutlier ? "outlier"
                                                    : "broken";
}

// What the host build of the estimator says about the same samples, as the firmware prints it.
struct Expected {
  std::vector<std::string> period_lines;
  std::map<uint32_t, std::string> stats_lines;  // by period count, without the health fields
  std::vector<uint64_t> geometry_samples;       // samples at which the geometry was found
  fl_estimator::Stats stats{};
};

Expected host_estimate(const std::vector<uint32_t>& t_us, const std::vector<uint16_t>& adc) {
  fl_estimator::PeriodEstimator e;  // the firmware's defaults: 89 +- 2 mm, 9.81 m/s^2
  Expected x;
  uint32_t periods = 0;
  for (std::size_t i = 0; i < adc.size(); ++i) {
    const uint8_t events = e.add_sample(t_us[i], adc[i]);
    if (events & fl_estimator::kGeometryFound) x.geometry_samples.push_back(i);
    for (; periods < e.period_count(); ++periods) {
      const fl_estimator::Period& p = e.period(periods);
      std::ostringstream line;
      line << "# period i=" << periods << " end_us=" << p.end.us
           << " T_us=" << fixed(p.period_us, 1) << " " << status_name(p.status);
      x.period_lines.push_back(line.str());
    }
    if (events & (fl_estimator::kPeriodAccepted | fl_estimator::kPeriodRejected)) {
      const fl_estimator::Stats s = e.stats();
      std::ostringstream line;
      line << "# stats periods=" << e.period_count() << " N=" << s.periods_used
           << " discarded=" << s.periods_discarded << " T_mean_us=" << fixed(s.period_s * 1e6f, 1)
           << " dT_us=" << fixed(s.period_std_s * 1e6f, 1)
           << " sem_us=" << fixed(s.period_sem_s * 1e6f, 1) << " mu_k=" << fixed(s.mu_k, 5)
           << " dmu_worst=" << fixed(s.mu_k_err_worst, 5)
           << " dmu_quad=" << fixed(s.mu_k_err_quadrature, 5);
      x.stats_lines[e.period_count()] = line.str();
    }
  }
  x.stats = e.stats();
  return x;
}

// The firmware's serial output, split up.
struct Printed {
  std::vector<std::string> comments;
  bool csv_header = false;
  std::vector<std::pair<uint32_t, uint16_t>> raw;
  std::vector<std::string> period_lines;
  std::vector<std::string> stats_lines;
  std::vector<std::string> bad_lines;
};

Printed split(const std::string& serial) {
  Printed p;
  std::istringstream in(serial);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("# period ", 0) == 0) {
      p.period_lines.push_back(line);
    } else if (line.rfind("# stats ", 0) == 0) {
      p.stats_lines.push_back(line);
    } else if (line.rfind('#', 0) == 0) {
      p.comments.push_back(line);
    } else if (line == "t_us,adc") {
      p.csv_header = true;
    } else {
      std::istringstream fields(line);
      unsigned long t = 0;
      unsigned value = 0;
      char comma = 0;
      if (fields >> t >> comma >> value && comma == ',' && fields.peek() == EOF)
        p.raw.emplace_back(static_cast<uint32_t>(t), static_cast<uint16_t>(value));
      else
        p.bad_lines.push_back(line);
    }
  }
  return p;
}

// The value of `key=` in a line, as a number.
long field(const std::string& line, const std::string& key) {
  const auto at = line.find(" " + key + "=");
  if (at == std::string::npos) return -1;
  return std::stol(line.substr(at + key.size() + 2));
}

class FirmwareUnderSimavr : public ::testing::TestWithParam<Case> {};

TEST_P(FirmwareUnderSimavr, PrintsWhatTheHostBuildComputesFromTheSameSamples) {
  const Case& c = GetParam();
  test::HallSignal signal = c.signal;
  signal.sample_rate_hz = c.rate_hz;
  const test::HallSamples made = test::generate(signal);
  // The firmware's clock: sample n at n * (1e6 / rate) us exactly (Timer1 counts CPU cycles).
  // After the signal the simulated ADC keeps reading its last value.
  const auto step = static_cast<uint32_t>(1e6 / c.rate_hz);
  std::vector<uint32_t> t_us;
  std::vector<uint16_t> adc;
  auto take_samples = [&](std::size_t n) {
    adc.assign(n, made.adc.back());
    std::copy_n(made.adc.begin(), std::min(n, made.adc.size()), adc.begin());
    t_us.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) t_us[i] = static_cast<uint32_t>(i) * step;
  };
  take_samples(made.adc.size());
  const std::vector<uint64_t> geometry_samples = host_estimate(t_us, adc).geometry_samples;

  const test::UnoRun run =
      test::run_uno(c.elf, made.adc, kExtraSamples, kCpuHz / 20, geometry_samples);
  const Printed fw = split(run.serial);
  // The host build on exactly the samples the firmware's estimator was given.
  take_samples(run.estimator_calls);
  const Expected host = host_estimate(t_us, adc);
  ASSERT_GE(host.period_lines.size(), 5u) << "the signal should give the host some periods";

  // The header, then one raw line per printed sample, exactly the samples the harness fed.
  ASSERT_FALSE(fw.comments.empty());
  EXPECT_EQ(fw.comments.front().rfind("# frictionlab rig firmware 1: sample_hz=", 0), 0u);
  EXPECT_TRUE(fw.csv_header);
  EXPECT_TRUE(fw.bad_lines.empty()) << fw.bad_lines.front();
  ASSERT_GE(fw.raw.size(), made.adc.size() / static_cast<std::size_t>(c.raw_every));
  for (std::size_t k = 0; k < fw.raw.size() && k * c.raw_every < adc.size(); ++k) {
    const std::size_t n = k * static_cast<std::size_t>(c.raw_every);
    ASSERT_EQ(fw.raw[k].first, t_us[n]) << "raw line " << k;
    ASSERT_EQ(fw.raw[k].second, adc[n]) << "raw line " << k;
  }

  // Every period, line for line, and every statistics line for the period count it shows.
  EXPECT_EQ(fw.period_lines, host.period_lines);
  ASSERT_FALSE(fw.stats_lines.empty());
  for (const std::string& line : fw.stats_lines) {
    const auto periods = static_cast<uint32_t>(field(line, "periods"));
    ASSERT_EQ(host.stats_lines.count(periods), 1u) << line;
    const std::string& expected = host.stats_lines.at(periods);
    EXPECT_EQ(line.substr(0, expected.size()), expected);
    EXPECT_EQ(line.substr(expected.size(), 10), " overruns=") << line;
  }
  EXPECT_EQ(field(fw.stats_lines.back(), "periods"), static_cast<long>(host.period_lines.size()));

  // Nothing lost: no sample missed by the interrupt, no raw line left out.
  EXPECT_EQ(field(fw.stats_lines.back(), "overruns"), 0);
  EXPECT_EQ(field(fw.stats_lines.back(), "raw_dropped"), 0);

  // The measured cost (recorded for docs/estimator.md).
  const double conversions = static_cast<double>(run.conversions);
  const double busy_per_sample = static_cast<double>(run.cycles - run.sleep_cycles) / conversions;
  const double budget = static_cast<double>(kCpuHz) / c.rate_hz;
  const long backlog = field(fw.stats_lines.back(), "backlog_max");
  std::cout << c.name << ": " << run.conversions << " samples; interrupt " << run.isr_cycles_max
            << " cycles worst (" << run.isr_cycles_mean << " mean); add_sample "
            << run.estimator_cycles_mean << " cycles mean, " << run.estimator_cycles_max_steady
            << " worst in steady state, " << run.estimator_cycles_max << " worst (call "
            << run.estimator_max_call << ", geometry found); CPU busy " << busy_per_sample
            << " cycles per sample of " << budget << " (" << 100.0 * busy_per_sample / budget
            << " %); ring backlog at most " << backlog << " of 63; stack at most "
            << run.stack_bytes_max << " bytes\n";
  RecordProperty("isr_cycles_max", static_cast<int>(run.isr_cycles_max));
  RecordProperty("add_sample_cycles_mean", static_cast<int>(run.estimator_cycles_mean));
  RecordProperty("add_sample_cycles_max_steady", static_cast<int>(run.estimator_cycles_max_steady));
  RecordProperty("add_sample_cycles_max", static_cast<int>(run.estimator_cycles_max));
  RecordProperty("busy_cycles_per_sample", static_cast<int>(busy_per_sample));
  RecordProperty("backlog_max", static_cast<int>(backlog));
  RecordProperty("stack_bytes_max", static_cast<int>(run.stack_bytes_max));

  // Keeping up: the interrupt and an average estimator call fit in one sample period, and all
  // the work, printing included, takes less than the CPU has (the 63-sample ring absorbs the
  // rare long calls: no overrun above).
  // Every conversion reached the estimator, but the one still running and the one just read.
  EXPECT_LE(run.conversions - run.estimator_calls, 2u);
  EXPECT_LT(static_cast<double>(run.isr_cycles_max) + run.estimator_cycles_mean, budget);
  EXPECT_LT(busy_per_sample, budget);
  // RAM: the static data and the deepest stack seen fit in the Uno's 2 KiB.
  const test::FunctionRange end = test::find_symbol(c.elf, "__bss_end");
  ASSERT_GT(end.address, 0x800100u);
  const uint32_t ram_peak = end.address - 0x800100u + run.stack_bytes_max;
  std::cout << c.name << ": RAM at most " << ram_peak << " of 2048 bytes (static "
            << end.address - 0x800100u << ", stack " << run.stack_bytes_max << ")\n";
  EXPECT_LT(ram_peak, 2048u);
}

test::HallSignal one_pulse_with_jumps() {
  test::HallSignal s;
  s.period_s = 0.25;
  s.duration_s = 7.0;
  s.noise_counts = 1.5;
  const std::vector<double> turn = test::turning_times(s, 0.0, s.duration_s);
  s.blanks.push_back({turn.at(14) - 0.05, turn.at(14) + 0.05});  // a missing pulse
  s.spurious.push_back(turn.at(20) + 0.1);                       // a spurious one
  return s;
}

test::HallSignal pair_with_a_missing_pulse() {
  test::HallSignal s;
  s.period_s = 0.4;
  s.duration_s = 8.0;
  s.sensor_offset_m = -0.010;
  s.polarity = -1;
  s.noise_counts = 1.5;
  const std::vector<double> turn = test::turning_times(s, 0.0, s.duration_s);
  const double pass = s.period_s / 6.0;  // the magnet is over the sensor at cos = 1/2
  s.blanks.push_back({turn.at(12) - pass - 0.03, turn.at(12) - pass + 0.03});
  return s;
}

test::HallSignal fast_one_pulse() {
  test::HallSignal s;
  s.period_s = 0.13;
  s.duration_s = 2.5;
  s.noise_counts = 1.5;
  return s;
}

test::HallSignal fast_pair() {
  test::HallSignal s;
  s.period_s = 0.2;
  s.duration_s = 2.5;
  s.sensor_offset_m = -0.010;
  s.noise_counts = 1.5;
  return s;
}

INSTANTIATE_TEST_SUITE_P(
    Rig, FirmwareUnderSimavr,
    ::testing::Values(Case{"OnePulseWithJumps1kHz", FL_FIRMWARE_1K_ELF, 1000.0, 1,
                           one_pulse_with_jumps()},
                      Case{"PairWithAMissingPulse1kHz", FL_FIRMWARE_1K_ELF, 1000.0, 1,
                           pair_with_a_missing_pulse()},
                      Case{"OnePulse10kHz", FL_FIRMWARE_10K_ELF, 10000.0, 10, fast_one_pulse()},
                      Case{"Pair10kHz", FL_FIRMWARE_10K_ELF, 10000.0, 10, fast_pair()}),
    [](const ::testing::TestParamInfo<Case>& param_info) {
      return std::string(param_info.param.name);
    });

}  // namespace
}  // namespace fl
