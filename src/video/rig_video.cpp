// The video engine (video_module.hpp): the rig drawn from the scene and posed from each step, the
// teaching overlay over it, frames at the video's clock into the MP4 and PNG sinks. Linked into
// the video module (frictionlab-video.so) and into the tests that draw videos directly; never
// into the frictionlab executable.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "assets/mesh_library.hpp"
#include "assets/part_catalog.hpp"
#include "io/field_ref.hpp"
#include "io/missing_component.hpp"
#include "io/paper_table_yaml.hpp"
#include "lab/video/caption_values.hpp"
#include "lab/video/video_module.hpp"
#include "render/components.hpp"
#include "render/gl/gl_context.hpp"
#include "render/gl/renderer.hpp"
#include "render/rig/caption_overlay.hpp"
#include "render/rig/rig_camera.hpp"
#include "render/rig/rig_overlay.hpp"
#include "render/rig/rig_view.hpp"
#include "render/sinks/png.hpp"
#include "render/sinks/video.hpp"
#include "scene/theory_motion.hpp"

namespace fl {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Seconds of simulated time the Hall plot, the motion strip and the phase portrait span.
constexpr double kPlotSeconds = 2.5;

// Keeps what the plots show (and half a second more), dropping older points in blocks of a
// second or more; `time_of` gives a point's time [s].
template <typename Points, typename TimeOf>
void drop_unshown(Points& points, double now, TimeOf time_of) {
  const double keep_from = now - kPlotSeconds - 0.5;
  if (points.empty() || time_of(points.front()) >= keep_from - 1.0) return;
  points.erase(points.begin(), std::find_if(points.begin(), points.end(), [&](const auto& p) {
                 return time_of(p) >= keep_from;
               }));
}

// The rig's moving parts as a step left them.
render::RigPose pose_of(const VideoStep& step) {
  render::RigPose pose;
  pose.plate_x = step.plate_x;
  pose.plate_y = step.plate_y;
  pose.plate_z = step.plate_z;
  pose.pitch = step.pitch;
  pose.yaw = step.yaw;
  pose.shaft_angles = step.shaft_angles;
  pose.shaft_speeds = step.shaft_speeds;
  return pose;
}

int shadow_map_size(int height) {
  int size = 512;
  while (size < 2048 && size < 1.4 * height) size *= 2;
  return size;
}

// How the material is called in the paper's table ("LEGO blocks"), its look told from its
// friction where they differ (lab/video/caption_values.hpp).
std::string material_name(const CompiledRig& rig, const std::string& asset_dir) {
  return run_material_name(rig, load_paper_table(paper_table_path(asset_dir)));
}

// The engine's state is this file's alone (the module hands out only VideoEngine).
struct RigVideo final : public VideoEngine {
  RigVideo(std::shared_ptr<const CompiledRig> compiled, const VideoDesc& v, const VideoRequest& r);
  void observe(const VideoStep& step) override;
  VideoReport finish(const VideoEnding& ending) override;
  std::string note() const override { return backend_note; }

  std::shared_ptr<const CompiledRig> owned;  // the run's rig, for the model, the pose and the title
  const CompiledRig& rig;
  VideoRequest request;
  VideoDesc video;
  std::size_t run_frames = 0;
  std::size_t title_frames = 0;
  double frame_interval = 0.0;  // s of simulated time between frames
  double exposure = 0.0;        // s of simulated time a shutter stays open

  std::unique_ptr<render::GlContext> context;
  std::unique_ptr<render::Renderer> renderer;
  std::unique_ptr<render::RigView> view;
  render::Camera camera;                       // the preset, framed once; the orbit turns it
  std::unique_ptr<render::FrameSink> encoder;  // the video file (--video)
  std::unique_ptr<render::FrameSink> png;
  render::TitleCard title;
  std::string heading;
  std::string material;

