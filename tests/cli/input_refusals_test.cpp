// Input no rig gives, refused by the command with a located message and exit status 2 before it
// is computed with, and never printed: a log of noise, a value beyond any bench (a period in
// milliseconds read as seconds, an amplitude of 1e308 mm, an accuracy of 200 %), an output that
// would replace an input, a file name that is not UTF-8, a file of one giant line; and logs the
// reader once misread (a 16-bit ADC's values, a clock that ticks more slowly than the samples
// come), each checked against a synthetic log's known period.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../support/run_command.hpp"
#include "../support/temp_folder.hpp"
#include "estimator/synthetic_hall.hpp"

namespace fl {
namespace {

namespace fs = std::filesystem;

const std::string kExe = FRICTIONLAB_EXE;
const std::string kSource = FRICTIONLAB_TEST_SOURCE_DIR;

// Uniform numbers in [0, 1) from a seed, the same on every platform.
class Uniform {
 public:
  explicit Uniform(std::uint64_t seed) : x_(seed) {}
  double next() {
    x_ = x_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(x_ >> 11) * 0x1.0p-53;
  }

 private:
  std::uint64_t x_;
};

// A Hall log of Gaussian pulses (300 counts above 512, sigma 10 ms) at the given times, 1 kHz.
std::string pulse_log(const std::vector<double>& pulses, double duration_s) {
  std::string text = "t_us,adc\n";
  const auto n = static_cast<int>(duration_s * 1000.0);
  for (int i = 0; i < n; ++i) {
    const double t = i * 1e-3;
    double v = 512.0;
    for (const double p : pulses) {
      const double u = (t - p) / 0.01;
      if (std::fabs(u) < 8.0) v += 300.0 * std::exp(-0.5 * u * u);
    }
    text += fmt::format("{},{}\n", i * 1000, std::lround(v));
  }
  return text;
}

// The magnet of the paper's rig (T = 0.79 s) read by an ADC of any range: baseline + height x the
// field, every `step_s`, each time written by `stamp` (the time in s).
template <typename Stamp>
std::string rig_log(const std::string& header, double baseline, double height, double step_s,
                    double duration_s, Stamp stamp) {
  test::HallSignal s;
  s.period_s = 0.79;
  std::string text = header + "\n";
  for (int i = 0; i * step_s < duration_s; ++i) {
    const double t = i * step_s;
    const double v = baseline + height * test::dipole_field(s, t);
    text += fmt::format("{},{}\n", stamp(t), std::lround(std::clamp(v, 0.0, 65535.0)));
  }
  return text;
}

class InputRefusals : public test::TempFolderTest {
 protected:
  InputRefusals() : TempFolderTest("fl-refusals") {}

  test::CommandResult lab(const std::string& args) {
    return test::run_command("cd " + dir_.string() + " && " + kExe + " " + args);
  }

  // A log of 60 pulses at random times over 30 s: noise, no oscillation.
  std::string noise_log(const std::string& name) {
    Uniform u(2);
    std::vector<double> pulses;
    for (int i = 0; i < 60; ++i) pulses.push_back(30.0 * u.next());
    return write(name, pulse_log(pulses, 30.0));
  }

