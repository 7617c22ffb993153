// The lab in the page's worker (browser/browser_lab.hpp), built natively: a session stepped to its
// end is `frictionlab run`'s run of the same set-up (summary and files byte for byte), a refused
// set-up has the request layer's problems by field, the controls and an unknown session answer as
// the server does, and a measurement file gives the request layer's period for it.
#include "browser/browser_lab.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hall_log/hall_log.hpp"
#include "lab/logs/log_estimate.hpp"
#include "lab/request/estimate_request.hpp"
#include "lab/request/report_request.hpp"
#include "lab/run/run_outputs.hpp"
#include "lab/run/summary_fields.hpp"
#include "support/run_command.hpp"
#include "support/scene_fixture.hpp"

namespace fl::browser {
namespace {

using nlohmann::json;

BrowserLab test_lab() {
  return BrowserLab(std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes",
                    FRICTIONLAB_TEST_ASSET_DIR, "frictionlab test");
}

// Steps the session (1/30 s of simulated time a step) until its `done`; every event in order.
std::vector<std::pair<std::string, json>> step_to_done(BrowserLab& lab, const std::string& id) {
  std::vector<std::pair<std::string, json>> out;
  for (int i = 0; i < 10000; ++i) {
    EXPECT_EQ(lab.control(id, R"({"action": "step"})").status, 200);
    const Answer frame = lab.events(id);
    EXPECT_EQ(frame.status, 200);
    for (const json& e : frame.body) out.emplace_back(e["event"], e["data"]);
    if (!out.empty() && out.back().first == "done") return out;
  }
  ADD_FAILURE() << "no done after 10000 steps";
  return out;
}

TEST(BrowserLab, OffersTheScenesOfItsFolderAndThePapersMaterials) {
  const Answer lab = test_lab().lab();
  ASSERT_EQ(lab.status, 200);
  std::vector<std::string> names;
  for (const json& s : lab.body["scenes"]) names.push_back(s["name"]);
  EXPECT_NE(std::find(names.begin(), names.end(), "paper-rig"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "minimal"), names.end());
  EXPECT_EQ(lab.body["version"], "frictionlab test");
  EXPECT_FALSE(lab.body["materials"].empty());
}

TEST(BrowserLab, ASessionSteppedToItsEndIsRunsRunByteForByte) {
  BrowserLab lab = test_lab();
  const Answer made = lab.create_session(
      R"({"scene": "minimal", "set": ["world.duration=1.5s", "rollers.spacing=70mm"]})");
  ASSERT_EQ(made.status, 201) << made.body.dump();
  const std::string id = made.body["id"];
  EXPECT_EQ(made.body["rig"]["spacing"].get<double>(), 0.07);
  const auto events = step_to_done(lab, id);
  ASSERT_FALSE(events.empty());

  const Scene scene = test::scene_file(
      "minimal.yaml",
      std::vector<SceneOverride>{{"world.duration", "1.5s"}, {"rollers.spacing", "70mm"}});
  const CompiledRig rig = compile_rig(scene);
  RunRecording recording;
  const RunSummary summary = run_experiment(rig, recording_for(scene.output), &recording);
  EXPECT_EQ(events.back().second, summary_json(summary));
  for (const auto& [name, text] : run_output_files(scene.output, rig, summary, recording)) {
    if (name == "timing.json") continue;
    const Answer file = lab.file(id, name);
    ASSERT_EQ(file.status, 200) << name;
    EXPECT_TRUE(file.body["text"] == text) << name << " differs from run's";
  }
  // Simulated time only moves forward, one step's 1/30 s at a time.
  double previous = -1.0;
  for (const auto& [name, data] : events) {
    if (name != "state") continue;
    EXPECT_GT(data["t"].get<double>(), previous);
    previous = data["t"].get<double>();
  }
}

// The session's lab report: refused before the run ends, then the run's summary in it, the
// student and the stopwatch from the body, in the language asked; a body it cannot take refused
// at its field.
TEST(BrowserLab, ASessionsReportHoldsItsSummaryInTheLanguageAsked) {
  BrowserLab lab = test_lab();
  const std::string id =
      lab.create_session(R"({"scene": "minimal", "set": ["world.duration=2s"], "name": "Ada"})")
          .body["id"];
  EXPECT_EQ(lab.report(id, "").status, 409);
  const auto events = step_to_done(lab, id);
  const json& summary = events.back().second;
  const Answer english = lab.report(id, "");
  ASSERT_EQ(english.status, 200) << english.body.dump();
  const std::string html = english.body["html"];
  EXPECT_NE(html.find("<html lang=\"en\">"), std::string::npos);
  EXPECT_NE(html.find("data-field=\"student\">Ada<"), std::string::npos);  // the session's name
  EXPECT_NE(html.find("data-value=\"" + summary["period_s"].dump() + "\""), std::string::npos);
  const Answer french = lab.report(id, R"({"student": "Curie, M.", "language": "fr",
              "stopwatch": [{"periods": 10, "wall_s": 7.9, "simulated_s": null}]})");
  ASSERT_EQ(french.status, 200) << french.body.dump();
  const std::string fr = french.body["html"];
  EXPECT_NE(fr.find("<html lang=\"fr\">"), std::string::npos);
  EXPECT_NE(fr.find("Curie, M."), std::string::npos);
  EXPECT_NE(fr.find("Chronométré à la main"), std::string::npos);
  EXPECT_NE(fr.find("<td class=\"n\">7,90</td>"), std::string::npos);
  for (const char* body : {R"({"language": "EN"})", R"({"language": 3})", R"({"colour": "red"})",
                           R"({"stopwatch": [{"periods": 0, "wall_s": 1, "simulated_s": null}]})",
                           R"({"stopwatch": [{"periods": 10, "wall_s": -1, "simulated_s": null}]})",
                           R"({"student": "=1+1"})", "[1, 2]", "{"}) {
    const Answer refused = lab.report(id, body);
    EXPECT_EQ(refused.status, 400) << body;
    EXPECT_FALSE(refused.body["error"].get<std::string>().empty()) << body;
  }
  // The page's "Your measurement", as the lab's estimate answered it: a part of its own, its
  // numbers the estimate's, beside the simulation's.
  const std::string phone = std::string(FRICTIONLAB_TEST_SOURCE_DIR) +
                            "/assets/examples/instruments/phone-magnetometer.csv";
  const Answer measured =
      lab.estimate("phone-magnetometer.csv", test::read_text(phone), "0.089", std::nullopt);
  ASSERT_EQ(measured.status, 200) << measured.body.dump();
  const Answer both = lab.report(id, json{{"measurement", measured.body}}.dump());
  ASSERT_EQ(both.status, 200) << both.body.dump();
  const std::string with = both.body["html"];
  EXPECT_NE(with.find("Measurement: phone-magnetometer.csv"), std::string::npos);
  EXPECT_NE(
      with.find("data-field=\"period_s\" data-value=\"" + measured.body["period_s"].dump() + "\""),
      std::string::npos);
  EXPECT_NE(with.find("data-field=\"mu_k\" data-value=\"" + measured.body["mu_k"].dump() + "\""),
            std::string::npos);
  json broken = measured.body;
  broken["period_s"] = -1;
  EXPECT_EQ(lab.report(id, json{{"measurement", broken}}.dump()).status, 400);
  broken.erase("period_s");
  EXPECT_EQ(lab.report(id, json{{"measurement", broken}}.dump()).status, 400);
  // A language the lab's data has no catalogue for: refused by the report's request, by field.
  const Answer klingon = lab.report(id, R"({"language": "tlh"})");
  EXPECT_EQ(klingon.status, 400);
  EXPECT_EQ(klingon.body["problems"][0]["field"], "language") << klingon.body.dump();
  EXPECT_EQ(lab.report("nope", "").status, 404);
}

// Bytes in base64, written here as RFC 4648 says, independently of the lab's decoder.
std::string base64_of(const std::string& bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t at = 0; at < bytes.size(); at += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - at);
    unsigned int group = 0;
    for (std::size_t k = 0; k < 3; ++k)
      group = (group << 8) | (k < n ? static_cast<unsigned char>(bytes[at + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k)
      out += k <= n ? kAlphabet[(group >> (18 - 6 * k)) & 0x3F] : '=';
  }
  return out;
}

// The number of `needle`s in `text`.
std::size_t count_of(const std::string& text, const std::string& needle) {
  std::size_t count = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1))
    ++count;
  return count;
}

