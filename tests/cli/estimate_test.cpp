// frictionlab estimate LOG: T +- dT and mu_k from Hall logs the test writes from a synthetic
// signal with a known period, and exit status 2 with a located message for logs that give none.
#include <unistd.h>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../support/run_command.hpp"
#include "../support/temp_folder.hpp"
#include "core/analytic_model.hpp"
#include "estimator/synthetic_hall.hpp"

namespace fl {
namespace {

const std::string kExe = FRICTIONLAB_EXE;

class Estimate : public test::TempFolderTest {
 protected:
  Estimate() : TempFolderTest("fl-estimate") {}

  // The samples as a CSV with the given header; the time in microseconds or seconds.
  std::string write_csv(const std::string& name, const test::HallSamples& s,
                        const std::string& header, bool seconds, const std::string& prefix = "") {
    std::string text = prefix + header + "\n";
    char line[64];
    for (std::size_t i = 0; i < s.adc.size(); ++i) {
      if (seconds)
        std::snprintf(line, sizeof line, "%.6f,%u\n", s.t_us[i] * 1e-6, s.adc[i]);
      else
        std::snprintf(line, sizeof line, "%u,%u\n", s.t_us[i], s.adc[i]);
      text += line;
    }
    return write(name, text);
  }

  test::CommandResult lab(const std::string& args) {
    return test::run_command(kExe + " estimate " + args);
  }