  std::string clean_log(const std::string& name) {
    return write(name, rig_log("t_us,adc", 512.0, 300.0, 1e-3, 20.0,
                               [](double t) { return std::llround(t * 1e6); }));
  }
};

// 1. A log of noise: more periods discarded than accepted, refused with its counts and what to do,
// by every command that estimates a log.
TEST_F(InputRefusals, ALogOfNoiseIsRefusedWithWhatWasFound) {
  noise_log("noise.csv");
  const test::CommandResult r = lab("estimate noise.csv");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(r.err.rfind("noise.csv:", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(" accepted and "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" discarded: more discarded than accepted"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--plot FILE.png shows the pulses"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("T ="), std::string::npos) << r.err;
  // compare --log refuses it before any simulation, with the same words.
  const test::CommandResult compared = lab("compare --log noise.csv --out cmp");
  EXPECT_EQ(compared.status, 2) << compared.out;
  EXPECT_NE(compared.err.find("more discarded than accepted"), std::string::npos) << compared.err;
  EXPECT_FALSE(fs::exists(dir_ / "cmp" / "compare-log.json"));
}

TEST_F(InputRefusals, ALogOfNoiseIsAFailedRowOfATable) {
  noise_log("noise.csv");
  clean_log("clean.csv");
  const test::CommandResult r = lab("estimate clean.csv noise.csv --out table");
  EXPECT_EQ(r.status, 3) << r.err;
  const nlohmann::json rows =
      nlohmann::json::parse(test::read_text(dir_ / "table" / "estimates.json"))["logs"];
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0]["status"], "ok");
  EXPECT_NEAR(rows[0]["period_s"].get<double>(), 0.79, 5e-4 * 0.79);
  EXPECT_EQ(rows[1]["status"], "failed");
  EXPECT_TRUE(rows[1]["period_s"].is_null());
  EXPECT_NE(rows[1]["error"].get<std::string>().find("more discarded than accepted"),
            std::string::npos);
}

TEST_F(InputRefusals, TooFewPeriodsAreRefused) {
  // Five pulses of the rig: four periods, each exact.
  write("short.csv", rig_log("t_us,adc", 512.0, 300.0, 1e-3, 5.0,
                             [](double t) { return std::llround(t * 1e6); }));
  const test::CommandResult r = lab("estimate short.csv");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.err.find("gave 4 periods, 4 accepted and 0 discarded: T +- dT needs at least 5 "
                       "accepted periods"),
            std::string::npos)
      << r.err;
}

TEST_F(InputRefusals, PeriodsScatteringBeyondARigsAreRefused) {
  // Pulses 0.5 s apart, each interval off by up to 19 %: nearly all within the estimator's 20 %,
  // their scatter 11 %.
  Uniform u(5);
  std::vector<double> pulses;
  for (double t = 0.3; t < 29.7; t += 0.5 * (1.0 + 0.19 * (2.0 * u.next() - 1.0)))
    pulses.push_back(t);
  write("scatter.csv", pulse_log(pulses, 30.0));
  const test::CommandResult r = lab("estimate scatter.csv");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.err.find("the accepted periods scatter by dT/T = 11."), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("beyond the 10 % of any rig"), std::string::npos) << r.err;
}

// 2. Values beyond any bench, never printed: a period in milliseconds read as seconds, a period
// that is a rig's only at another spacing, a series of periods in milliseconds.
TEST_F(InputRefusals, APeriodBeyondAnyRigIsRefusedByAnalytic) {
  const test::CommandResult ms = lab("analytic --period 790");
  EXPECT_EQ(ms.status, 2);
  EXPECT_TRUE(ms.out.empty()) << ms.out;
  EXPECT_EQ(
      ms.err.rfind("--period 790: error: expected the period T from 0.0044857 to 63.4374 s", 0), 0u)
      << ms.err;
  EXPECT_NE(ms.err.find("found 790 s: a plain number is SI, so 790 was read as 790 s; write "
                        "790ms for milliseconds"),
            std::string::npos)
      << ms.err;
  // Within the range, but mu_k = 2 pi^2 l / (g T^2) = 2.0e-4 at 89 mm: no rig's.
  const test::CommandResult slow = lab("analytic --period 30s");
  EXPECT_EQ(slow.status, 2);
  EXPECT_TRUE(slow.out.empty()) << slow.out;
  EXPECT_NE(slow.err.find("--period 30s: error: T = 30 s at l = 89 mm"), std::string::npos)
      << slow.err;
  EXPECT_NE(slow.err.find("expected mu_k from 0.001 to 100"), std::string::npos) << slow.err;
  // ... and at 2 m it is one (mu_k 4.5e-3).
  EXPECT_EQ(lab("analytic --period 30s --spacing 2m").status, 0);
}

TEST_F(InputRefusals, ASeriesOfPeriodsInMillisecondsIsRefusedAtItsCell) {
  write("ms.csv", "label,spacing,period,period_err\na,60mm,648,5\nb,70mm,702,5\nc,80mm,757,5\n");
  const test::CommandResult r = lab("fit ms.csv");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(r.err.rfind("ms.csv:2:8: error: period: expected the period T from", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("write 648ms for milliseconds"), std::string::npos) << r.err;
  // Each row a rig's period and spacing, the line through them none: T^2 rises by 1100 s^2 over
  // 1 mm, mu_k = 2 pi^2 / (g s) = 1.8e-6.
  write("line.csv", "spacing,period,period_err\n1 mm,50 s,0.5 s\n2 mm,60 s,0.5 s\n");
  const test::CommandResult line = lab("fit line.csv");
  EXPECT_EQ(line.status, 2);
  EXPECT_TRUE(line.out.empty()) << line.out;
  EXPECT_EQ(line.err.rfind("line.csv: error: the fitted line's slope 1.1e+06 s^2/m gives a mu_k "
                           "no rig has: expected mu_k from 0.001 to 100",
                           0),
            0u)
      << line.err;
}

// 3. A measured period beyond any rig is refused at its cell before any simulation.
TEST_F(InputRefusals, AMeasuredPeriodBeyondAnyRigIsRefusedBeforeAnySimulation) {
  write("measured.csv", "label,period,period_err\nlego,790,0.03 s\n");
  const test::CommandResult r = lab("compare --measured measured.csv --out cmp");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("measured.csv:2:6: error: period: expected the period T", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("write 790ms for milliseconds"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "cmp"));
  // A period of some rig, but none at the row's spacing (the scene's 89 mm).
  write("slow.csv", "label,period,period_err\nlego,30 s,0.03 s\n");
  const test::CommandResult slow = lab("compare --measured slow.csv --out cmp");
  EXPECT_EQ(slow.status, 2);
  EXPECT_EQ(slow.err.rfind("slow.csv:2:6: error: row \"lego\": T = 30 s at l = 89 mm", 0), 0u)
      << slow.err;
  EXPECT_FALSE(fs::exists(dir_ / "cmp" / "compare.csv"));
}

// 4. An accuracy the step rule cannot honour.
TEST_F(InputRefusals, AnAccuracyBeyondTenPercentIsRefused) {
  for (const char* accuracy : {"200%", "11%", "0%", "-1%"}) {
    const test::CommandResult r = lab(std::string("run ") + kSource +
                                      "/scenes/minimal.yaml --duration 1s --accuracy " + accuracy);
    EXPECT_EQ(r.status, 2) << accuracy;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(r.err.rfind(std::string("--accuracy ") + accuracy +
                              ": error: expected a period accuracy above 0 and at most 10 %",
                          0),
              0u)
        << r.err;
  }
}

// 5. An amplitude beyond any rig.
TEST_F(InputRefusals, AnAmplitudeBeyondAnyRigIsRefused) {
  const test::CommandResult r = lab("analytic --mu-k 0.3 --amplitude 1e308mm");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(
      r.err.rfind("--amplitude 1e308mm: error: expected the amplitude A from 0 to 2000 mm", 0), 0u)
      << r.err;
  EXPECT_EQ(lab("analytic --mu-k 0.3 --amplitude -1mm").status, 2);
  EXPECT_EQ(lab("analytic --mu-k 0.3 --amplitude 2m").status, 0);
}

// 6. A clock that ticks more slowly than the samples come: the advised rate is the samples' own,
// and the period it gives is the log's.
TEST_F(InputRefusals, TheRateAdvisedIsTheOneThatGivesTheLogsPeriod) {
  // 500 samples a second, their millisecond times rounded down to 4 ms: every other one repeats.
  write("ticks.csv", rig_log("t_ms,adc", 512.0, 300.0, 2e-3, 20.0, [](double t) {
          return 4 * static_cast<long long>(std::floor(t * 1e3 / 4.0 + 1e-9));
        }));
  const test::CommandResult r = lab("estimate ticks.csv");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("the log reads with --rate 500Hz: T = 0.7900 s"), std::string::npos)
      << r.err;
  const test::CommandResult advised = lab("estimate ticks.csv --rate 500Hz --json");
  ASSERT_EQ(advised.status, 0) << advised.err;
  EXPECT_NEAR(nlohmann::json::parse(advised.out)["period_s"].get<double>(), 0.79, 5e-4 * 0.79);
}

// 7. A 16-bit ADC's values above 32767 give the period.
TEST_F(InputRefusals, AdcValuesUpTo65535GiveThePeriod) {
  for (const double baseline : {30000.0, 40000.0}) {
    const std::string name = fmt::format("adc{:.0f}.csv", baseline);
    write(name, rig_log("t_us,adc", baseline, 25000.0, 1e-3, 20.0,
                        [](double t) { return std::llround(t * 1e6); }));
    const test::CommandResult r = lab("estimate " + name + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_NEAR(j["period_s"].get<double>(), 0.79, 5e-4 * 0.79) << name;
    // The resting level: the baseline and the little field of the magnet away from the sensor
    // (under 1 % of the pulses' height), read in the 16-bit range, not wrapped.
    EXPECT_GT(j["baseline_adc"].get<double>(), baseline) << name;
    EXPECT_LT(j["baseline_adc"].get<double>(), baseline + 0.01 * 25000.0) << name;
    EXPECT_GE(j["periods_used"].get<int>(), 20) << name;
  }
}

// 8. An output that is (or would overwrite) an input, refused naming both; the input unchanged.
TEST_F(InputRefusals, AnOutputThatWouldReplaceAnInputIsRefused) {
  const std::string log = clean_log("X.csv");
  const std::string series_text = test::read_text(kSource + "/assets/examples/student-series.csv");
  write("S.csv", series_text);
  write("D/fit.csv", series_text);
  const std::string log_text = test::read_text(log);
  struct Case {
    std::string args;
    std::string located;  // the field and its value
    std::string input;    // the input it names
  };
  for (const Case& c : {
           Case{"estimate X.csv --plot X.csv", "--plot X.csv: error: ", "(X.csv)"},
           Case{"estimate X.csv --plot ./X.csv", "--plot ./X.csv: error: ", "(X.csv)"},
           Case{"estimate X.csv --mc 10 --mc-plot X.csv", "--mc-plot X.csv: error: ", "(X.csv)"},
           Case{"fit S.csv --plot S.csv", "--plot S.csv: error: ", "(S.csv)"},
           Case{"fit D/fit.csv --out D", "--out D: error: ",
                "fit.csv would replace the series "
                "(D/fit.csv)"},
       }) {
    const test::CommandResult r = lab(c.args);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.out;
    EXPECT_EQ(r.err.rfind(c.located, 0), 0u) << r.err;
    EXPECT_NE(r.err.find(c.input), std::string::npos) << r.err;
  }
  // A log named as the table's own file.
  write("T/estimates.csv", log_text);
  const test::CommandResult table = lab("estimate X.csv T/estimates.csv --out T");
  EXPECT_EQ(table.status, 2);
  EXPECT_NE(table.err.find("estimates.csv would replace a log (T/estimates.csv)"),
            std::string::npos)
      << table.err;
  EXPECT_EQ(test::read_text(log), log_text);
  EXPECT_EQ(test::read_text(dir_ / "S.csv"), series_text);
  EXPECT_EQ(test::read_text(dir_ / "D" / "fit.csv"), series_text);
  EXPECT_EQ(test::read_text(dir_ / "T" / "estimates.csv"), log_text);
}

// 9. A file name that is not UTF-8: shown escaped in messages and JSON, the run completed.
TEST_F(InputRefusals, AFileNameThatIsNotUtf8IsShownEscaped) {
  const std::string bad = "bad\xff.csv";
  clean_log(bad);
  clean_log("good.csv");
  const test::CommandResult one = lab("estimate " + bad + " --json");
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_EQ(nlohmann::json::parse(one.out)["log"], "bad\\xff.csv");
  const test::CommandResult text = lab("estimate " + bad);
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_EQ(text.out.rfind("frictionlab estimate: bad\\xff.csv\n", 0), 0u) << text.out;
  const test::CommandResult table = lab("estimate " + bad + " good.csv --out table");
  ASSERT_EQ(table.status, 0) << table.err;
  const nlohmann::json rows =
      nlohmann::json::parse(test::read_text(dir_ / "table" / "estimates.json"))["logs"];
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0]["label"], "bad\\xff.csv");
  EXPECT_EQ(rows[0]["status"], "ok");
  EXPECT_NE(test::read_text(dir_ / "table" / "estimates.csv").find("bad\\xff.csv,bad\\xff.csv,ok"),
            std::string::npos);
  const test::CommandResult missing = lab("estimate nope\xfe.csv");
  EXPECT_EQ(missing.status, 2);
  EXPECT_EQ(missing.err, "nope\\xfe.csv: error: cannot open the log: No such file or directory\n");
}