// With its file, the student's measurement is in the report as `frictionlab report FILE` puts
// it: its signal and every period the estimator judged, its file named as the student named it.
TEST(BrowserLab, AReportWithTheMeasurementsFileHoldsItsSignalAndPeriods) {
  BrowserLab lab = test_lab();
  const std::string id =
      lab.create_session(R"({"scene": "minimal", "set": ["world.duration=2s"]})").body["id"];
  step_to_done(lab, id);
  const std::string phone = std::string(FRICTIONLAB_TEST_SOURCE_DIR) +
                            "/assets/examples/instruments/phone-magnetometer.csv";
  const std::string bytes = test::read_text(phone);
  const Answer measured = lab.estimate("phone-magnetometer.csv", bytes, "0.089", std::nullopt);
  ASSERT_EQ(measured.status, 200) << measured.body.dump();
  const json file{{"name", "phone-magnetometer.csv"}, {"base64", base64_of(bytes)}};
  const Answer answer =
      lab.report(id, json{{"measurement", measured.body}, {"measurement_file", file}}.dump());
  ASSERT_EQ(answer.status, 200) << answer.body.dump();
  const std::string html = answer.body["html"];
  const std::string part = html.substr(html.find("Measurement: phone-magnetometer.csv"));
  // The file read by the command line's report, at the same spacing: its periods, one row each.
  ReportRequest cli;
  cli.inputs = {phone};
  cli.measurement.spacing = 0.089;
  const ReportResult alone = make_report(cli);
  ASSERT_EQ(alone.content.parts.size(), 1u);
  const std::size_t periods = alone.content.parts[0].periods.size();
  ASSERT_GE(periods, 5u);
  const std::string table = part.substr(part.find("<table class=\"periods-table\">"));
  EXPECT_EQ(count_of(table.substr(0, table.find("</table>")), "<tr"), periods + 1);  // + header
  EXPECT_GE(count_of(part, "<svg"), 2u);  // the signal as read, and the periods
  EXPECT_NE(
      part.find("data-field=\"period_s\" data-value=\"" + measured.body["period_s"].dump() + "\""),
      std::string::npos);
  EXPECT_EQ(html.find("frictionlab-upload-"), std::string::npos);  // no server folder in it
  // A file that is not base64, or without the measurement it was estimated as: refused.
  const json broken{{"name", "x.csv"}, {"base64", "not base64!"}};
  EXPECT_EQ(
      lab.report(id, json{{"measurement", measured.body}, {"measurement_file", broken}}.dump())
          .status,
      400);
  EXPECT_EQ(lab.report(id, json{{"measurement_file", file}}.dump()).status, 400);
}

