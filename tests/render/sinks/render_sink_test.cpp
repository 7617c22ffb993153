// Frame sinks: PNG frames with exactly the expected names that read back to the same pixels,
// an MP4 that ffprobe reports as H.264, yuv420p, N frames, N/30 s; WebM (VP9) and GIF likewise by
// the file's extension.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "render/sinks/png.hpp"
#include "render/sinks/video.hpp"
#include "render_test_support.hpp"
#include "support/run_command.hpp"

namespace fl::render {
namespace {

// A frame with a pattern that moves with `index` and no two neighbours alike.
Image test_frame(int width, int height, int index) {
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.row(y) + 4 * x;
      p[0] = static_cast<std::uint8_t>(x * 3 + index * 7);
      p[1] = static_cast<std::uint8_t>(y * 5);
      p[2] = static_cast<std::uint8_t>((x ^ y) + index);
      p[3] = 255;
    }
  }
  return image;
}

std::set<std::string> file_names(const std::filesystem::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    names.insert(entry.path().filename().string());
  return names;
}

TEST(RenderPngSink, WritesExactlyTheNumberedFilesAndTheyReadBack) {
  FL_REQUIRE_RENDER();
  const auto dir = fl::test::render_output_dir("png_sink");
  PngSinkOptions options;
  options.directory = dir.string();
  auto sink = make_png_sink(options);
  for (int i = 0; i < 3; ++i) sink->write(test_frame(37, 21, i).view());
  sink->finish();
  EXPECT_EQ(sink->frame_count(), 3u);
  EXPECT_EQ(file_names(dir),
            (std::set<std::string>{"frame_000000.png", "frame_000001.png", "frame_000002.png"}));
  for (int i = 0; i < 3; ++i) {
    const Image back = read_png((dir / png_frame_name(options, i)).string());
    const Image sent = test_frame(37, 21, i);
    ASSERT_EQ(back.width, 37);
    ASSERT_EQ(back.height, 21);
    EXPECT_EQ(back.rgba, sent.rgba) << "frame " << i;
  }
}

TEST(RenderPngSink, RefusesAFolderWithFramesOfAnEarlierRunUnlessToldToReplaceThem) {
  FL_REQUIRE_RENDER();
  const auto dir = fl::test::render_output_dir("png_sink_old");
  PngSinkOptions options;
  options.directory = dir.string();
  {
    auto sink = make_png_sink(options);
    for (int i = 0; i < 5; ++i) sink->write(test_frame(8, 8, i).view());
    sink->finish();
  }
  std::filesystem::create_directories(dir / "keep");
  { std::ofstream(dir / "notes.txt") << "not a frame"; }
  EXPECT_THROW(make_png_sink(options), RenderError);
  options.replace_existing = true;
  auto sink = make_png_sink(options);
  sink->write(test_frame(8, 8, 0).view());
  sink->finish();
  EXPECT_EQ(file_names(dir), (std::set<std::string>{"frame_000000.png", "keep", "notes.txt"}));
}

TEST(RenderPngSink, ReadingAFileThatIsNotAPngNamesIt) {
  FL_REQUIRE_RENDER();
  const auto dir = fl::test::render_output_dir("png_bad");
  { std::ofstream(dir / "x.png") << "hello"; }
  try {
    read_png((dir / "x.png").string());
    FAIL();
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("x.png"), std::string::npos) << e.what();
  }
}