// A scene whose file name is not UTF-8 and which names itself nothing: the run's name is its file
// stem, escaped, in the summary and the JSON (it ended --json in an internal error).
TEST_F(InputRefusals, ASceneFileNameThatIsNotUtf8IsShownEscaped) {
  std::string scene =
      test::read_text(std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/minimal.yaml");
  scene.erase(scene.find("name: minimal\n"), std::string("name: minimal\n").size());
  write("rig\xff.yaml", scene);
  const test::CommandResult r = lab("run rig\xff.yaml --duration 1s --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["scene"], "rig\\xff");
}

// 11. What the log reader's fuzzer (tests/fuzz/hall_log_fuzzer.cpp) found: a header that is not
// UTF-8 (a Latin-1 "µ" after a column's name) ended `--json` in an internal error.
TEST_F(InputRefusals, AHeaderThatIsNotUtf8IsShownEscaped) {
  const std::string clean = test::read_text(clean_log("clean.csv"));
  write("latin.csv", "t_us,adc\xb5" + clean.substr(clean.find('\n')));
  const test::CommandResult r = lab("estimate latin.csv --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["adc_column"], "adc\\xb5");
  EXPECT_NEAR(j["period_s"].get<double>(), 0.79, 5e-4 * 0.79);
}

// 10. A file of one giant line is refused at its first line, after reading a few kilobytes of
// it; a file over the most read is refused by its size.
TEST_F(InputRefusals, AFileOfOneGiantLineIsRefusedAtOnce) {
  std::ofstream(dir_ / "digits.txt", std::ios::binary) << std::string(4u << 20, '7');
  const test::CommandResult r = lab("estimate digits.txt");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("digits.txt:1: error: line 1 of the log runs past 8192 bytes without a "
                        "line end",
                        0),
            0u)
      << r.err;
  std::ofstream(dir_ / "second.csv", std::ios::binary) << "t_us,adc\n0,512\n"
                                                       << std::string(9000, '1') << "\n";
  const test::CommandResult second = lab("estimate second.csv");
  EXPECT_EQ(second.status, 2);
  EXPECT_EQ(second.err.rfind("second.csv:3: error: line 3 of the log runs past 8192 bytes", 0), 0u)
      << second.err;
  // 600 MiB of nothing (a sparse file): over the 512 MiB read, refused without reading it.
  { std::ofstream(dir_ / "huge.csv", std::ios::binary) << "t_us,adc\n"; }
  fs::resize_file(dir_ / "huge.csv", std::uintmax_t{600} << 20);
  const test::CommandResult huge = lab("estimate huge.csv");
  EXPECT_EQ(huge.status, 2);
  EXPECT_NE(huge.err.find("huge.csv: error: the log is larger than 512 MiB"), std::string::npos)
      << huge.err;
}

// A long log read as it cannot be is tried, for the advice, on its first 8 MiB only, and the
// advice says so: its period is the log's.
TEST_F(InputRefusals, ALongLogsAdviceIsTriedOnItsFirstEightMebibytes) {
  test::HallSignal s;
  s.period_s = 0.79;
  std::string text = "sensorValue\n";
  for (int i = 0; i < 2'400'000; ++i)  // 9.6 MB: values alone, 1 kHz
    text += std::to_string(std::lround(512.0 + 300.0 * test::dipole_field(s, i * 1e-3))) + "\n";
  write("values.csv", text);
  const test::CommandResult r = lab("estimate values.csv");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("the log reads with --rate 1kHz: T = 0.7900 s, mu_k 0.287 from "),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(" periods in its first 8 MiB"), std::string::npos) << r.err;
}

// Another instrument's file, named by what it holds and refused with exit status 2, by estimate
// and by compare --log, rather than read as a log of binary bytes or of the wrong columns; a
// phone's magnetometer, the instrument estimate reads, is read. A video's header with no video
// after it is read as a video (tracking/) and refused as one that cannot be.
TEST_F(InputRefusals, AnotherInstrumentsFileIsNamedAndRefused) {
  write("clip.mp4", std::string("\0\0\0\x20"
                                "ftypisom\0\0\x02\0",
                                16) +
                        std::string(100000, 'v'));
  const test::CommandResult video = lab("estimate clip.mp4");
  EXPECT_EQ(video.status, 2) << video.out;
  EXPECT_EQ(video.err.rfind("clip.mp4: error:", 0), 0u) << video.err;
  // (A build without libav says so instead.)
  EXPECT_TRUE(video.err.find("libav cannot read it as a video") != std::string::npos ||
              video.err.find("this build of frictionlab reads no video") != std::string::npos)
      << video.err;
  // A zip whose entries' names say phyphox, and nothing else of a zip: opened, and refused as a
  // damaged one.
  write("export.zip", std::string("PK\x03\x04", 4) + std::string(26, '\0') + "meta/device.csv");
  for (const char* command : {"estimate export.zip", "compare --log export.zip --out cmp"}) {
    const test::CommandResult zip = lab(command);
    EXPECT_EQ(zip.status, 2) << command;
    EXPECT_TRUE(zip.err.find("export.zip: error: the zip is damaged") != std::string::npos ||
                zip.err.find("this build was made without minizip") != std::string::npos)
        << command << ": " << zip.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "cmp" / "compare-log.json"));
  // A phone's magnetometer beside the paper's rig: the magnet's pulses on the Earth's field.
  test::HallSignal s;
  s.period_s = 0.79;
  std::string phone = "\"Time (s)\";\"Magnetic field x (\xC2\xB5T)\"\n";
  for (int i = 0; i < 3000; ++i) {
    const double t = i / 100.0;
    std::string row = fmt::format("{:.2f};{:.3f}\n", t, 30.0 + 50.0 * test::dipole_field(s, t));
    for (char& c : row)
      if (c == '.') c = ',';
    phone += row;
  }
  write("Raw Data.csv", phone);
  const test::CommandResult read = lab("estimate 'Raw Data.csv' --json");
  ASSERT_EQ(read.status, 0) << read.err;
  const auto json = nlohmann::json::parse(read.out);
  EXPECT_EQ(json["instrument"], "phyphox magnetometer");
  EXPECT_EQ(json["channel"], "x");
  EXPECT_TRUE(json["decimal_comma"].get<bool>());
  EXPECT_TRUE(json["baseline_adc"].is_null());
  EXPECT_NEAR(json["period_s"].get<double>(), 0.79, 0.79 * 5e-4);
}

}  // namespace
}  // namespace fl