TEST(BrowserLab, AnUnchangedStateIsNotSentAgain) {
  BrowserLab lab = test_lab();
  const std::string id = lab.create_session(R"({"scene": "minimal"})").body["id"];
  const auto names = [&] {
    std::vector<std::string> out;
    for (const json& e : lab.events(id).body) out.push_back(e["event"]);
    return out;
  };
  EXPECT_EQ(names(), std::vector<std::string>{"state"});  // paused at t = 0
  EXPECT_TRUE(names().empty());                           // still paused: nothing new
  EXPECT_EQ(lab.control(id, R"({"action": "step"})").status, 200);
  EXPECT_EQ(names(), std::vector<std::string>{"state"});  // a step: the plate moved
  EXPECT_TRUE(names().empty());
  EXPECT_EQ(lab.control(id, R"({"speed": 0.25})").status, 200);
  EXPECT_EQ(names(), std::vector<std::string>{"state"});  // the speed changed
  EXPECT_EQ(lab.control(id, R"({"action": "reset"})").status, 200);
  EXPECT_EQ(names(), (std::vector<std::string>{"reset", "state"}));
}

TEST(BrowserLab, NoRegimeIsSaidBeforeThePlateHasTurned) {
  BrowserLab lab = test_lab();
  const std::string id = lab.create_session(R"({"scene": "minimal"})").body["id"];
  // Each state's time, way (the sign of vx) and regime, over 2 s of steps.
  int first_way = 0;
  bool turned = false;
  bool said = false;
  for (int i = 0; i < 60; ++i) {
    for (const json& e : lab.events(id).body) {
      if (e["event"] != "state") continue;
      const double vx = e["data"]["vx"];
      const int way = vx > 0.0 ? 1 : vx < 0.0 ? -1 : 0;
      if (first_way == 0) first_way = way;
      turned = turned || (way != 0 && way != first_way);
      const std::string regime = e["data"]["regime"];
      // A regime is what the trajectory shows: an oscillation once the plate came back.
      if (!turned) {
        EXPECT_EQ(regime, "") << "t = " << e["data"]["t"];
      }
      said = said || regime == "oscillates";
    }
    lab.control(id, R"({"action": "step"})");
  }
  EXPECT_TRUE(turned);
  EXPECT_TRUE(said);
}