  nlohmann::json json(const std::string& args) {
    const test::CommandResult r = lab(args + " --json");
    EXPECT_EQ(r.status, 0) << r.err;
    return nlohmann::json::parse(r.out);
  }
};

test::HallSignal rig() {
  test::HallSignal s;
  s.period_s = 0.79;
  s.duration_s = 30.0;
  return s;
}

TEST_F(Estimate, APeriodWithinFiveHundredthsOfAPercentAndTheModelsMuK) {
  const test::HallSignal s = rig();
  const std::string log = write_csv("hall.csv", test::generate(s), "t_us,adc", false);
  const nlohmann::json j = json(log);
  for (const char* key :
       {"period_s", "period_std_s", "period_sem_s", "periods_used", "periods_discarded", "mu_k",
        "mu_k_err_worst", "mu_k_err_quadrature", "pulses", "geometry", "samples", "spacing_m",
        "spacing_err_m", "gravity_m_s2", "format", "periods", "plot"})
    EXPECT_TRUE(j.contains(key)) << key;
  const double period = j["period_s"].get<double>();
  EXPECT_NEAR(period, s.period_s, 5e-4 * s.period_s);
  EXPECT_EQ(j["periods_discarded"].get<int>(), 0);
  EXPECT_GE(j["periods_used"].get<int>(),
            static_cast<int>(test::turning_times(s, 0.0, s.duration_s).size()) - 4);
  EXPECT_EQ(j["geometry"], "one-pulse");
  EXPECT_EQ(j["format"], "csv");
  EXPECT_DOUBLE_EQ(j["spacing_m"].get<double>(), 0.089);
  const MuKUncertainty model = mu_k_with_uncertainty(period, j["period_std_s"].get<double>(), 0.089,
                                                     0.002, 0.0, kDefaultGravity);
  EXPECT_NEAR(j["mu_k"].get<double>(), model.mu_k, 1e-6 * model.mu_k);
  EXPECT_NEAR(j["mu_k_err_worst"].get<double>(), model.worst, 1e-6 * model.worst);
  EXPECT_NEAR(j["mu_k_err_quadrature"].get<double>(), model.quadrature, 1e-6 * model.quadrature);
  EXPECT_EQ(j["periods"].size(),
            j["periods_used"].get<std::size_t>() + j["periods_discarded"].get<std::size_t>());
}

TEST_F(Estimate, SecondsMicrosecondsAndTheFirmwaresCaptureAgree) {
  test::HallSignal s = rig();
  s.noise_counts = 2.0;
  s.sensor_offset_m = -0.010;  // a pair per period
  const test::HallSamples samples = test::generate(s);
  const nlohmann::json us = json(write_csv("us.csv", samples, "t_us,adc", false));
  const nlohmann::json sec = json(write_csv("s.csv", samples, "time,value", true));
  const nlohmann::json fw = json(write_csv(
      "rig.log", samples, "t_us,adc", false,
      "# frictionlab rig firmware 1: sample_hz=1000 sample_us=1000.0000 raw_every=1\r\n"));
  EXPECT_EQ(us["geometry"], "pair");
  EXPECT_EQ(us["period_s"], sec["period_s"]);
  EXPECT_EQ(us["period_std_s"], sec["period_std_s"]);
  EXPECT_EQ(us["period_s"], fw["period_s"]);
  EXPECT_EQ(fw["format"], "firmware");
  EXPECT_EQ(sec["time_column"], "time");
  EXPECT_EQ(sec["adc_column"], "value");
}

TEST_F(Estimate, JumpsAreCountedAndLeftOut) {
  test::HallSignal s = rig();
  const auto turn = test::turning_times(s, 0.0, s.duration_s);
  s.blanks.push_back({turn.at(10) - 0.15, turn.at(10) + 0.15});
  s.spurious.push_back(turn.at(20) + 0.3 * s.period_s);
  const nlohmann::json j = json(write_csv("jumps.csv", test::generate(s), "t_us,adc", false));
  EXPECT_EQ(j["periods_discarded"].get<int>(), 3);
  EXPECT_EQ(j["periods_outliers"].get<int>(), 1);
  EXPECT_NEAR(j["period_s"].get<double>(), s.period_s, 5e-4 * s.period_s);
}

TEST_F(Estimate, TheSpacingGivesMuK) {
  const std::string log = write_csv("hall.csv", test::generate(rig()), "t_us,adc", false);
  const nlohmann::json a = json(log);
  const nlohmann::json b = json(log + " --spacing 10cm --spacing-err 1mm");
  EXPECT_DOUBLE_EQ(b["spacing_m"].get<double>(), 0.1);
  EXPECT_DOUBLE_EQ(b["spacing_err_m"].get<double>(), 0.001);
  EXPECT_NEAR(b["mu_k"].get<double>() / a["mu_k"].get<double>(), 0.1 / 0.089, 1e-6);
}

// A student's one comparison: the paper's value for the plate's material, named by --material or
// by the log's sidecar, and the difference in combined standard errors, computed here from the
// two values and their uncertainties.
TEST_F(Estimate, OneLogBesideThePapersValueForItsMaterial) {
  test::HallSignal slow = rig();
  slow.period_s = 0.94;  // LEGO at 77 K: T = 0.94 +- 0.02 s, mu_k = 0.20 +- 0.01
  const std::string log = write_csv("hall.csv", test::generate(slow), "t_us,adc", false);
  const nlohmann::json j = json(log + " --material lego --temperature 77K");
  const nlohmann::json& paper = j["paper"];
  EXPECT_EQ(paper["material"], "LEGO blocks");
  EXPECT_EQ(paper["temperature_k"], 77.0);
  EXPECT_EQ(paper["mu_k"], 0.20);
  EXPECT_EQ(paper["mu_k_err"], 0.01);
  const double mu = j["mu_k"];
  const double err = j["mu_k_err_quadrature"];
  EXPECT_NEAR(paper["difference_standard_errors"].get<double>(),
              (mu - 0.20) / std::sqrt(err * err + 0.01 * 0.01), 1e-9);
  const test::CommandResult text = lab(log + " --material lego --temperature 77K");
  EXPECT_NE(text.out.find("LEGO blocks at 77 K: mu_k 0.2 +- 0.01, T 0.94 +- 0.02 s"),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("combined standard errors from it"), std::string::npos) << text.out;
  // Without a material: no comparison (null, not a made-up one).
  EXPECT_TRUE(json(log)["paper"].is_null());
  // The sidecar's material, and a material the paper has not at that temperature.
  write("hall.yaml", "material: plexiglas\n");
  EXPECT_EQ(json(log)["paper"]["key"], "plexiglas");
  const test::CommandResult cold = lab(log + " --material iron --temperature 77K");
  EXPECT_EQ(cold.status, 2);
  EXPECT_NE(cold.err.find("the paper measured Iron at 300 K only"), std::string::npos) << cold.err;
}

// A geometry given that the log contradicts is said before the result, with the numbers the log
// gives read as it shows itself: a one-pulse log given as pairs would quarter mu_k unsaid.
TEST_F(Estimate, AGeometryTheLogContradictsIsSaid) {
  const std::string one = write_csv("one.csv", test::generate(rig()), "t_us,adc", false);
  const test::CommandResult pair = lab(one + " --geometry pair");
  ASSERT_EQ(pair.status, 0) << pair.err;
  EXPECT_NE(pair.err.find("warning: --geometry pair: the log shows one pulse per period"),
            std::string::npos)
      << pair.err;
  EXPECT_NE(pair.err.find("T = 0.79"), std::string::npos) << pair.err;
  test::HallSignal passes = rig();
  passes.sensor_offset_m = -0.012;  // the magnet passes the sensor and comes back: a pair
  const std::string two = write_csv("two.csv", test::generate(passes), "t_us,adc", false);
  // A pair given as one: the alternating intervals fit no period, and the error says which to
  // give.
  const test::CommandResult forced = lab(two + " --geometry one");
  EXPECT_EQ(forced.status, 2);
  EXPECT_NE(forced.err.find("give --geometry pair"), std::string::npos) << forced.err;
  // Given as it is: nothing said.
  EXPECT_EQ(lab(one + " --geometry one").err.find("warning"), std::string::npos);
  EXPECT_EQ(lab(two + " --geometry pair").err.find("warning"), std::string::npos);
}

// A time column read in the wrong unit: a log named in seconds whose times are milliseconds
// shows no pulse (5999 s of one sample a second), one named in microseconds gives T = 0.79 ms and
// mu_k 286944. Both are refused, saying the unit that makes the log a rig's, which then works.
TEST_F(Estimate, ATimeReadInTheWrongUnitIsRefusedNamingTheUnitThatFits) {
  const test::HallSamples samples = test::generate(rig());
  std::string text;
  for (std::size_t i = 0; i < samples.adc.size(); ++i)
    text += std::to_string(samples.t_us[i] / 1000) + "," + std::to_string(samples.adc[i]) + "\n";
  const std::string as_seconds = write("seconds.csv", "t_s,adc\n" + text);
  const std::string as_micros = write("micros.csv", "t_us,adc\n" + text);
  for (const std::string& log : {as_seconds, as_micros}) {
    const test::CommandResult r = lab(log);
    EXPECT_EQ(r.status, 2) << log;
    // Checked before it is given: the period it names is the one the unit then gives.
    EXPECT_NE(r.err.find("if its time is in ms, give --time-unit ms, which reads it as T = 0.79"),
              std::string::npos)
        << r.err;
    const nlohmann::json fixed = json(log + " --time-unit ms");
    // The times above are whole milliseconds: a pulse is timed within 1 ms, so the mean period
    // within 1 ms of 0.79 s, and 2 ms bounds it.
    EXPECT_NEAR(fixed["period_s"].get<double>(), 0.79, 2e-3) << log;
  }
  EXPECT_NE(lab(as_micros).err.find("mu_k = 2"), std::string::npos);
}

TEST_F(Estimate, PrintsAReadableSummary) {
  const std::string log = write_csv("hall.csv", test::generate(rig()), "t_us,adc", false);
  const test::CommandResult r = lab(log);
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* text :
       {"period T", "mu_k", "one pulse per period", "discarded", "89.0 +- 2.0 mm"})
    EXPECT_NE(r.out.find(text), std::string::npos) << text << "\n" << r.out;
}

TEST_F(Estimate, PlotsWhatTheEstimatorSaw) {
  test::HallSignal s = rig();
  s.spurious.push_back(12.3);
  const std::string log = write_csv("hall.csv", test::generate(s), "t_us,adc", false);
  const std::string png = (dir_ / "hall.png").string();
  const nlohmann::json j = json(log + " --plot " + png);
  EXPECT_EQ(j["plot"], png);
  std::ifstream f(png, std::ios::binary);
  char magic[8] = {};
  f.read(magic, 8);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  EXPECT_GT(std::filesystem::file_size(png), 10000u);
}

TEST_F(Estimate, BadLogsExitWithStatusTwoAndSayWhatWasFound) {
  test::HallSignal flat = rig();
  flat.peak_counts = 0.0;
  flat.noise_counts = 1.0;
  flat.duration_s = 5.0;
  test::HallSignal three = rig();  // three pulses: two to learn the signal from, one left
  three.duration_s = 2.0;
  test::HallSignal few = rig();  // too few pulses to tell the geometry
  few.duration_s = 4.5;
  struct Case {
    std::string args;
    std::string message;
  };
  const std::string dir = dir_.string();
  for (const Case& c : {
           // No header: read by position, the time in microseconds (1 kHz); no pulse in it.
           Case{write("numbers.csv", "0,512\n1000,513\n"),
                dir + "/numbers.csv:1: error: no pulse in 2 samples"},
           Case{write("text.csv", "t_us,adc\n0,512\nabc,513\n"),
                dir + "/text.csv:3:1: error: column \"t_us\": expected a number, found \"abc\""},
           Case{write("back.csv", "t_s,adc\n0.1,512\n0.3,513\n0.2,514\n"),
                dir + "/back.csv:3:1: error: time 0.3 s is ahead of the next sample's 0.2 s"},
           Case{write("empty.csv", ""), dir + "/empty.csv:1: error: the log is empty"},
           Case{write_csv("flat.csv", test::generate(flat), "t_us,adc", false),
                dir + "/flat.csv:2: error: no pulse in 5000 samples"},
           Case{write_csv("three.csv", test::generate(three), "t_us,adc", false),
                dir + "/three.csv:"},
           Case{write_csv("few.csv", test::generate(few), "t_us,adc", false), dir + "/few.csv:"},
           Case{dir + "/missing.csv", dir + "/missing.csv: error: cannot open the log"},
           Case{dir + "/x.csv --geometry banana",
                "--geometry banana: error: expected auto, one or pair"},
           Case{dir + "/x.csv --spacing 89kg", "--spacing: error: expected a length"},
       }) {
    const test::CommandResult r = lab(c.args);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.out << r.err;
    EXPECT_EQ(r.err.rfind(c.message, 0), 0u) << c.args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << c.args;  // never a made-up period
  }
  EXPECT_NE(lab(dir + "/three.csv").err.find("only one pulse"), std::string::npos);
  EXPECT_NE(lab(dir + "/few.csv").err.find("needs five in a row"), std::string::npos);
}

TEST_F(Estimate, StandardInputAndAFolder) {
  const std::string log = write_csv("hall.csv", test::generate(rig()), "t_us,adc", false);
  const nlohmann::json file = json(log);
  const test::CommandResult in =
      test::run_command("sh -c '" + kExe + " estimate - --json < " + log + "'");
  ASSERT_EQ(in.status, 0) << in.err;
  const nlohmann::json piped = nlohmann::json::parse(in.out);
  EXPECT_EQ(piped["log"], "<stdin>");
  EXPECT_EQ(piped["period_s"], file["period_s"]);
  // A folder: its hall.csv (a run's outputs), or its only log.
  const nlohmann::json folder = json(dir_.string());
  EXPECT_EQ(folder["file"], log);
  EXPECT_EQ(folder["period_s"], file["period_s"]);
  std::filesystem::create_directories(dir_ / "one");
  std::filesystem::copy_file(log, dir_ / "one" / "rig-log.txt");
  EXPECT_EQ(json((dir_ / "one").string())["period_s"], file["period_s"]);
  std::filesystem::copy_file(log, dir_ / "one" / "again.csv");
  // A folder of several logs: the table of them, one row per log, by name.
  const test::CommandResult two = lab((dir_ / "one").string() + " --json");
  ASSERT_EQ(two.status, 0) << two.err;
  const nlohmann::json rows = nlohmann::json::parse(two.out)["logs"];
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0]["label"], "again.csv");
  EXPECT_EQ(rows[1]["label"], "rig-log.txt");
  EXPECT_EQ(rows[1]["period_s"], file["period_s"]);
}