std::string probe(const std::string& file, const std::string& entries) {
  const auto r = fl::test::run_command(
      "ffprobe -v error -count_frames -select_streams v:0 "
      "-show_entries " +
      entries + " -of default=noprint_wrappers=1 '" + file + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  return r.out;
}

class RenderMp4 : public ::testing::TestWithParam<int> {};

TEST_P(RenderMp4, FfprobeSeesH264Yuv420pAllFramesAndTheExactDuration) {
  FL_REQUIRE_VIDEO();
  if (fl::test::run_command("ffprobe -version").status != 0)
    GTEST_SKIP() << "ffprobe is not installed (apt-get install ffmpeg)";
  const int frames = GetParam();
  const auto dir = fl::test::render_output_dir("mp4_" + std::to_string(frames));
  const std::string file = (dir / "test.mp4").string();
  VideoOptions options;
  options.path = file;
  options.fps = 30;
  auto sink = make_mp4_sink(options);
  for (int i = 0; i < frames; ++i) sink->write(test_frame(160, 90, i).view());
  sink->finish();
  EXPECT_EQ(sink->frame_count(), static_cast<std::size_t>(frames));
  EXPECT_EQ(file_names(dir), std::set<std::string>{"test.mp4"});  // no .part left behind

  const std::string stream =
      probe(file,
            "stream=codec_name,pix_fmt,nb_read_frames,avg_frame_rate,color_space,color_primaries,"
            "color_transfer,duration");
  EXPECT_NE(stream.find("codec_name=h264"), std::string::npos) << stream;
  EXPECT_NE(stream.find("pix_fmt=yuv420p"), std::string::npos) << stream;
  EXPECT_NE(stream.find("nb_read_frames=" + std::to_string(frames) + "\n"), std::string::npos)
      << stream;
  EXPECT_NE(stream.find("avg_frame_rate=30/1"), std::string::npos) << stream;
  EXPECT_NE(stream.find("color_space=bt709"), std::string::npos) << stream;
  EXPECT_NE(stream.find("color_primaries=bt709"), std::string::npos) << stream;
  EXPECT_NE(stream.find("color_transfer=bt709"), std::string::npos) << stream;
  const std::string format = probe(file, "format=duration");
  const double expected = frames / 30.0;
  const auto at = format.find("duration=");
  ASSERT_NE(at, std::string::npos) << format;
  EXPECT_NEAR(std::stod(format.substr(at + 9)), expected, 1e-6) << format;
  const auto stream_at = stream.find("duration=");
  ASSERT_NE(stream_at, std::string::npos) << stream;
  EXPECT_NEAR(std::stod(stream.substr(stream_at + 9)), expected, 1e-6) << stream;
}

INSTANTIATE_TEST_SUITE_P(Frames, RenderMp4, ::testing::Values(1, 45, 150),
                         [](const auto& param_info) {
                           return std::to_string(param_info.param) + "frames";
                         });

TEST(RenderMp4Errors, AnOddSizeAndAnUnfinishedVideoFailCleanly) {
  FL_REQUIRE_VIDEO();
  const auto dir = fl::test::render_output_dir("mp4_errors");
  VideoOptions options;
  options.path = (dir / "odd.mp4").string();
  options.queue_frames = 0;
  {
    auto sink = make_mp4_sink(options);
    EXPECT_THROW(sink->write(test_frame(161, 90, 0).view()), RenderError);
  }
  options.path = (dir / "abandoned.mp4").string();
  {
    auto sink = make_mp4_sink(options);
    sink->write(test_frame(160, 90, 0).view());
  }  // destroyed without finish(): nothing left behind
  EXPECT_TRUE(file_names(dir).empty());
  options.preset = "warp-speed";
  auto sink = make_mp4_sink(options);
  EXPECT_THROW(sink->write(test_frame(160, 90, 0).view()), RenderError);
}

// The sink the file's extension picks: WebM (VP9) and GIF, each frame counted by ffprobe, the
// duration exact, the size kept.
struct FormatCase {
  std::string extension;
  std::string codec;
  int frames;
  int fps;
};

class RenderVideoFormat : public ::testing::TestWithParam<FormatCase> {};

TEST_P(RenderVideoFormat, FfprobeSeesTheCodecAllFramesTheSizeAndTheDuration) {
  FL_REQUIRE_VIDEO();
  if (fl::test::run_command("ffprobe -version").status != 0)
    GTEST_SKIP() << "ffprobe is not installed (apt-get install ffmpeg)";
  const FormatCase c = GetParam();
  const auto dir = fl::test::render_output_dir("format_" + c.extension);
  const std::string file = (dir / ("test." + c.extension)).string();
  VideoOptions options;
  options.path = file;
  options.fps = c.fps;
  auto sink = make_video_sink(options);
  for (int i = 0; i < c.frames; ++i) sink->write(test_frame(160, 90, i).view());
  sink->finish();
  EXPECT_EQ(sink->frame_count(), static_cast<std::size_t>(c.frames));
  EXPECT_EQ(file_names(dir), std::set<std::string>{"test." + c.extension});
  const std::string stream = probe(file, "stream=codec_name,nb_read_frames,width,height");
  EXPECT_NE(stream.find("codec_name=" + c.codec + "\n"), std::string::npos) << stream;
  EXPECT_NE(stream.find("nb_read_frames=" + std::to_string(c.frames) + "\n"), std::string::npos)
      << stream;
  EXPECT_NE(stream.find("width=160\n"), std::string::npos) << stream;
  EXPECT_NE(stream.find("height=90\n"), std::string::npos) << stream;
  const std::string format = probe(file, "format=duration");
  const auto at = format.find("duration=");
  ASSERT_NE(at, std::string::npos) << format;
  // WebM counts time in milliseconds and a GIF in hundredths of a second: at 10 and 25 fps
  // both hold every frame's start exactly.
  EXPECT_NEAR(std::stod(format.substr(at + 9)), static_cast<double>(c.frames) / c.fps, 1e-6)
      << format;
}

INSTANTIATE_TEST_SUITE_P(
    Formats, RenderVideoFormat,
    ::testing::Values(FormatCase{"webm", "vp9", 45, 25}, FormatCase{"gif", "gif", 30, 10},
                      FormatCase{"GIF", "gif", 1, 10}, FormatCase{"mp4", "h264", 12, 30}),
    [](const auto& param_info) {
      return param_info.param.extension + "_" + std::to_string(param_info.param.frames);
    });

TEST(RenderVideoFormatErrors, AnUnknownExtensionAndAnAbandonedGifLeaveNothing) {
  FL_REQUIRE_VIDEO();
  const auto dir = fl::test::render_output_dir("format_errors");
  VideoOptions options;
  options.path = (dir / "x.avi").string();
  try {
    make_video_sink(options);
    FAIL() << "an .avi was accepted";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find(".mp4, .gif or .webm"), std::string::npos) << e.what();
  }
  options.path = (dir / "abandoned.gif").string();
  options.queue_frames = 0;
  {
    auto sink = make_video_sink(options);
    sink->write(test_frame(160, 90, 0).view());
    sink->write(test_frame(160, 90, 1).view());
  }  // destroyed without finish(): nothing left behind
  options.path = (dir / "abandoned.webm").string();
  {
    auto sink = make_video_sink(options);
    sink->write(test_frame(160, 90, 0).view());
  }
  EXPECT_TRUE(file_names(dir).empty());
  // A GIF's delays are whole hundredths of a second: past 50 fps it cannot keep the rate.
  options.path = (dir / "fast.gif").string();
  options.fps = 60;
  EXPECT_THROW(make_video_sink(options), RenderError);
}

}  // namespace
}  // namespace fl::render