  // The run so far.
  bool started = false;
  render::RigPose previous;
  double previous_t = 0.0;
  std::size_t next_frame = 0;   // of the run (title frames not counted)
  std::size_t video_frame = 0;  // every frame written, title included
  std::vector<render::HallPoint> hall;
  std::optional<std::array<double, 2>> hall_seen;  // lowest and highest ADC value so far
  std::vector<double> pulses;
  std::vector<double> learning_pulses;  // s, the pulses the estimator learned the signal from
  std::vector<std::array<double, 2>> discarded;  // s, the estimator's discarded periods
  render::EstimatorValues estimator;
  std::optional<double> motor_speed;
  double roller_speed = 0.0;
  std::string regime;  // the run's diagnosis so far
  bool has_sensor = false;
  // The forces of the step shown, to the video's one scale; arrows only where the camera sees
  // the contacts (not in the sensor's close-up).
  render::PlateForces forces;
  render::ForceScale force_scale;
  bool force_arrows = true;
  // x(t): the steps' (t, x), the theory from the first step, the estimator's turning points.
  std::vector<Eigen::Vector2d> motion;
  std::optional<HarmonicMotion> theory;
  std::string theory_label;
  double x_range = 0.0;
  std::vector<double> turning_points;
  // v against x (video.phase_portrait): the steps' (t, x, v), and the rollers' surface speed.
  std::vector<Eigen::Vector3d> phase;
  double slip_speed = 0.0;

  VideoReport report;
  std::string backend_note;  // why "auto" chose the back end it did, when it had to fall back

