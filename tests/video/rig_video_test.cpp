// frictionlab run --video/--frames/--still: an MP4 that ffprobe reports as H.264 in yuv420p with
// duration x fps x slow-motion frames (plus the title card's), exactly the expected PNG files,
// a still; captions on the frames whose simulated time they cover; --title and --orbit; a run
// that asks for no frames never starts GL, opens a mesh or loads the renderer (the video module
// and what it links); missing components, a missing or foreign video module and bad options fail
// with status 2 and a message that names them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/components.hpp"
#include "render/rig/force_overlay.hpp"
#include "render/sinks/png.hpp"
#include "support/run_command.hpp"

namespace fl {
namespace {

namespace fs = std::filesystem;

const std::string kExe = FRICTIONLAB_EXE;
const std::string kScenes = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/";
const std::string kRig = kScenes + "paper-rig.yaml";
// Whether this build draws frames: the drawing layer and a GL back end (OSMesa or EGL).
constexpr bool kDraws = render::kHasRender && (render::kHasOsmesa || render::kHasEgl);

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(FRICTIONLAB_TEST_BINARY_DIR) / "rig-video-test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Under LeakSanitizer, frictionlab's GL runs meet OSMesa's own leaks: the suppressions the GL
// tests use (lsan.supp) go to it too; without a sanitizer the variable is ignored.
test::CommandResult lab(const std::string& args, const std::string& env = "") {
  const std::string lsan =
      "LSAN_OPTIONS=suppressions=" FRICTIONLAB_TEST_SOURCE_DIR "/tests/render/lsan.supp ";
  return test::run_command(lsan + env + (env.empty() ? "" : " ") + kExe + " " + args);
}

bool have_ffprobe() {
  return test::run_command("ffprobe -version").status == 0;
}

// ffprobe's view of the video stream and the container.
nlohmann::json probe(const fs::path& file) {
  const auto r = test::run_command(
      "ffprobe -v error -select_streams v:0 -count_frames -show_entries "
      "stream=codec_name,pix_fmt,width,height,r_frame_rate,nb_read_frames,duration "
      "-show_entries format=duration -of json " +
      file.string());
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

#define FL_REQUIRE_VIDEO_RUN()                                                                \
  do {                                                                                        \
    if (!kDraws || !render::kHasVideo) GTEST_SKIP() << "built without rendering or video";    \
    if (!have_ffprobe()) GTEST_SKIP() << "ffprobe is not installed (apt-get install ffmpeg)"; \
  } while (0)

TEST(RigVideo, TheMp4HasTheFramesOfTheVideosClock) {
  FL_REQUIRE_VIDEO_RUN();
  const fs::path dir = fresh_dir("mp4");
  struct Case {
    std::string args;
    int frames;       // duration x fps x slow motion, + 2 s x fps of title card
    double duration;  // s of video
  };
  for (const Case& c : {
           // 1 s simulated at 10 fps, 2x slow motion: 20 frames, 2 s of video.
           Case{"--duration 1s --fps 10 --slow-motion 2 --set video.title=false --set "
                "video.end_card=false",
                20, 2.0},
           // With the scene's title card (2 s x 10 fps more in front) and end card (3 s x 10 fps
           // after).
           Case{"--duration 1s --fps 10 --slow-motion 2", 70, 7.0},
           // Real time at 24 fps: 0.5 s -> 12 frames.
           Case{"--duration 0.5s --fps 24 --set video.title=false --set video.end_card=false", 12,
                0.5},
       }) {
    const fs::path file = dir / "rig.mp4";
    fs::remove(file);
    const auto r = lab("run " + kRig + " --size 320x180 " + c.args + " --video " + file.string());
    ASSERT_EQ(r.status, 0) << c.args << "\n" << r.err;
    const auto j = probe(file);
    const auto& s = j["streams"][0];
    EXPECT_EQ(s["codec_name"], "h264") << c.args;
    EXPECT_EQ(s["pix_fmt"], "yuv420p") << c.args;
    EXPECT_EQ(s["width"], 320);
    EXPECT_EQ(s["height"], 180);
    EXPECT_EQ(std::stoi(s["nb_read_frames"].get<std::string>()), c.frames) << c.args;
    EXPECT_NEAR(std::stod(s["duration"].get<std::string>()), c.duration, 1e-3) << c.args;
    EXPECT_NEAR(std::stod(j["format"]["duration"].get<std::string>()), c.duration, 1e-3) << c.args;
    EXPECT_NE(r.out.find("video                  " + std::to_string(c.frames) + " frames"),
              std::string::npos)
        << r.out;
    EXPECT_FALSE(fs::exists(file.string() + ".part"));
  }
}

// The file's extension picks the format: each written by a short run and read back by ffprobe.
TEST(RigVideo, EachFormatHasItsCodecFramesSizeAndDuration) {
  FL_REQUIRE_VIDEO_RUN();
  const fs::path dir = fresh_dir("formats");
  struct Case {
    std::string file;
    std::string args;
    std::string codec;
    int width, height, frames;
    double duration;  // s
  };
  const std::string short_run =
      "--duration 0.5s --fps 10 --size 320x180 --set video.title=false --set video.end_card=false";
  for (const Case& c : {
           Case{"rig.mp4", short_run, "h264", 320, 180, 5, 0.5},
           Case{"rig.webm", short_run, "vp9", 320, 180, 5, 0.5},
           Case{"rig.gif", short_run, "gif", 320, 180, 5, 0.5},
           // A GIF without --size and --fps: the scene's 1280x720 at 30 fps drawn at 640x360
           // and 10 fps; 1 s, the 2 s title card and the 3 s end card: 60 frames.
           Case{"title.gif", "--duration 1s", "gif", 640, 360, 60, 6.0},
       }) {
    const fs::path file = dir / c.file;
    const auto r = lab("run " + kRig + " " + c.args + " --video " + file.string());
    ASSERT_EQ(r.status, 0) << c.file << "\n" << r.err;
    const auto j = probe(file);
    const auto& s = j["streams"][0];
    EXPECT_EQ(s["codec_name"], c.codec) << c.file;
    EXPECT_EQ(s["width"], c.width) << c.file;
    EXPECT_EQ(s["height"], c.height) << c.file;
    EXPECT_EQ(std::stoi(s["nb_read_frames"].get<std::string>()), c.frames) << c.file;
    EXPECT_NEAR(std::stod(j["format"]["duration"].get<std::string>()), c.duration, 1e-3) << c.file;
    EXPECT_FALSE(fs::exists(file.string() + ".part"));
  }
}

// An extension it cannot write is refused before anything is loaded, run or created: status 2,
// the accepted extensions named, the file's folder not even made.
TEST(RigVideo, AnUnknownVideoFormatIsRefusedBeforeAnyWork) {
  const fs::path dir = fresh_dir("refused");
  for (const std::string name : {"new/rig.avi", "new/rig", "new/rig.mp4.txt"}) {
    const auto r = lab("run " + kRig + " --duration 600s --video " + (dir / name).string());
    EXPECT_EQ(r.status, 2) << name;
    EXPECT_NE(r.err.find("--video: error: expected a video file ending in .mp4, .gif or .webm"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.out, "") << name;  // no run, no summary
    EXPECT_FALSE(fs::exists(dir / "new")) << name;
  }
}

// Ctrl-C during a run with a video: the video up to its last frame, playable, in every format.
TEST(RigVideo, AnInterruptedRunClosesAPlayableVideoInEveryFormat) {
  FL_REQUIRE_VIDEO_RUN();
  const fs::path dir = fresh_dir("interrupted");
  for (const std::string extension : {"mp4", "webm", "gif"}) {
    const fs::path file = dir / ("rig." + extension);
    const auto r = test::run_command(
        "(LSAN_OPTIONS=suppressions=" FRICTIONLAB_TEST_SOURCE_DIR "/tests/render/lsan.supp " +
        kExe + " run " + kRig + " --duration 600s --fps 10 --size 320x180 " +
        "--set video.title=false --set video.end_card=false --video " + file.string() +
        " & pid=$!; sleep 4; kill -INT $pid; wait $pid; echo status $?)");
    EXPECT_NE(r.out.find("status 130"), std::string::npos) << extension << "\n" << r.out << r.err;
    ASSERT_TRUE(fs::exists(file)) << extension << "\n" << r.err;
    EXPECT_FALSE(fs::exists(file.string() + ".part"));
    const auto j = probe(file);
    const int frames = std::stoi(j["streams"][0]["nb_read_frames"].get<std::string>());
    EXPECT_GT(frames, 0) << extension;
    // As many frames as the run reported writing.
    EXPECT_NE(r.out.find("video                  " + std::to_string(frames) + " frames"),
              std::string::npos)
        << extension << "\n"
        << r.out;
  }
}

// --gl egl draws on EGL; auto takes EGL where it starts, and where it does not (here: glvnd
// given no vendor library) draws on OSMesa with a one-line note saying why.
TEST(RigVideo, TheEglBackEndDrawsAndAutoFallsBackToOsmesaWithANote) {
  if (!kDraws || !render::kHasEgl || !render::kHasOsmesa)
    GTEST_SKIP() << "built without both GL back ends";
  const fs::path dir = fresh_dir("egl");
  const std::string still = " --duration 0.2s --size 160x90 --still ";
  auto r = lab("run " + kRig + still + (dir / "egl.png").string() + " --gl egl");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("note:"), std::string::npos) << r.err;
  // The output says which back end and which GL renderer drew the frames.
  EXPECT_NE(r.out.find("  renderer               "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(EGL"), std::string::npos) << r.out;
  const std::string egl_out = r.out;
  r = lab("run " + kRig + still + (dir / "osmesa.png").string() + " --gl osmesa");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("(OSMesa"), std::string::npos) << r.out;
  // llvmpipe without a GPU, named by GL_RENDERER in both, and in --json.
  for (const std::string& out : {egl_out, r.out})
    EXPECT_NE(out.find("llvmpipe"), std::string::npos) << out;
  const auto json = lab("run " + kRig + still + (dir / "json.png").string() + " --json");
  ASSERT_EQ(json.status, 0) << json.err;
  EXPECT_NE(json.out.find("\"renderer\": \""), std::string::npos) << json.out;
  // One renderer (llvmpipe) behind both: the same picture.
  EXPECT_EQ(test::read_text(dir / "egl.png"), test::read_text(dir / "osmesa.png"));
  const std::string no_vendor = "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json";
  r = lab("run " + kRig + still + (dir / "x.png").string() + " --gl egl", no_vendor);
  if (r.status == 0) GTEST_SKIP() << "this libEGL is not glvnd's: EGL cannot be made to fail";
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("error: EGL"), std::string::npos) << r.err;
  r = lab("run " + kRig + still + (dir / "auto.png").string(), no_vendor);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("note: GL back end egl did not start ("), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("); using osmesa\n"), std::string::npos) << r.err;
  EXPECT_EQ(test::read_text(dir / "auto.png"), test::read_text(dir / "osmesa.png"));
}

TEST(RigVideo, FramesWritesExactlyTheExpectedFilesAndAStill) {
  if (!kDraws) GTEST_SKIP() << "built without rendering or without a GL back end";
  const fs::path dir = fresh_dir("frames");
  const fs::path frames = dir / "frames";
  const fs::path still = dir / "still.png";
  const auto names = [&] {
    std::set<std::string> out;
    for (const auto& e : fs::directory_iterator(frames)) out.insert(e.path().filename().string());
    return out;
  };
  // 0.5 s at 10 fps: frames at t = 0, 0.1, ... 0.4 s.
  auto r = lab(
      "run " + kRig +
      " --duration 0.5s --fps 10 --size 160x90 --set video.title=false --set video.end_card=false" +
      " --frames " + frames.string() + " --still " + still.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(names(),
            (std::set<std::string>{"frame_000000.png", "frame_000001.png", "frame_000002.png",
                                   "frame_000003.png", "frame_000004.png"}));
  const render::Image first = render::read_png((frames / "frame_000000.png").string());
  EXPECT_EQ(first.width, 160);
  EXPECT_EQ(first.height, 90);
  const render::Image end = render::read_png(still.string());
  EXPECT_EQ(end.width, 160);
  // A second run into the same folder replaces the first one's frames: 3 frames now.
  r = lab(
      "run " + kRig +
      " --duration 0.3s --fps 10 --size 160x90 --set video.title=false --set video.end_card=false" +
      " --frames " + frames.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(names(),
            (std::set<std::string>{"frame_000000.png", "frame_000001.png", "frame_000002.png"}));
}

// Rollers off their shafts (0.45 mm): the plate jumps and the estimator discards most periods;
// the video's Hall plot shades them red, which true rollers never show.
// The end of the last period the run's estimator rejected [s], from its periods.csv; < 0 if none.
double last_rejected_end(const fs::path& periods_csv) {
  std::ifstream in(periods_csv);
  std::string line;
  std::getline(in, line);  // start_s,end_s,period_s,status
  double last = -1.0;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string start, end, period, status;
    std::getline(fields, start, ',');
    std::getline(fields, end, ',');
    std::getline(fields, period, ',');
    std::getline(fields, status);
    if (status.rfind("rejected", 0) == 0) last = std::stod(end);
  }
  return last;
}

// Where the run's estimator rejected a period, the Hall plot shades it. A hopping plate is
// chaotic (docs/physics.md): which periods its jumps spoil is one realization, so the still is
// taken just after the last period this very run rejected, which the plot then shows.
TEST(RigVideo, TheHallPlotShadesTheDiscardedPeriods) {
  if (!kDraws) GTEST_SKIP() << "built without rendering or without a GL back end";
  const fs::path dir = fresh_dir("discarded");
  const auto reddish = [&](const std::string& runout, const std::string& duration) {
    const fs::path still = dir / ("still-" + runout + ".png");
    const auto r = lab("run " + kScenes + "imperfect/runout.yaml --set rollers.runout=" + runout +
                       " --duration " + duration + " --size 640x360 --still " + still.string());
    EXPECT_EQ(r.status, 0) << r.err;
    const render::Image image = render::read_png(still.string());
    // The Hall plot: the panel at the bottom left (8 to 308 px across, 256 to 352 px down).
    int count = 0;
    for (int y = 262; y < 350; ++y)
      for (int x = 12; x < 304; ++x) {
        const auto p = image.view().at(x, y);
        // Red over the grey panel (green and blue alike), not the orange trace (blue far below
        // green).
        if (p[0] > p[1] + 30 && std::abs(p[1] - p[2]) < 20) ++count;
      }
    return count;
  };
  const auto run = lab("run " + kScenes + "imperfect/runout.yaml --set rollers.runout=0.45mm " +
                       "--duration 30s --out " + (dir / "run").string());
  ASSERT_EQ(run.status, 0) << run.err;
  const double rejected = last_rejected_end(dir / "run" / "periods.csv");
  ASSERT_GT(rejected, 0.0) << "0.45 mm of run-out spoiled no period in 30 s";
  // Measured: about 4900 shaded pixels of the plot's 25 700 with the jumps, none without.
  EXPECT_GT(reddish("0.45mm", std::to_string(rejected + 0.1) + "s"), 1000);
  EXPECT_EQ(reddish("0mm", "30s"), 0);
}

// The pixels of one colour (within 3 of each channel), as 4-connected groups: their sizes and
// their longest extents (the largest distance between two of their pixels).
struct PixelGroup {
  int pixels = 0;
  double extent = 0.0;  // px
  double min_x = 1e9;   // px
};
std::vector<PixelGroup> colour_groups(const render::Image& image, const render::Color& colour,
                                      int x0, int x1, int y0, int y1) {
  const auto matches = [&](int x, int y) {
    const auto p = image.view().at(x, y);
    const float want[3] = {colour.r, colour.g, colour.b};
    for (int c = 0; c < 3; ++c)
      if (std::abs(static_cast<int>(p[c]) - static_cast<int>(std::lround(want[c] * 255.0f))) > 3)
        return false;
    return true;
  };
  std::vector<int> seen(static_cast<std::size_t>(image.width * image.height), 0);
  std::vector<PixelGroup> groups;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      if (seen[static_cast<std::size_t>(y * image.width + x)] || !matches(x, y)) continue;
      std::vector<std::array<int, 2>> members, todo{{x, y}};
      seen[static_cast<std::size_t>(y * image.width + x)] = 1;
      while (!todo.empty()) {
        const auto [px, py] = todo.back();
        todo.pop_back();
        members.push_back({px, py});
        for (const auto [dx, dy] : {std::array{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
          const int nx = px + dx, ny = py + dy;
          if (nx < x0 || nx >= x1 || ny < y0 || ny >= y1) continue;
          auto& mark = seen[static_cast<std::size_t>(ny * image.width + nx)];
          if (mark || !matches(nx, ny)) continue;
          mark = 1;
          todo.push_back({nx, ny});
        }
      }
      PixelGroup g;
      g.pixels = static_cast<int>(members.size());
      for (const auto& a : members) {
        g.min_x = std::min(g.min_x, static_cast<double>(a[0]));
        for (const auto& b : members)
          g.extent = std::max(g.extent, std::hypot(a[0] - b[0], a[1] - b[1]));
      }
      groups.push_back(g);
    }
  return groups;
}

// The forces on screen are the solver's: a run stopped with the plate off centre, the still's
// weight bars and normal-force arrows measured in pixels against the contact forces the
// trajectory file holds for the same last step.
TEST(RigVideo, TheForceArrowsAndWeightBarsFollowTheTrajectorysContactForces) {
  if (!kDraws) GTEST_SKIP() << "built without rendering or without a GL back end";
  const fs::path dir = fresh_dir("forces");
  const fs::path still = dir / "still.png";
  // At 0.25 s the plate (released 30 mm off centre, T = 0.78 s) is 13 mm on roller 0's side:
  // roller 0 carries about 1.8 times roller 1's load.
  const auto r = lab("run " + kRig + " --duration 0.25s --size 1280x720 --still " + still.string() +
                     " --out " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream trajectory(dir / "out" / "trajectory.csv");
  std::string line, last;
  while (std::getline(trajectory, line))
    if (!line.empty()) last = line;
  std::vector<double> row;
  std::stringstream cells(last);
  for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
  ASSERT_EQ(row.size(), 11u) << last;
  const double n0 = row[7], n1 = row[9];  // normal0_n, normal1_n
  ASSERT_GT(n0, 1.5 * n1) << "the plate is not where the test expects it";
  ASSERT_GT(n1, 0.0);

  const render::Image image = render::read_png(still.string());
  // The weight bars: the normal force's colour in the left quarter, two tall groups (the labels'
  // glyphs are small).
  const render::WeightBars bars = render::weight_bars(Eigen::Vector2f(0.0f, 0.0f), 2.0f);
  const double full = bars.full[0].height;  // px, a share of 1 at 1280x720
  auto left = colour_groups(image, render::kNormalForceColor, 0, 320, 40, 500);
  std::erase_if(left, [](const PixelGroup& g) { return g.pixels < 500; });
  ASSERT_EQ(left.size(), 2u);
  std::sort(left.begin(), left.end(),
            [](const PixelGroup& a, const PixelGroup& b) { return a.min_x < b.min_x; });
  const double width = bars.full[0].width;
  const double tall0 = left[0].pixels / width, tall1 = left[1].pixels / width;
  EXPECT_NEAR(tall0, n0 / (n0 + n1) * full, 1.5);
  EXPECT_NEAR(tall1, n1 / (n0 + n1) * full, 1.5);

  // The arrows N0 and N1 over the rig: the two largest groups of that colour right of the
  // panels longer than a label's glyph (about 20 px); their lengths in pixels stand as the forces
  // do (one scale for every arrow).
  auto arrows = colour_groups(image, render::kNormalForceColor, 320, 1280, 40, 560);
  std::erase_if(arrows, [](const PixelGroup& g) { return g.extent < 30.0; });
  std::sort(arrows.begin(), arrows.end(),
            [](const PixelGroup& a, const PixelGroup& b) { return a.pixels > b.pixels; });
  ASSERT_GE(arrows.size(), 2u);
  arrows.resize(2);
  std::sort(arrows.begin(), arrows.end(),
            [](const PixelGroup& a, const PixelGroup& b) { return a.min_x < b.min_x; });
  // Roller 0 is on the left. A group's extent is the arrow's length plus half its shaft's width
  // (the square end behind its start), within a pixel at each end.
  const double shaft = 2.2;  // px: half of 2 x 2.2 px
  const double l0 = arrows[0].extent - shaft, l1 = arrows[1].extent - shaft;
  EXPECT_NEAR(l0 / l1, n0 / n1, (n0 / n1) * (2.0 / l0 + 2.0 / l1))
      << "arrow lengths " << l0 << " and " << l1 << " px for " << n0 << " and " << n1 << " N";
}

// A run a guard stops (rollers turning outward push the plate off at t = 0.21 s) ends its video
// on its last frame held for 2 s under a red banner; a run that ends normally has none.
TEST(RigVideo, ARunAGuardStoppedEndsOnABannerSayingWhy) {
  if (!kDraws) GTEST_SKIP() << "built without rendering or without a GL back end";
  const fs::path dir = fresh_dir("guard");
  const auto red_rows = [](const render::Image& image) {
    int rows = 0;
    for (int y = 0; y < image.height; ++y) {
      int red = 0;
      for (int x = 0; x < image.width; ++x) {
        const auto p = image.view().at(x, y);
        if (p[0] > 130 && p[1] < 60 && p[2] < 60) ++red;
      }
      if (red > image.width / 2) ++rows;
    }
    return rows;
  };
  auto r = lab("run " + kScenes + "extreme/rollers-outward.yaml --duration 1s --fps 10 --size " +
               "320x180 --frames " + (dir / "stopped").string());
  EXPECT_EQ(r.status, 3) << r.err;
  // Frames at t = 0, 0.1, 0.2 s, then 2 s x 10 fps of banner.
  EXPECT_TRUE(fs::exists(dir / "stopped" / "frame_000022.png"));
  EXPECT_FALSE(fs::exists(dir / "stopped" / "frame_000023.png"));
  EXPECT_EQ(red_rows(render::read_png((dir / "stopped" / "frame_000002.png").string())), 0);
  // The banner is 30 px tall at 320x180 (a heading and two lines of reason); its text leaves
  // more than a third of its rows mostly red (18 measured).
  EXPECT_GT(red_rows(render::read_png((dir / "stopped" / "frame_000022.png").string())), 10);
  r = lab("run " + kRig + " --duration 0.3s --fps 10 --size 320x180 --set video.title=false " +
          "--set video.end_card=false --frames " + (dir / "normal").string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir / "normal" / "frame_000003.png"));
  EXPECT_EQ(red_rows(render::read_png((dir / "normal" / "frame_000002.png").string())), 0);
}

// The pixels where two PNG frames differ: how many, and how many of them lie outside a region.
struct Difference {
  int pixels = 0;
  int outside = 0;
};
Difference difference(const fs::path& a, const fs::path& b, int x0, int y0, int x1, int y1) {
  const render::Image p = render::read_png(a.string());
  const render::Image q = render::read_png(b.string());
  Difference d;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      const auto u = p.view().at(x, y);
      const auto v = q.view().at(x, y);
      if (u[0] == v[0] && u[1] == v[1] && u[2] == v[2]) continue;
      ++d.pixels;
      d.outside += x < x0 || x >= x1 || y < y0 || y >= y1;
    }
  return d;
}

// frame_000007.png
std::string frame_name(int k) {
  const std::string digits = std::to_string(k);
  return "frame_" + std::string(6 - digits.size(), '0') + digits + ".png";
}

// --captions replaces the scene's narration; a caption shows while the simulated time is in it,
// so at 2x slow motion and 10 fps (t = k / 20 s) a caption from 0.3 s to 0.5 s is on frames 6 to 9,
// and one from 0.8 s with no end on frames 16 to the last. Those frames differ from a run without
// captions only above the bottom panels (y < 256 at 640x360); every other frame is the same file.
TEST(RigVideo, CaptionsShowWhileTheSimulatedTimeIsInThem) {
  if (!kDraws) GTEST_SKIP() << "built without rendering or without a GL back end";
  const fs::path dir = fresh_dir("captions");
  std::ofstream(dir / "captions.yaml")
      << "captions:\n"
         "  - {at: 0.3 s, until: 0.5 s, text: The rollers turn toward each other.}\n"
         "  - {at: 0.8 s, text: \"The net friction pulls the plate back: \xcf\x89\xc2\xb2 = "
         "2\xce\xbc\xe2\x82\x96g/l.\"}\n";
  std::ofstream(dir / "none.yaml") << "captions: []\n";
  const std::string run = "run " + kRig +
                          " --duration 1s --fps 10 --slow-motion 2 --size 640x360 "
                          "--set video.title=false --set video.end_card=false";
  auto r = lab(run + " --captions " + (dir / "captions.yaml").string() + " --frames " +
               (dir / "with").string());
  ASSERT_EQ(r.status, 0) << r.err;
  r = lab(run + " --captions " + (dir / "none.yaml").string() + " --frames " +
          (dir / "without").string());
  ASSERT_EQ(r.status, 0) << r.err;
  for (int k = 0; k < 20; ++k) {
    const std::string name = frame_name(k);
    const bool captioned = (k >= 6 && k <= 9) || k >= 16;
    if (!captioned) {
      EXPECT_EQ(test::read_text(dir / "with" / name), test::read_text(dir / "without" / name))
          << name;
      continue;
    }
    const Difference d = difference(dir / "with" / name, dir / "without" / name, 40, 100, 600, 256);
    EXPECT_GT(d.pixels, 2000) << name;
    EXPECT_EQ(d.outside, 0) << name;
  }
}

// video.phase_portrait adds v against x under the motion strip and changes nothing else of the
// frame: at 640x360 its panel spans x 490 to 632, y 122 to 202 (rig_overlay.hpp), and the
// camera still frames the paper's rig as without it.
TEST(RigVideo, ThePhasePortraitChangesOnlyItsPanel) {
  if (!kDraws) GTEST_SKIP() << "built without rendering or without a GL back end";
  const fs::path dir = fresh_dir("phase");
  const std::string run = "run " + kRig + " --duration 1s --size 640x360 --still ";
  auto r = lab(run + (dir / "plain.png").string());
  ASSERT_EQ(r.status, 0) << r.err;
  r = lab(run + (dir / "phase.png").string() + " --set video.phase_portrait=true");
  ASSERT_EQ(r.status, 0) << r.err;
  const Difference d = difference(dir / "phase.png", dir / "plain.png", 490, 122, 632, 202);
  EXPECT_GT(d.pixels, 3000);  // a panel of 142 x 80 with an ellipse, a trace and axes
  EXPECT_EQ(d.outside, 0);
}

// scenes/extreme/roller-200rpm.yaml, the portrait's teaching case: the rollers' surface speed
// v_r (0.21 m/s) lies inside the theory's ellipse, so the dashed slip limits are in view and the
// ellipse (light blue, dashed) crosses them, while the plate's own trace (white) stays between
// them: it caught up with a roller and its amplitude was clipped.
TEST(RigVideo, ThePortraitOfAClippedPlateKeepsItsTraceInsideTheSlipLimits) {
  if (!kDraws) GTEST_SKIP() << "built without rendering or without a GL back end";
  const fs::path dir = fresh_dir("phase-clipped");
  const fs::path still = dir / "still.png";
  const auto r = lab("run " + kScenes + "extreme/roller-200rpm.yaml --duration 4s --size 640x360 " +
                     "--set video.phase_portrait=true --still " + still.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const render::Image image = render::read_png(still.string());
  // The portrait's plot area (its panel spans x 490 to 632, y 122 to 202 at 640x360).
  int limit_top = 1 << 20, limit_bottom = -1;
  std::vector<int> white_rows, blue_rows;
  for (int y = 140; y < 190; ++y) {
    int orange = 0;
    for (int x = 530; x < 626; ++x) {
      const auto p = image.view().at(x, y);
      orange += p[0] > 180 && p[1] < 170 && p[2] < 120;
      if (p[0] > 225 && p[1] > 225 && p[2] > 225) white_rows.push_back(y);
      if (p[0] < 170 && p[1] > 170 && p[2] > 220) blue_rows.push_back(y);
    }
    // A dashed line across the area (3 of every 5 points drawn; 26 of these 96 pixels measured).
    if (orange > 15) {
      limit_top = std::min(limit_top, y);
      limit_bottom = std::max(limit_bottom, y);
    }
  }
  ASSERT_GE(limit_top, 0);
  ASSERT_GT(limit_bottom - limit_top, 20) << "two limit lines, one above the other";
  ASSERT_FALSE(white_rows.empty());
  ASSERT_FALSE(blue_rows.empty());
  // The trace between the lines' outer edges (it runs along them while clipped); the ellipse
  // beyond them.
  EXPECT_GE(*std::min_element(white_rows.begin(), white_rows.end()), limit_top);
  EXPECT_LE(*std::max_element(white_rows.begin(), white_rows.end()), limit_bottom);
  // The ellipse's top speed is A0 Omega = 1.16 v_r: 2 px past each line at this size.
  EXPECT_LT(*std::min_element(blue_rows.begin(), blue_rows.end()), limit_top);
  EXPECT_GT(*std::max_element(blue_rows.begin(), blue_rows.end()), limit_bottom);
}

// --title turns the title card on and replaces its title, and only the title: the first frame
// differs from the scene's own card only in the title's band at the top. --orbit turns the
// camera: the frames drift away from those of a camera that stays put.
TEST(RigVideo, TheTitleAndTheOrbitFromTheCommandLine) {
  if (!kDraws) GTEST_SKIP() << "built without rendering or without a GL back end";
  const fs::path dir = fresh_dir("title-orbit");
  const std::string run =
      "run " + kRig + " --duration 0.2s --fps 10 --size 320x180 --set video.end_card=false";
  auto r = lab(run + " --frames " + (dir / "scene").string());
  ASSERT_EQ(r.status, 0) << r.err;
  r = lab(run + " --set video.title=false --title 'Kinetic friction, measured' --frames " +
          (dir / "titled").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("video                  22 frames (20 title, 0 ending)"), std::string::npos)
      << r.out;
  const Difference title =
      difference(dir / "titled" / frame_name(0), dir / "scene" / frame_name(0), 0, 0, 320, 50);
  EXPECT_GT(title.pixels, 300);
  EXPECT_EQ(title.outside, 0);

  const std::string still = "run " + kRig + " --duration 1s --fps 10 --size 320x180 " +
                            "--set video.title=false --set video.end_card=false --frames ";
  r = lab(still + (dir / "still").string());
  ASSERT_EQ(r.status, 0) << r.err;
  r = lab(still + (dir / "orbit").string() + " --orbit 90deg/s");
  ASSERT_EQ(r.status, 0) << r.err;
  // 0.9 s of video at 90 deg/s: the camera has turned 81 degrees.
  const Difference turned =
      difference(dir / "orbit" / frame_name(9), dir / "still" / frame_name(9), 0, 0, 0, 0);
  EXPECT_GT(turned.pixels, 320 * 180 / 5);
}

TEST(RigVideo, ARunWithoutFramesNeverStartsGl) {
  // An unknown back end: a plain run does not care, a run that draws fails naming it.
  const std::string env = "FRICTIONLAB_GL=nonsense";
  auto r = lab("run " + kRig + " --duration 0.2s --json", env);
  EXPECT_EQ(r.status, 0) << r.err;
  r = lab("run " + kRig + " --duration 0.2s --still x.png", env);
  EXPECT_EQ(r.status, 2);
  if (render::kHasRender) {
    EXPECT_NE(r.err.find("unknown GL back end 'nonsense' (from FRICTIONLAB_GL); valid back ends: "
                         "osmesa, egl, auto"),
              std::string::npos)
        << r.err;
  }
  // The command line's --gl wins over the variable, and is named when it is wrong.
  r = lab("run " + kRig + " --duration 0.2s --still x.png --gl glfw", env);
  EXPECT_EQ(r.status, 2);
  if (render::kHasRender) {
    EXPECT_NE(r.err.find("unknown GL back end 'glfw' (from --gl)"), std::string::npos) << r.err;
  }
}

TEST(RigVideo, ARunWithoutFramesOpensNoMesh) {
  // An asset folder with the part index and the paper's table but no mesh file.
  const fs::path assets = fresh_dir("assets-without-meshes");
  fs::create_directories(assets / "lego");
  fs::copy_file(fs::path(FRICTIONLAB_TEST_ASSET_DIR) / "lego" / "parts.yaml",
                assets / "lego" / "parts.yaml");
  fs::copy(fs::path(FRICTIONLAB_TEST_ASSET_DIR) / "paper", assets / "paper",
           fs::copy_options::recursive);
  const std::string with = "--assets " + assets.string() + " ";
  // The paper's rig (frame, gears, blocks) runs without its meshes ...
  auto r = lab(with + "run " + kRig + " --duration 0.2s --json");
  EXPECT_EQ(r.status, 0) << r.err;
  if (!kDraws) return;
  // ... and drawing it needs them: the missing file is named.
  r = lab(with + "run " + kRig + " --duration 0.2s --size 160x90 --still " +
          (assets / "x.png").string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(".glb"), std::string::npos) << r.err;
  // A scene without LEGO parts draws without any mesh.
  r = lab(with + "run " + kScenes + "minimal.yaml --duration 0.2s --size 160x90 --still " +
          (assets / "minimal.png").string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(assets / "minimal.png"));
}

// The shared objects the dynamic loader initialised in a run (LD_DEBUG=libs: "calling init: ...").
std::string loaded_objects(const std::string& args) {
  const auto r = lab(args, "LD_DEBUG=libs");
  EXPECT_EQ(r.status, 0) << args << "\n" << r.err;
  std::string out;
  std::size_t at = 0;
  while ((at = r.err.find("calling init: ", at)) != std::string::npos) {
    const std::size_t end = r.err.find('\n', at);
    out += r.err.substr(at + 14, end - at - 14) + "\n";
    at = end;
  }
  return out;
}

TEST(RigVideo, ARunWithoutFramesLoadsNoRenderer) {
  for (const std::string& args :
       {std::string("table"), "run " + kScenes + "minimal.yaml --duration 0.2s",
        "run " + kRig + " --duration 0.2s"}) {
    const std::string objects = loaded_objects(args);
    EXPECT_NE(objects.find("libyaml-cpp"), std::string::npos) << args << ":\n" << objects;
    for (const char* name :
         {"frictionlab-video", "frictionlab-decoder", "libOSMesa", "libEGL", "libLLVM",
          "libavcodec", "libavformat", "libavfilter", "libswscale", "libassimp", "libpng"})
      EXPECT_EQ(objects.find(name), std::string::npos) << args << " loaded " << name;
  }
  if (!kDraws) return;
  // A still loads the module, and the module the back end.
  const fs::path dir = fresh_dir("loads");
  const std::string objects = loaded_objects("run " + kScenes + "minimal.yaml --duration 0.1s " +
                                             "--size 160x90 --still " + (dir / "x.png").string());
  EXPECT_NE(objects.find("frictionlab-video.so"), std::string::npos) << objects;
  if (render::kHasOsmesa) {
    EXPECT_NE(objects.find("libOSMesa"), std::string::npos) << objects;
  }
  if (render::kHasEgl) {
    EXPECT_NE(objects.find("libEGL"), std::string::npos) << objects;
  }
}

TEST(RigVideo, AMissingOrForeignVideoModuleIsNamedWithStatusTwo) {
  const std::string still =
      " --duration 0.1s --size 160x90 --still " + (fresh_dir("module") / "x.png").string();
  struct Case {
    std::string module;
    std::string message;
  };
  for (const Case& c : {
           Case{"/nonexistent/frictionlab-video.so",
                "video module /nonexistent/frictionlab-video.so (from FRICTIONLAB_VIDEO_MODULE), "
                "which does not exist"},
           Case{kRig, "cannot be loaded"},
           Case{"/lib/x86_64-linux-gnu/libm.so.6", "is not a frictionlab video module"},
       }) {
    const auto r =
        lab("run " + kScenes + "minimal.yaml" + still, "FRICTIONLAB_VIDEO_MODULE=" + c.module);
    EXPECT_EQ(r.status, 2) << c.module << "\n" << r.err;
    // A build without rendering never looks for the module: it says what it lacks.
    EXPECT_NE(r.err.find(render::kHasRender ? c.message : "OSMesa"), std::string::npos)
        << c.module << "\n"
        << r.err;
  }
}

TEST(RigVideo, MissingComponentsAndBadOptionsExitWithStatusTwo) {
  const fs::path dir = fresh_dir("bad");
  const std::string video = " --video " + (dir / "x.mp4").string();
  auto r = lab("run " + kRig + " --duration 0.2s" + video);
  if (!kDraws) {
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("OSMesa"), std::string::npos) << r.err;
  } else if (!render::kHasVideo) {
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("libav"), std::string::npos) << r.err;
    // Frames still work without libav.
    r = lab("run " + kRig + " --duration 0.1s --size 160x90 --frames " + (dir / "f").string());
    EXPECT_EQ(r.status, 0) << r.err;
  } else {
    EXPECT_EQ(r.status, 0) << r.err;
  }
  struct Case {
    std::string args;
    std::string message;
  };
  for (const Case& c : {
           Case{"--size 641x360", "--size: error: H.264 in yuv420p needs an even width"},
           Case{"--size huge", "--size: error: expected WIDTHxHEIGHT"},
           Case{"--camera side", "--camera: error: expected a camera preset"},
           Case{"--fps 0", "--fps: error: expected 1 to 240 frames per second"},
           Case{"--slow-motion 0", "--slow-motion: error: expected a slow-motion factor"},
       }) {
    r = lab("run " + kRig + " --duration 0.1s " + c.args + video);
    EXPECT_EQ(r.status, 2) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
  }
}

}  // namespace
}  // namespace fl