TEST(BrowserLab, ARefusedSetUpHasItsProblemsByField) {
  BrowserLab lab = test_lab();
  const Answer refused =
      lab.create_session(R"({"scene": "minimal", "set": ["rollers.spacing=-3mm"]})");
  EXPECT_EQ(refused.status, 400);
  ASSERT_EQ(refused.body["problems"].size(), 1u);
  EXPECT_EQ(refused.body["problems"][0]["value"], "rollers.spacing=-3mm");
  EXPECT_NE(refused.body["problems"][0]["message"].get<std::string>().find("positive"),
            std::string::npos);
  const Answer unknown = lab.create_session(R"({"scene": "../etc/passwd"})");
  EXPECT_EQ(unknown.status, 400);
  const Answer broken = lab.create_session("{not json");
  EXPECT_EQ(broken.status, 400);
  EXPECT_TRUE(broken.body.contains("error"));
}

TEST(BrowserLab, ControlsAndAnUnknownSessionAnswerAsTheServer) {
  BrowserLab lab = test_lab();
  const std::string id = lab.create_session(R"({"scene": "minimal"})").body["id"];
  EXPECT_EQ(lab.control(id, R"({"action": "play"})").body["playing"], true);
  EXPECT_EQ(lab.control(id, R"({"speed": 0.25})").body["speed"], 0.25);
  EXPECT_EQ(lab.control(id, R"({"speed": 3})").status, 400);
  EXPECT_EQ(lab.control(id, R"({"action": "fly"})").status, 400);
  // Files come when the run has ended.
  EXPECT_EQ(lab.file(id, "summary.json").status, 404);
  EXPECT_EQ(lab.end(id).status, 200);
  EXPECT_EQ(lab.events(id).status, 404);
  EXPECT_EQ(lab.control(id, R"({"action": "play"})").status, 404);
  EXPECT_EQ(lab.end(id).status, 404);
}

TEST(BrowserLab, AMeasurementFileGivesTheRequestLayersPeriod) {
  const std::string file = std::string(FRICTIONLAB_TEST_SOURCE_DIR) +
                           "/assets/examples/instruments/phone-magnetometer.csv";
  const Answer answer =
      test_lab().estimate("phone.csv", test::read_text(file), "0.089", std::nullopt);
  ASSERT_EQ(answer.status, 200) << answer.body.dump();
  EstimateRequest request;
  request.logs = {file};
  const OneLogEstimate direct = estimate_one_log(prepare_estimate(request));
  EXPECT_EQ(answer.body["period_s"].get<double>(), direct.json()["period_s"].get<double>());
  EXPECT_EQ(answer.body["file"], "phone.csv");
  const Answer refused = test_lab().estimate("notes.txt", "hello\n", std::nullopt, std::nullopt);
  EXPECT_EQ(refused.status, 400);
}