// Each error's advice names an option, and following it gives the true period.
TEST_F(Estimate, TheAdviceInAnErrorWorks) {
  const test::HallSignal s = rig();
  const test::HallSamples samples = test::generate(s);
  struct Case {
    std::string log;
    std::string advice;  // in the message, and what is then given
    double period_s;     // the truth
  };
  // A sensor at the middle of the travel: evenly spaced passes shaped like a pass.
  test::HallSignal middle = rig();
  middle.sensor_offset_m = -middle.amplitude_m;
  // A sensor inside the turning point by 0.75 of the amplitude: a pair too wide to recognise.
  test::HallSignal wide = rig();
  wide.sensor_offset_m = -0.75 * wide.amplitude_m;
  // A sketch printing millis() at 2 kHz: every other time repeats.
  test::HallSignal fast = rig();
  fast.sample_rate_hz = 2000.0;
  fast.duration_s = 10.0;
  const test::HallSamples fast_samples = test::generate(fast);
  std::string millis = "millis,adc\n";
  for (std::size_t i = 0; i < fast_samples.adc.size(); ++i)
    millis += std::to_string(fast_samples.t_us[i] / 1000) + "," +
              std::to_string(fast_samples.adc[i]) + "\n";
  // Values only, and three numbers a line without a header.
  std::string values = "sensorValue\n";
  std::string three;
  for (std::size_t i = 0; i < samples.adc.size(); ++i) {
    values += std::to_string(samples.adc[i]) + "\n";
    three += std::to_string(samples.t_us[i] / 1000) + "," + std::to_string(samples.adc[i]) + ",7\n";
  }
  for (const Case& c : {
           Case{write_csv("middle.csv", test::generate(middle), "t_us,adc", false),
                "--geometry pair", middle.period_s},
           Case{write_csv("wide.csv", test::generate(wide), "t_us,adc", false), "--geometry pair",
                wide.period_s},
           Case{write("millis.csv", millis), "--rate 2kHz", fast.period_s},
           Case{write("values.csv", values), "--rate 1kHz", s.period_s},
           Case{write("three.csv", three), "--columns t_ms,adc,_", s.period_s},
       }) {
    const test::CommandResult r = lab(c.log);
    EXPECT_EQ(r.status, 2) << c.log << "\n" << r.out;
    EXPECT_EQ(r.err.rfind(c.log + ":", 0), 0u) << r.err;
    const std::string option = c.advice.substr(0, c.advice.find(' '));
    EXPECT_NE(r.err.find(option), std::string::npos) << r.err;
    if (option == "--geometry") {
      EXPECT_NE(r.err.find(c.advice), std::string::npos) << r.err;
    }
    const nlohmann::json j = json(c.log + " " + c.advice);
    EXPECT_NEAR(j["period_s"].get<double>(), c.period_s, 5e-4 * c.period_s) << c.log;
  }
}