  void take_samples(const VideoStep& step);
  void take_estimator(const VideoStep& step);
  void take_motion(const VideoStep& step);
  void draw(const render::RigPose& pose, double t, double video_time, float title_opacity);
  // Hands the frame drawn to GL's read-back; the frames it has read go to the sinks, a couple
  // of frames behind the drawing where the back end reads through buffer objects.
  void emit();
  // Writes the oldest frame read back to the sinks.
  void write_taken();
  // Writes every frame still being read back.
  void drain();
  render::RigOverlayState overlay_state(double t) const;
};

RigVideo::RigVideo(std::shared_ptr<const CompiledRig> compiled, const VideoDesc& v,
                   const VideoRequest& r)
    : owned(std::move(compiled)), rig(*owned), request(r), video(v) {
  const auto start = Clock::now();
  run_frames = run_frame_count(video, rig.world.duration);
  title_frames = title_frame_count(video);
  frame_interval = 1.0 / (video.fps * video.slow_motion);
  // A quarter of the frame interval (a 90 degree shutter): at 1600 rpm and 30 fps the rollers'
  // mark smears over 80 degrees, a streak that still shows where it is.
  exposure = 0.25 * frame_interval;
  has_sensor = rig.sensor.has_value() && !rig.magnets.empty();
  try {
    // The encoder first: a build without libav says so before anything is drawn.
    if (!request.video.empty()) {
      render::VideoOptions options;
      options.path = request.video;
      options.fps = video.fps;
      encoder = render::make_video_sink(options);
    }
    render::GlContextOptions gl;
    gl.width = video.width;
    gl.height = video.height;
    gl.samples = 4;
    gl.backend = request.gl;
    gl.source = request.gl.empty() ? "" : field_ref("gl");
    context = render::make_gl_context(gl, &backend_note);
    report.backend = context->description();
    // The shadow map's texels about as fine as the frame's pixels over the rig: 512 at 360p,
    // 1024 at 720p, 2048 at 1080p (a 2048 map at 360p costs a third of the frame).
    render::RendererOptions look;
    look.shadow_map_size = shadow_map_size(video.height);
    renderer = std::make_unique<render::Renderer>(*context, look);

    // LEGO parts only when the scene names some: the part index and their meshes.
    std::optional<assets::PartCatalog> catalog;
    assets::MeshLibrary meshes;
    if (render::rig_uses_parts(rig))
      catalog = assets::load_part_catalog(assets::part_catalog_path(request.asset_dir));
    // The front camera looks through the near wall: it is cut away, so the rollers show.
    const bool cut_away = !video.placed && video.camera == "front";
    render::RigModel model =
        render::build_rig_model(rig, catalog ? &*catalog : nullptr, &meshes, cut_away);
    report.frame_triangles = model.stats.frame_triangles_drawn;
    report.frame_triangles_full = model.stats.frame_triangles_full;
    camera = render::rig_camera(model, video);
    force_scale = render::force_scale(camera, video.width, video.height, Eigen::Vector3f::Zero(),
                                      rig.rollers.spacing, rig.plate.mass * rig.gravity_normal);
    force_arrows = video.overlay && (video.placed || video.camera != "sensor");
    // A camera that stays put never sees the frame's back faces: leave them out.
    if (video.orbit == 0.0) render::cull_back_faces(model, model.tilt.inverse() * camera.position);
    forces.rig_to_world = model.tilt;
    view = std::make_unique<render::RigView>(*renderer, std::move(model));

    if (!request.frames.empty()) {
      render::PngSinkOptions options;
      options.directory = request.frames;
      options.replace_existing = true;
      // Encoded on a pool of threads beside the drawing (render/sinks/png.hpp): one per core with a
      // GPU drawing; one with a software rasteriser, which draws on every core itself (a pool of
      // two there only competed with it; bench/README.md's performance table).
      const std::string drawn_by = context->description();
      const bool software = drawn_by.find("llvmpipe") != std::string::npos ||
                            drawn_by.find("softpipe") != std::string::npos;
      png = render::make_png_pool_sink(options, software ? 1 : 0);
    }
  } catch (const render::RenderError& e) {
    throw VideoUnavailable(e.what());
  } catch (const MissingComponent& e) {
    throw VideoUnavailable(e.what());
  } catch (const std::invalid_argument& e) {
    throw VideoUnavailable(std::string("the rig cannot be drawn: ") + e.what());
  }
  material = material_name(rig, request.asset_dir);
  title = render::make_title_card(rig, material, video.slow_motion, video.fps, video.title_text);
  heading = render::rig_heading(rig, material);
  report.width = video.width;
  report.height = video.height;
  report.fps = video.fps;
  report.slow_motion = video.slow_motion;
  report.camera = video.placed ? "placed" : video.camera;
  report.setup_seconds = seconds_since(start);
}

void RigVideo::take_samples(const VideoStep& step) {
  for (const VideoHallSample& sample : step.new_samples) {
    const double adc = sample.adc;
    hall.push_back({sample.t, adc});
    if (!hall_seen) hall_seen = std::array<double, 2>{adc, adc};
    (*hall_seen)[0] = std::min((*hall_seen)[0], adc);
    (*hall_seen)[1] = std::max((*hall_seen)[1], adc);
  }
  drop_unshown(hall, step.t, [](const render::HallPoint& p) { return p.t; });
}

void RigVideo::take_estimator(const VideoStep& step) {
  if (step.motor_speed) motor_speed = step.motor_speed;
  roller_speed = step.roller_speed;
  regime = step.regime;
  if (!step.estimate) return;
  const VideoEstimate& r = *step.estimate;
  estimator.pulses = r.pulses;
  estimator.periods = r.periods_used;
  if (r.periods_used > 0) {
    estimator.period = r.period;
    estimator.period_std = r.period_std;
    estimator.mu_k = r.mu_k;
    estimator.mu_k_err = r.mu_k_err_worst;
  }
  pulses = r.pulse_times;
  learning_pulses = r.learning_pulse_times;
  estimator.learning_pulses = static_cast<int>(r.learning_pulse_times.size());
  estimator.signal_learned = r.signal_learned;
  estimator.geometry_known = r.geometry_known;
  estimator.provisional_periods = static_cast<int>(r.provisional_periods.size());
  estimator.provisional_period.reset();
  estimator.provisional_std.reset();
  if (!r.provisional_periods.empty()) {
    double sum = 0.0;
    for (const double p : r.provisional_periods) sum += p;
    const double mean = sum / static_cast<double>(r.provisional_periods.size());
    estimator.provisional_period = mean;
    if (r.provisional_periods.size() >= 2) {
      double sq = 0.0;
      for (const double p : r.provisional_periods) sq += (p - mean) * (p - mean);
      estimator.provisional_std =
          std::sqrt(sq / static_cast<double>(r.provisional_periods.size() - 1));
    }
  }
  estimator.periods_discarded = r.periods_discarded;
  discarded = r.discarded;
  turning_points = r.turning_points;
}

void RigVideo::take_motion(const VideoStep& step) {
  // The arrows start on the plate's near edge (the side the cameras look from, -y), where the
  // contact lines end.
  const float near_y = static_cast<float>(-0.5 * rig.plate_desc.width);
  for (std::size_t k = 0; k < 2; ++k) {
    const VideoContact& c = step.contacts[k];
    forces.rollers[k] = render::ContactForce{
        c.touching, c.normal_force, c.friction_force,
        Eigen::Vector3f(static_cast<float>(c.point_x), near_y, static_cast<float>(c.point_z))};
  }
  forces.centre =
      Eigen::Vector3f(static_cast<float>(step.plate_x), near_y, static_cast<float>(step.plate_z));
  if (motion.empty()) {
    // The theory starts where the run does.
    theory = theory_motion(rig, step.plate_x, step.plate_vx);
    theory_label =
        theory && rig.period_thick
            ? fmt::format("theory: thick plate, \xce\xbc\xe2\x82\x96 = {:.3g}, T = {:.4f} s",
                          rig.friction.mu_k, *rig.period_thick)
            : std::string("no theory: the rollers do not restore the plate");
    x_range = std::max({1e-3, 1.15 * std::fabs(step.plate_x), 1.15 * rig.amplitude_initial});
  }
  motion.emplace_back(step.t, step.plate_x);
  if (video.phase_portrait) {
    phase.emplace_back(step.t, step.plate_x, step.plate_vx);
    slip_speed = std::fabs(step.roller_speed) * rig.rollers.radius;
  }
  const auto time_of = [](const auto& p) { return p.x(); };
  drop_unshown(motion, step.t, time_of);
  drop_unshown(phase, step.t, time_of);
}

render::RigOverlayState RigVideo::overlay_state(double t) const {
  render::RigOverlayState o;
  o.heading = heading;
  o.t = t;
  o.slow_motion = video.slow_motion;
  o.motor_speed = motor_speed;
  o.roller_speed = roller_speed;
  o.hall = hall;
  o.hall_window = kPlotSeconds;
  if (hall_seen) {
    // The range seen so far, padded, at least 40 counts tall.
    const double mid = 0.5 * ((*hall_seen)[0] + (*hall_seen)[1]);
    const double half = std::max(20.0, 0.56 * ((*hall_seen)[1] - (*hall_seen)[0]));
    o.hall_range = std::array<double, 2>{mid - half, mid + half};
  }
  o.pulses = pulses;
  o.learning_pulses = learning_pulses;
  o.discarded = discarded;
  o.has_sensor = has_sensor;
  o.estimator = estimator;
  o.material = material;
  o.paper_period = rig.friction_source.paper_period;
  o.paper_mu_k = rig.friction_source.paper_mu_k;
  o.regime = regime;
  o.forces = forces;
  o.force_scale = force_scale;
  render::MotionStripState m;
  m.t = t;
  m.window = kPlotSeconds;
  m.simulated = motion;
  m.theory = theory;
  m.theory_label = theory_label;
  m.turning_points = turning_points;
  m.x_range = x_range;
  o.motion = m;
  if (video.phase_portrait) {
    render::PhasePortraitState p;
    p.t = t;
    p.window = kPlotSeconds;
    p.simulated = phase;
    p.theory = theory;
    p.slip_speed = slip_speed;
    p.x_range = x_range;
    o.phase = p;
  }
  return o;
}

void RigVideo::draw(const render::RigPose& pose, double t, double video_time, float title_opacity) {
  renderer->begin_frame(render::orbit_camera(camera, video.orbit * video_time),
                        render::rig_light());
  view->draw(pose, exposure);
  const float scale = render::overlay_scale(video.width, video.height);
  if (force_arrows && scale >= render::kSmallestOverlayScale)
    render::draw_force_arrows(
        renderer->overlay(), scale,
        render::force_arrows(render::orbit_camera(camera, video.orbit * video_time), video.width,
                             video.height, forces, force_scale));
  if (!video.overlay) return;
  render::draw_rig_overlay(renderer->overlay(), video.width, video.height, overlay_state(t));
  if (const auto caption = render::caption_at(video.captions, t))
    render::draw_caption(renderer->overlay(), video.width, video.height, *caption);
  if (title_opacity > 0.0f)
    render::draw_title_card(renderer->overlay(), video.width, video.height, title, title_opacity);
}

void RigVideo::emit() {
  renderer->submit_frame();
  report.triangles = renderer->last_frame_stats().triangles;
  ++video_frame;
  const render::GlContext& gl = renderer->context();
  while (gl.queued_frames() > gl.frames_behind()) write_taken();
}

void RigVideo::write_taken() {
  const render::ImageView frame = renderer->context().take_frame();
  if (encoder) encoder->write(frame);
  if (png) png->write(frame);
}

void RigVideo::drain() {
  while (renderer->context().queued_frames() > 0) write_taken();
}

void RigVideo::observe(const VideoStep& step) {
  const auto start = Clock::now();
  take_samples(step);
  take_estimator(step);
  take_motion(step);
  const render::RigPose current = pose_of(step);
  const bool sinks = encoder || png;
  if (!started) {
    started = true;
    previous = current;
    previous_t = step.t;
    // The title card: the rig at rest, the card fading out over its last 0.4 s.
    for (std::size_t i = 0; sinks && i < title_frames; ++i) {
      const double video_time = static_cast<double>(i) / video.fps;
      const double left = kTitleSeconds - video_time;
      draw(current, step.t, video_time, static_cast<float>(std::clamp(left / 0.4, 0.0, 1.0)));
      emit();
    }
  }
  // Every frame whose instant this step has reached, interpolated between the two steps.
  while (sinks && next_frame < run_frames) {
    const double t = static_cast<double>(next_frame) * frame_interval;
    if (t > step.t + 1e-9) break;
    const double span = step.t - previous_t;
    const double f = span > 0.0 ? std::clamp((t - previous_t) / span, 0.0, 1.0) : 1.0;
    const double video_time = static_cast<double>(video_frame) / video.fps;
    draw(render::interpolate(previous, current, f), t, video_time, 0.0f);
    emit();
    ++next_frame;
  }
  previous = current;
  previous_t = step.t;
  report.render_seconds += seconds_since(start);
}

VideoReport RigVideo::finish(const VideoEnding& ending) {
  const std::string stopped =
      ending.stopped_by.empty()
          ? std::string()
          : fmt::format("stopped at t = {:.3f} s: {}", ending.stopped_at, ending.stopped_by);
  const std::size_t before_ending = video_frame;
  if (started && (encoder || png)) {
    // A run a guard stopped: its last frame held, with a banner saying why.
    for (std::size_t i = 0; !stopped.empty() && i < guard_banner_frame_count(video); ++i) {
      draw(previous, previous_t, static_cast<double>(video_frame) / video.fps, 0.0f);
      render::draw_guard_banner(renderer->overlay(), video.width, video.height, stopped);
      emit();
    }
    // The end card fades in over the last frame in 0.4 s.
    const std::size_t end_frames = end_card_frame_count(video);
    if (end_frames > 0) {
      const render::TitleCard card =
          render::make_end_card(overlay_state(previous_t), theory_label, stopped);
      for (std::size_t i = 0; i < end_frames; ++i) {
        const double shown = static_cast<double>(i) / video.fps;
        draw(previous, previous_t, static_cast<double>(video_frame) / video.fps, 0.0f);
        render::draw_title_card(renderer->overlay(), video.width, video.height, card,
                                static_cast<float>(std::clamp(shown / 0.4, 0.0, 1.0)));
        emit();
      }
    }
  }
  report.ending_frames = video_frame - before_ending;
  drain();
  if (!request.still.empty() && started) {
    // The still turns with the orbit as the frame after the video's last would, whether or not
    // a video is written: a still alone counts the frames the video would have had.
    std::size_t frames_before = video_frame;
    if (!encoder && !png) {
      // The frames observe() draws: those whose instant is at most the last step's (+ 1 ns).
      const auto reached =
          static_cast<std::size_t>(std::floor((previous_t + 1e-9) / frame_interval));
      frames_before = title_frames + std::min(run_frames, reached + 1) +
                      (stopped.empty() ? 0 : guard_banner_frame_count(video)) +
                      end_card_frame_count(video);
    }
    draw(previous, previous_t, static_cast<double>(frames_before) / video.fps, 0.0f);
    if (!stopped.empty())
      render::draw_guard_banner(renderer->overlay(), video.width, video.height, stopped);
    render::write_png(request.still, renderer->end_frame());
    report.triangles = renderer->last_frame_stats().triangles;
  }
  const auto start = Clock::now();
  if (encoder) encoder->finish();
  if (png) png->finish();
  report.finish_seconds = seconds_since(start);
  report.frames = video_frame;
  report.title_frames = std::min(title_frames, video_frame);
  return report;
}

}  // namespace

std::unique_ptr<VideoEngine> make_video_engine(std::shared_ptr<const CompiledRig> rig,
                                               const VideoDesc& video,
                                               const VideoRequest& request) {
  return std::make_unique<RigVideo>(std::move(rig), video, request);
}

}  // namespace fl
