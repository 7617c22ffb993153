// A measurement file a page sends (POST /api/estimate): read by `frictionlab estimate`'s readers,
// its period the one the request layer gives for the same file, mu_k from the page's spacing by
// the paper's formula, the file named as the page named it (never the server's folder, which is
// gone after the answer), and each refusal a located message: a file with no period, no name, a
// spacing in the wrong unit, a body over the bound (refused before it is read), a form's body.
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include <gtest/gtest.h>

#include "lab/request/estimate_request.hpp"
#include "serve/lab_server_fixture.hpp"
#include "serve/measurement_upload.hpp"
#include "support/run_command.hpp"

namespace fl::serve {
namespace {

const std::string kInstruments =
    std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/assets/examples/instruments/";

class MeasurementUploadTest : public LabServerTest {
 protected:
  void SetUp() override {
    LabServerTest::SetUp();
    // The server's temporary folders land in this test's own.
    std::filesystem::create_directories(dir_ / "tmp");
    setenv("TMPDIR", (dir_ / "tmp").c_str(), 1);
  }
  void TearDown() override {
    unsetenv("TMPDIR");
    LabServerTest::TearDown();
  }
  httplib::Result upload(const std::string& query, const std::string& bytes,
                         const std::string& type = "application/octet-stream") {
    return client_->Post(("/api/estimate" + query).c_str(), bytes, type.c_str());
  }
};

TEST_F(MeasurementUploadTest, APhonesFileGivesTheEstimateOfTheCommandWithThePagesSpacing) {
  const std::string file = kInstruments + "phone-magnetometer.csv";
  const auto res = upload("?name=my%20phone.csv&spacing=0.07", test::read_text(file));
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  const json body = json::parse(res->body);
  EXPECT_EQ(body["file"], "my phone.csv");
  EXPECT_EQ(body["instrument"], "phyphox magnetometer");
  // The request layer on the file itself: the same T, to the bit.
  EstimateRequest request;
  request.logs = {file};
  const OneLogEstimate direct = estimate_one_log(prepare_estimate(request));
  EXPECT_EQ(body["period_s"].get<double>(), direct.json()["period_s"].get<double>());
  EXPECT_EQ(body["periods_used"], direct.json()["periods_used"]);
  // mu_k = 2 pi^2 l / (g T^2) with the page's l (the estimator's single precision).
  const double t = body["period_s"].get<double>();
  EXPECT_NEAR(body["mu_k"].get<double>(),
              2 * std::numbers::pi * std::numbers::pi * 0.07 / (9.81 * t * t), 1e-6);
  EXPECT_EQ(body["spacing_m"].get<double>(), 0.07);
  EXPECT_EQ(body.size(), 18u) << body.dump();  // MeasurementEstimate's keys
  // The file's folder went with the answer.
  EXPECT_TRUE(std::filesystem::is_empty(dir_ / "tmp"));
}

TEST_F(MeasurementUploadTest, AZipIsReadFromTheEntryItHolds) {
  const auto res = upload("?name=C:%5CUsers%5Cada%5Cexport.zip",
                          test::read_text(kInstruments + "phone-export.zip"));
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  EXPECT_EQ(json::parse(res->body)["file"], "export.zip/Raw Data.csv");
}

TEST_F(MeasurementUploadTest, RefusalsAreLocatedAndNameNoFolderOfTheServer) {
  // Noise: the reader's message, at the file as the page named it.
  const auto noise = upload("?name=noise.csv", "t_s,adc\n0,1\n0.001,5\n0.002,3\n");
  ASSERT_TRUE(noise);
  EXPECT_EQ(noise->status, 400);
  const std::string said = json::parse(noise->body)["error"];
  EXPECT_EQ(said.rfind("noise.csv:", 0), 0u) << said;
  EXPECT_EQ(noise->body.find("frictionlab-upload"), std::string::npos) << noise->body;
  EXPECT_EQ(noise->body.find(dir_.string()), std::string::npos) << noise->body;
  // No name; a spacing of 89 m (a plain number is SI): by field.
  const auto nameless = upload("", "t_s,adc\n");
  ASSERT_TRUE(nameless);
  EXPECT_EQ(nameless->status, 400);
  EXPECT_NE(nameless->body.find("expected the file's name as ?name="), std::string::npos);
  const auto metres =
      upload("?name=a.csv&spacing=89", test::read_text(kInstruments + "phone-magnetometer.csv"));
  ASSERT_TRUE(metres);
  EXPECT_EQ(metres->status, 400);
  const json problems = json::parse(metres->body)["problems"];
  ASSERT_EQ(problems.size(), 1u) << metres->body;
  EXPECT_EQ(problems[0]["field"], "spacing");
  // A form's body (curl's default) is read up to 8 KiB only: said so.
  const auto form =
      upload("?name=a.csv", std::string(20000, 'a'), "application/x-www-form-urlencoded");
  ASSERT_TRUE(form);
  EXPECT_EQ(form->status, 413);
  EXPECT_NE(form->body.find("application/octet-stream"), std::string::npos) << form->body;
  EXPECT_TRUE(std::filesystem::is_empty(dir_ / "tmp"));
}

TEST_F(MeasurementUploadTest, AFileOverTheBoundIsRefusedBeforeItIsReadAndOtherPathsKeepTheirs) {
  // 40 MiB declared, nothing sent: refused at once, the connection kept open by the client.
  RawConnection big(port_);
  ASSERT_TRUE(big.connected());
  big.send(
      "POST /api/estimate?name=big.mp4 HTTP/1.1\r\nHost: lab\r\n"
      "Content-Type: application/octet-stream\r\nContent-Length: 41943040\r\n\r\n");
  const std::string refused = big.answer();
  EXPECT_EQ(refused.rfind("HTTP/1.1 413", 0), 0u) << refused.substr(0, 200);
  EXPECT_NE(refused.find("larger than 32 MiB"), std::string::npos) << refused.substr(0, 400);
  // A session's body keeps its 64 KiB: refused before its bytes are read too.
  RawConnection session(port_);
  ASSERT_TRUE(session.connected());
  session.send(
      "POST /api/sessions HTTP/1.1\r\nHost: lab\r\nContent-Type: application/json\r\n"
      "Content-Length: 100000\r\n\r\n");
  const std::string kept = session.answer();
  EXPECT_EQ(kept.rfind("HTTP/1.1 413", 0), 0u) << kept.substr(0, 200);
  EXPECT_NE(kept.find("larger than 64 KiB"), std::string::npos) << kept.substr(0, 400);
  const auto after = client_->Get("/api/lab");
  ASSERT_TRUE(after);
  EXPECT_EQ(after->status, 200);
}

TEST_F(MeasurementUploadTest, TwoFilesAtOnceAndAThirdIsToldToComeBackBeforeItIsRead) {
  const std::string csv = test::read_text(kInstruments + "phone-magnetometer.csv");
  const std::string head = fmt::format(
      "POST /api/estimate?name=slow.csv HTTP/1.1\r\nHost: lab\r\nContent-Type: "
      "application/octet-stream\r\nConnection: close\r\nContent-Length: {}\r\n\r\n",
      csv.size());
  // Two files still coming (their heads sent, their bodies not), then a third's head alone. The
  // server reads the three heads on threads of its own, in an order the test cannot choose: a
  // round in which the third came before the others (and waited for its body until the server's
  // read timeout), or a round's first met the last round's places not yet given back, is tried
  // again, fresh, within a minute however loaded the machine.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  std::string refused, answered;
  while (answered.rfind("HTTP/1.1 200", 0) != 0 && std::chrono::steady_clock::now() < deadline) {
    RawConnection first(port_), second(port_);
    ASSERT_TRUE(first.send(head));
    ASSERT_TRUE(second.send(head));
    RawConnection third(port_);
    ASSERT_TRUE(third.send(head));
    refused = third.answer();  // refused from its head, its body never sent
    if (refused.rfind("HTTP/1.1 503", 0) != 0) continue;
    // The first file comes whole and is read.
    first.send(csv);
    answered = first.answer();
  }
  EXPECT_EQ(refused.rfind("HTTP/1.1 503", 0), 0u) << refused.substr(0, 300);
  EXPECT_NE(refused.find("send yours again"), std::string::npos) << refused.substr(0, 400);
  EXPECT_EQ(answered.rfind("HTTP/1.1 200", 0), 0u) << answered.substr(0, 300);
  // Its place and the second's were given back: a new file is taken.
  const auto after = upload("?name=after.csv", csv);
  ASSERT_TRUE(after);
  EXPECT_EQ(after->status, 200) << after->body;
}

TEST(UploadName, TheFilesLastPartInLettersTheServerKeeps) {
  EXPECT_EQ(upload_name("C:\\Users\\ada\\Raw Data.csv"), "Raw Data.csv");
  EXPECT_EQ(upload_name("../../etc/passwd"), "passwd");
  EXPECT_EQ(upload_name("fréquence;rm.csv"), "fr__quence_rm.csv");
  EXPECT_EQ(upload_name(".."), "measurement");
  EXPECT_EQ(upload_name(""), "measurement");
  EXPECT_EQ(upload_name(std::string(300, 'a') + ".csv").size(), 100u);
}

}  // namespace
}  // namespace fl::serve