TEST(BrowserLab, ARigFedByThePageGivesEstimatesPeriodsOnItsLog) {
  BrowserLab lab = test_lab();
  // A simulated run of the paper's rig with a rigid-foam plate (T = 0.30 s), as the firmware's
  // 1 kHz lines.
  const Answer made = lab.create_session(
      R"({"scene": "paper-rig", "set": ["friction.mu_k=rigid-foam", "world.duration=3.5s"]})");
  ASSERT_EQ(made.status, 201);
  const std::string id = made.body["id"];
  const json summary = step_to_done(lab, id).back().second;
  const double truth = summary["period_trajectory_s"];
  const std::string hall = lab.file(id, "hall.csv").body["text"];
  std::string lines =
      "# frictionlab rig firmware 1: sample_hz=1000 sample_us=1000.0000 "
      "raw_every=1\r\nt_us,adc\r\n";
  for (std::size_t at = hall.find('\n') + 1; at < hall.size();) {
    const std::size_t end = hall.find('\n', at);
    lines += hall.substr(at, end - at) + "\r\n";
    at = end + 1;
  }

  EXPECT_EQ(lab.rig_log().status, 404);
  EXPECT_EQ(lab.rig_bytes("12,500\r\n", false).status, 409);  // no port open
  const Answer opened = lab.rig_open("USB 2341:0043", 250000);
  ASSERT_EQ(opened.status, 200) << opened.body.dump();
  EXPECT_EQ(opened.body["state"], "waiting");
  EXPECT_EQ(lab.rig_open("USB 2341:0043", 0).status, 400);
  // The page reads the port in pieces of any size; a line may be split between two.
  std::vector<json> events;
  for (std::size_t at = 0; at < lines.size(); at += 997) {
    lab.rig_bytes(lines.substr(at, 997), false);
    for (const json& e : lab.events(id).body)
      if (e["event"] == "rig") events.push_back(e["data"]);
  }
  const Answer gone = lab.rig_bytes("", true);
  EXPECT_EQ(gone.body["state"], "unplugged");
  for (const json& e : lab.events(id).body)
    if (e["event"] == "rig") events.push_back(e["data"]);
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.back()["state"], "unplugged");

  // The log is every byte sent; `estimate` on it finds the page's periods, each exactly.
  const Answer log = lab.rig_log();
  ASSERT_EQ(log.status, 200);
  EXPECT_TRUE(log.body["text"] == lines);
  LogSetUp set_up;
  set_up.spacing = events.back()["spacing"];
  const LogEstimate estimate =
      estimate_log(parse_hall_log(log.body["text"].get<std::string>(), "rig.log"), set_up, false);
  std::vector<json> page;
  for (const json& e : events)
    for (const json& p : e["periods"]) page.push_back(p);
  ASSERT_GE(page.size(), 6u);
  ASSERT_GE(estimate.periods.size(), page.size());
  for (std::size_t i = 0; i < page.size(); ++i) {
    const EstimatedPeriod& p = estimate.periods[i];
    EXPECT_EQ(page[i], json::array({p.start, p.end, p.period, p.status == fl_estimator::kAccepted}))
        << i;
  }
  ASSERT_FALSE(events.back()["estimate"].is_null());
  EXPECT_NEAR(events.back()["estimate"]["period"].get<double>(), truth, 5e-4 * truth);
  // Closed by the page: the log stays.
  EXPECT_EQ(lab.rig_close().body["lines"], events.back()["lines"]);
}

}  // namespace
}  // namespace fl::browser