// Advice is checked before it is given: each way of reading the log the message would suggest is
// tried on it, and the message names the ones that give a rig's period, with the period they give
// (the one the option then gives), or says what was tried when none does: a column of a counter
// under a values-only header read at 1 kHz gives no pulse, so --rate 1kHz is not advised.
TEST_F(Estimate, AdviceIsCheckedBeforeItIsGiven) {
  const test::HallSamples samples = test::generate(rig());
  std::string three;  // time in ms, the value, a constant: no header
  for (std::size_t i = 0; i < samples.adc.size(); ++i)
    three += std::to_string(samples.t_us[i] / 1000) + "," + std::to_string(samples.adc[i]) + ",7\n";
  const std::string log = write("three.csv", three);
  const test::CommandResult r = lab(log);
  EXPECT_EQ(r.status, 2);
  const std::string advised = "the log reads with --columns t,adc,_: T = ";
  const std::size_t at = r.err.find(advised);
  ASSERT_NE(at, std::string::npos) << r.err;
  // The only reading that works: the constant or the value as the time give none.
  EXPECT_EQ(r.err.find("; or with"), std::string::npos) << r.err;
  const double said = std::stod(r.err.substr(at + advised.size()));
  const nlohmann::json j = json(log + " --columns t,adc,_");
  EXPECT_NEAR(j["period_s"].get<double>(), said, 5e-5);
  EXPECT_NEAR(said, 0.79, 2e-3);

  std::string counter = "Hall\n";  // a banner-like header over a counter: no Hall signal
  for (int i = 0; i < 5000; ++i) counter += std::to_string(1000 + i) + "\n";
  const test::CommandResult c = lab(write("counter.csv", counter));
  EXPECT_EQ(c.status, 2);
  EXPECT_NE(c.err.find("tried --rate 1kHz on it: it gives no period of a rig"), std::string::npos)
      << c.err;
  EXPECT_EQ(c.err.find("for example --rate 1kHz"), std::string::npos) << c.err;
}

TEST_F(Estimate, APlotEvenWhenThereIsNoPeriod) {
  test::HallSignal flat = rig();
  flat.peak_counts = 0.0;
  flat.duration_s = 3.0;
  const std::string log = write_csv("flat.csv", test::generate(flat), "t_us,adc", false);
  const std::string png = (dir_ / "flat.png").string();
  const test::CommandResult r = lab(log + " --plot " + png);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("the plot " + png + " shows the signal"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(png));
}

}  // namespace
}  // namespace fl
