#include "tracking/plate_tracker.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace fl {
namespace {

constexpr double kLeastChangeGrey = 16.0;  // a pixel's two states differ by at least this much
constexpr double kNoisesOfChange = 8.0;    // and by this many times the video's noise
constexpr double kMostMisfit = 0.25;       // of a pixel's coverage to a step in the shared motion
constexpr std::size_t kLeastFollowed = 8;  // pixels for a track
constexpr int kPowerIterations = 60;
constexpr int kLongestBaseline = 8;  // pixels, for the growth of the covered area

// The video's noise in grey levels: the spread of frame-to-frame changes of pixels that do not
// move (the median change, which most pixels show), as a standard deviation.
double noise_of(const std::vector<GrayFrame>& frames, const std::vector<std::size_t>& region) {
  std::array<std::size_t, 256> changes{};
  std::size_t count = 0;
  for (std::size_t k = 1; k < std::min<std::size_t>(frames.size(), 31); ++k)
    for (std::size_t p : region) {
      ++changes[static_cast<std::size_t>(
          std::abs(static_cast<int>(frames[k].levels[p]) - frames[k - 1].levels[p]))];
      ++count;
    }
  std::size_t seen = 0;
  std::size_t median = 0;
  while (median < 255 && 2 * (seen + changes[median]) < count) seen += changes[median++];
  // The change of two independent samples has sqrt(2) times their spread; a median of 0 (a clean
  // or heavily compressed video) counts as half a level.
  return 1.4826 * std::max(0.5, static_cast<double>(median)) / std::numbers::sqrt2;
}

// A pixel's grey level at a percentile of its frames (nearest rank).
float percentile(std::vector<std::uint8_t>& values, double fraction) {
  const auto at = static_cast<std::ptrdiff_t>(std::lround(fraction * (values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + at, values.end());
  return values[static_cast<std::size_t>(at)];
}

// Patches of neighbouring pixels (8 neighbours) of a mask on a width x height grid: each marked
// pixel's patch number, -1 for the others.
std::vector<int> patches_of(const std::vector<std::uint8_t>& mask, int width, int height,
                            int* count) {
  std::vector<int> patch(mask.size(), -1);
  std::vector<std::size_t> stack;
  *count = 0;
  for (std::size_t start = 0; start < mask.size(); ++start) {
    if (!mask[start] || patch[start] >= 0) continue;
    patch[start] = *count;
    stack.push_back(start);
    while (!stack.empty()) {
      const std::size_t p = stack.back();
      stack.pop_back();
      const int x = static_cast<int>(p % static_cast<std::size_t>(width));
      const int y = static_cast<int>(p / static_cast<std::size_t>(width));
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx;
          const int ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
          const std::size_t n = static_cast<std::size_t>(ny) * width + nx;
          if (mask[n] && patch[n] < 0) {
            patch[n] = *count;
            stack.push_back(n);
          }
        }
    }
    ++*count;
  }
  return patch;
}

// The pixels whose grey changes enough to be an edge's: each one's two states and its coverage
// over the frames (the fraction of the way from one state to the other, from its mean).
struct Changing {
  std::vector<std::size_t> pixels;
  std::vector<float> low;
  std::vector<float> span;
  std::vector<std::vector<float>> cover;
  double largest = 0.0;  // the largest change of any pixel [grey levels]

  // Pixel i's coverage in frame k, 0 to 1, turned over for sense -1.
  double state(const std::vector<GrayFrame>& frames, std::size_t i, std::size_t k,
               int sense) const {
    const auto e = static_cast<double>(
        std::clamp((frames[k].levels[pixels[i]] - low[i]) / span[i], 0.0f, 1.0f));
    return sense > 0 ? e : 1.0 - e;
  }
};

Changing changing_pixels(const std::vector<GrayFrame>& frames,
                         const std::vector<std::size_t>& region, double least) {
  Changing out;
  std::vector<std::uint8_t> values(frames.size());
  for (std::size_t p : region) {
    for (std::size_t k = 0; k < frames.size(); ++k) values[k] = frames[k].levels[p];
    float lo = percentile(values, 0.02);
    float hi = percentile(values, 0.98);
    out.largest = std::max(out.largest, static_cast<double>(hi - lo));
    if (static_cast<double>(hi - lo) < least) continue;
    // Each state's grey is the median of the frames on its side of the middle: the percentiles
    // lie in the noise's tails, and a step between them would be less than a whole one.
    const auto middle = std::partition(values.begin(), values.end(),
                                       [&](std::uint8_t v) { return v < 0.5f * (lo + hi); });
    std::vector<std::uint8_t> darker(values.begin(), middle), lighter(middle, values.end());
    lo = percentile(darker, 0.5);
    hi = percentile(lighter, 0.5);
    std::vector<float> c(frames.size());
    double mean = 0.0;
    for (std::size_t k = 0; k < frames.size(); ++k) {
      c[k] = std::clamp((frames[k].levels[p] - lo) / (hi - lo), 0.0f, 1.0f);
      mean += static_cast<double>(c[k]);
    }
    mean /= static_cast<double>(frames.size());
    for (float& v : c) v -= static_cast<float>(mean);
    out.pixels.push_back(p);
    out.low.push_back(lo);
    out.span.push_back(hi - lo);
    out.cover.push_back(std::move(c));
  }
  return out;
}

// The motion the changing pixels share: the first principal component of their coverages over
// time, by power iteration from the series of the pixel that changes most.
std::vector<double> shared_motion(const Changing& changing, std::size_t frames) {
  std::size_t start = 0;
  double most = -1.0;
  for (std::size_t i = 0; i < changing.cover.size(); ++i) {
    double energy = 0.0;
    for (float v : changing.cover[i]) energy += static_cast<double>(v) * static_cast<double>(v);
    if (energy > most) {
      most = energy;
      start = i;
    }
  }
  std::vector<double> shared(changing.cover[start].begin(), changing.cover[start].end());
  std::vector<double> next(frames);
  for (int iteration = 0; iteration < kPowerIterations; ++iteration) {
    std::fill(next.begin(), next.end(), 0.0);
    for (const std::vector<float>& c : changing.cover) {
      double along = 0.0;
      for (std::size_t k = 0; k < frames; ++k) along += static_cast<double>(c[k]) * shared[k];
      for (std::size_t k = 0; k < frames; ++k) next[k] += along * static_cast<double>(c[k]);
    }
    double norm = 0.0;
    for (double v : next) norm += v * v;
    norm = std::sqrt(norm);
    if (norm == 0.0) break;
    for (std::size_t k = 0; k < frames; ++k) shared[k] = next[k] / norm;
  }
  return shared;
}

// The pixels that follow the plate (indices into Changing), marked on a frame's grid with the
// sense in which each changes.
struct Followed {
  std::vector<std::size_t> kept;
  std::vector<std::uint8_t> mask;
  std::vector<std::int8_t> sense;
};

// With the frames in order of the shared motion, a pixel an edge passes over is in one state up
// to some frame and in the other after it. Its misfit to the best such step (the coverage it
// would need changed) is a small part of what a step at the end would need; a pixel that changes
// for another reason (a roller's mark, light) fits no step.
Followed pixels_that_step(const std::vector<GrayFrame>& frames, const Changing& changing,
                          const std::vector<double>& shared) {
  const std::size_t count = frames.size();
  std::vector<std::size_t> order(count);
  for (std::size_t k = 0; k < count; ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return shared[a] < shared[b]; });
  Followed out;
  out.mask.assign(frames.front().levels.size(), 0);
  out.sense.assign(out.mask.size(), 0);
  std::vector<double> sorted(count);
  const auto n = static_cast<double>(count);
  for (std::size_t i = 0; i < changing.pixels.size(); ++i) {
    double total = 0.0;
    for (std::size_t k = 0; k < count; ++k) {
      sorted[k] = changing.state(frames, i, order[k], 1);
      total += sorted[k];
    }
    double below = 0.0, rising = 1e300, falling = 1e300;
    for (std::size_t k = 0; k <= count; ++k) {
      const auto at = static_cast<double>(k);
      rising = std::min(rising, 2.0 * below + n - at - total);  // off, then on
      falling = std::min(falling, at - 2.0 * below + total);    // on, then off
      if (k < count) below += sorted[k];
    }
    if (std::min(rising, falling) > kMostMisfit * std::min(total, n - total)) continue;
    out.kept.push_back(i);
    out.mask[changing.pixels[i]] = 1;
    out.sense[changing.pixels[i]] = rising <= falling ? 1 : -1;
  }
  return out;
}

// Near the ends of the swing the shared motion changes little, so noise orders those frames and
// the pixels the edges reach only there fit no step in its order. They are found from their
// neighbours instead: a pixel next to a followed one is one an edge reaches too when it is in the
// state it is rarely in only while that neighbour is in one of its states (the edge passes the
// neighbour first).
void grow_to_the_swings_ends(const std::vector<GrayFrame>& frames, const Changing& changing,
                             const std::array<int, 4>& box, Followed& followed) {
  const int width = frames.front().width;
  std::vector<std::ptrdiff_t> index_of(followed.mask.size(), -1);
  for (std::size_t i = 0; i < changing.pixels.size(); ++i)
    index_of[changing.pixels[i]] = static_cast<std::ptrdiff_t>(i);
  const auto count = static_cast<double>(frames.size());
  for (std::size_t next = 0; next < followed.kept.size(); ++next) {
    const std::size_t inner = followed.kept[next];
    const std::size_t p = changing.pixels[inner];
    const int x = static_cast<int>(p % static_cast<std::size_t>(width));
    const int y = static_cast<int>(p / static_cast<std::size_t>(width));
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if (nx < box[0] || ny < box[1] || nx >= box[0] + box[2] || ny >= box[1] + box[3]) continue;
        const std::size_t n = static_cast<std::size_t>(ny) * width + nx;
        if (followed.mask[n] || index_of[n] < 0) continue;
        const auto outer = static_cast<std::size_t>(index_of[n]);
        for (int s : {1, -1}) {
          double own = 0.0, beyond_on = 0.0, beyond_off = 0.0;
          for (std::size_t k = 0; k < frames.size(); ++k) {
            const double e = changing.state(frames, outer, k, s);
            const double inner_on = changing.state(frames, inner, k, followed.sense[p]);
            own += e;
            beyond_on += std::max(0.0, e - inner_on);
            beyond_off += std::max(0.0, e - (1.0 - inner_on));
          }
          if (own <= 0.0 || own >= 0.5 * count) continue;
          if (std::min(beyond_on, beyond_off) > kMostMisfit * own) break;
          followed.mask[n] = 1;
          followed.sense[n] = static_cast<std::int8_t>(beyond_on <= beyond_off ? s : -s);
          followed.kept.push_back(outer);
          break;
        }
      }
  }
}

// The line of the motion: the followed pixels' principal axis, pointing right (or down).
struct Line {
  double ux = 1.0, uy = 0.0;
  double along(std::size_t p, int width) const {
    return static_cast<double>(p % static_cast<std::size_t>(width)) * ux +
           static_cast<double>(p / static_cast<std::size_t>(width)) * uy;
  }
};

Line line_of(const std::vector<std::size_t>& pixels, int width) {
  const auto w = static_cast<std::size_t>(width);
  double mx = 0.0, my = 0.0;
  for (std::size_t p : pixels) {
    mx += static_cast<double>(p % w);
    my += static_cast<double>(p / w);
  }
  mx /= static_cast<double>(pixels.size());
  my /= static_cast<double>(pixels.size());
  double sxx = 0.0, syy = 0.0, sxy = 0.0;
  for (std::size_t p : pixels) {
    const double dx = static_cast<double>(p % w) - mx;
    const double dy = static_cast<double>(p / w) - my;
    sxx += dx * dx;
    syy += dy * dy;
    sxy += dx * dy;
  }
  const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  Line line{std::cos(angle), std::sin(angle)};
  if (line.ux < -1e-12 || (std::abs(line.ux) <= 1e-12 && line.uy < 0)) line = {-line.ux, -line.uy};
  return line;
}

// The patches of followed pixels (the plate's ends' strips, or one band when a plate's pattern
// joins them): how many, and how far they reach along the line.
struct Patches {
  int ends = 0;            // patches with a tenth of the largest's pixels or more
  double extent_px = 0.0;  // from the first of those to the last, along the line
};

Patches patches_along(const Followed& followed, const Changing& changing, const Line& line,
                      int width, int height) {
  int patch_count = 0;
  const std::vector<int> patch = patches_of(followed.mask, width, height, &patch_count);
  struct Patch {
    double least = 1e300, most = -1e300;
    std::size_t pixels = 0;
  };
  std::vector<Patch> patches(static_cast<std::size_t>(patch_count));
  for (std::size_t i : followed.kept) {
    const std::size_t p = changing.pixels[i];
    const double q = line.along(p, width);
    Patch& b = patches[static_cast<std::size_t>(patch[p])];
    b.least = std::min(b.least, q);
    b.most = std::max(b.most, q);
    ++b.pixels;
  }
  std::size_t largest = 0;
  for (const Patch& b : patches) largest = std::max(largest, b.pixels);
  Patches out;
  double first = 1e300, last = -1e300;
  for (const Patch& b : patches) {
    if (10 * b.pixels < largest) continue;
    ++out.ends;
    first = std::min(first, b.least);
    last = std::max(last, b.most + 1.0);
  }
  out.extent_px = last - first;
  return out;
}

// How much the covered area grows for each pixel the plate moves, from the pixels' own steps:
// with the frames in order of their covered area, each followed pixel turns on at some area, and
// the pixel k further along the line turns on k pixels of motion later. The median of those
// differences over k, over pairs of followed pixels, is the growth, whether each edge has its own
// strip or a plate's pattern joins many edges into one band (a pair across two edges is one of
// few).
double area_per_pixel_of_motion(const std::vector<GrayFrame>& frames, const Changing& changing,
                                const Followed& followed, const Line& line) {
  const std::size_t count = frames.size();
  const int width = frames.front().width;
  std::vector<double> area(count, 0.0);
  for (std::size_t i : followed.kept)
    for (std::size_t k = 0; k < count; ++k)
      area[k] += changing.state(frames, i, k, followed.sense[changing.pixels[i]]);
  std::vector<std::size_t> order(count);
  for (std::size_t k = 0; k < count; ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return area[a] < area[b]; });
  // Each pixel's step: the area midway between the frames either side of its best split.
  std::vector<double> step_at(followed.mask.size(), std::nan(""));
  const auto n = static_cast<double>(count);
  for (std::size_t i : followed.kept) {
    const std::size_t p = changing.pixels[i];
    double total = 0.0;
    for (std::size_t k = 0; k < count; ++k)
      total += changing.state(frames, i, k, followed.sense[p]);
    double below = 0.0, best = 1e300;
    std::size_t split = 0;
    for (std::size_t k = 0; k <= count; ++k) {
      const double misfit = 2.0 * below + n - static_cast<double>(k) - total;
      if (misfit < best) best = misfit, split = k;
      if (k < count) below += changing.state(frames, i, order[k], followed.sense[p]);
    }
    if (split > 0 && split < count)
      step_at[p] = 0.5 * (area[order[split - 1]] + area[order[split]]);
  }
  // Pixels up to kLongestBaseline apart along the line's main axis, every one between them
  // followed: a video's frames sample the swing at a few dozen phases when its period is close to
  // a whole number of frames, so the areas where pixels turn come in steps of about a pixel of
  // motion, and a longer baseline divides that step.
  const bool across = std::abs(line.ux) >= std::abs(line.uy);
  const int dx = across ? (line.ux >= 0 ? 1 : -1) : 0;
  const int dy = across ? 0 : (line.uy >= 0 ? 1 : -1);
  const double apart = across ? std::abs(line.ux) : std::abs(line.uy);
  std::vector<double> growth;
  for (std::size_t i : followed.kept) {
    const std::size_t p = changing.pixels[i];
    if (std::isnan(step_at[p])) continue;
    int x = static_cast<int>(p % static_cast<std::size_t>(width));
    int y = static_cast<int>(p / static_cast<std::size_t>(width));
    std::optional<std::size_t> far;
    int steps = 0;
    for (int k = 1; k <= kLongestBaseline; ++k) {
      x += dx, y += dy;
      if (x < 0 || y < 0 || x >= width || y >= frames.front().height) break;
      const std::size_t q = static_cast<std::size_t>(y) * width + x;
      if (std::isnan(step_at[q])) break;
      far = q, steps = k;
    }
    if (far) growth.push_back((step_at[*far] - step_at[p]) / (steps * apart));
  }
  if (growth.empty()) return std::nan("");
  std::nth_element(growth.begin(), growth.begin() + growth.size() / 2, growth.end());
  return growth[growth.size() / 2];
}

}  // namespace

PlateTracker::PlateTracker(TrackOptions options, double scale) : options_(std::move(options)) {
  if (options_.learn_frames < 10)
    throw std::invalid_argument("the tracker learns from 10 frames or more");
  track_.scale = scale;
}

void PlateTracker::add(const GrayFrame& frame) {
  if (!learned_ && learning_.empty()) {
    track_.first = frame;
    box_ = {0, 0, frame.width, frame.height};
    if (options_.roi) {
      const auto [x, y, w, h] = *options_.roi;
      const double s = track_.scale;
      box_ = {static_cast<int>(std::floor(x * s)), static_cast<int>(std::floor(y * s)),
              static_cast<int>(std::ceil(w * s)), static_cast<int>(std::ceil(h * s))};
      const int video_width = static_cast<int>(std::lround(frame.width / s));
      const int video_height = static_cast<int>(std::lround(frame.height / s));
      if (w < 2 || h < 2 || x < 0 || y < 0 || box_[0] + box_[2] > frame.width ||
          box_[1] + box_[3] > frame.height)
        throw std::invalid_argument(
            fmt::format("the region {},{},{},{} lies outside the video's {}x{} pixels (x, y of its "
                        "top-left corner, then its width and height)",
                        x, y, w, h, video_width, video_height));
    }
    track_.region = {static_cast<int>(std::lround(box_[0] / track_.scale)),
                     static_cast<int>(std::lround(box_[1] / track_.scale)),
                     static_cast<int>(std::lround(box_[2] / track_.scale)),
                     static_cast<int>(std::lround(box_[3] / track_.scale))};
  }
  if (frame.width != track_.first.width || frame.height != track_.first.height)
    throw NoTrack(fmt::format("the frames change size at t = {:.3f} s", frame.t_s));
  if (!learned_) {
    learning_.push_back(frame);
    if (learning_.size() >= static_cast<std::size_t>(options_.learn_frames)) learn();
    return;
  }
  track_.t_s.push_back(frame.t_s);
  track_.x.push_back(position(frame));
}

void PlateTracker::learn() {
  const std::size_t frames = learning_.size();
  const double seconds = frames > 1 ? learning_.back().t_s - learning_.front().t_s : 0.0;
  if (frames < 10)
    throw NoTrack(fmt::format("the video has {} frames; the tracker needs 10 or more", frames));
  const int width = track_.first.width;
  std::vector<std::size_t> region;
  for (int y = box_[1]; y < box_[1] + box_[3]; ++y)
    for (int x = box_[0]; x < box_[0] + box_[2]; ++x)
      region.push_back(static_cast<std::size_t>(y) * width + x);
  track_.noise_grey = noise_of(learning_, region);
  const double least = std::max(kLeastChangeGrey, kNoisesOfChange * track_.noise_grey);
  const Changing changing = changing_pixels(learning_, region, least);
  if (changing.pixels.size() < kLeastFollowed)
    throw NoTrack(fmt::format(
        "nothing moves in the video: over its first {} frames ({:.1f} s) {} "
        "pixel(s) change by {:.0f} grey levels or more (16, or 8 times the "
        "video's noise of {:.1f} if that is more), and the largest "
        "change is {:.0f} of 255; a swinging plate's edges change hundreds",
        frames, seconds, changing.pixels.size(), least, track_.noise_grey, changing.largest));

  Followed followed = pixels_that_step(learning_, changing, shared_motion(changing, frames));
  if (followed.kept.size() < kLeastFollowed)
    throw NoTrack(
        fmt::format("nothing moves back and forth in the video: {} pixels change, but "
                    "only {} follow one motion together (a plate's edges give dozens)",
                    changing.pixels.size(), followed.kept.size()));
  grow_to_the_swings_ends(learning_, changing, box_, followed);

  std::vector<std::size_t> followed_pixels;
  for (std::size_t i : followed.kept) followed_pixels.push_back(changing.pixels[i]);
  const Line line = line_of(followed_pixels, width);
  track_.direction_deg = -std::atan2(line.uy, line.ux) * 180.0 / std::numbers::pi;  // up: +
  const Patches patches = patches_along(followed, changing, line, width, track_.first.height);
  track_.edges = patches.ends;
  // The next pixel along the line turns later as the covered area grows, if it grows with the
  // motion along the line; if it turns earlier, every pixel's sense is turned over (the area
  // becomes what it did not cover, and the growth changes sign) so that the position grows along
  // the line.
  area_per_px_ = area_per_pixel_of_motion(learning_, changing, followed, line);
  if (area_per_px_ < 0.0) {
    for (std::int8_t& s : followed.sense) s = static_cast<std::int8_t>(-s);
    area_per_px_ = -area_per_px_;
  }
  if (!(area_per_px_ > 0.0))
    throw NoTrack(
        fmt::format("nothing moves along a line in the video: {} pixels change together, "
                    "but not as edges passing over them one after another",
                    followed.kept.size()));

  for (std::size_t i : followed.kept) {
    pixels_.push_back(changing.pixels[i]);
    low_.push_back(changing.low[i]);
    span_.push_back(changing.span[i]);
    sense_.push_back(followed.sense[changing.pixels[i]]);
  }
  track_.pixels_followed = static_cast<int>(pixels_.size());
  track_.followed = std::move(followed.mask);
  track_.frames_learned = static_cast<int>(frames);
  learned_ = true;
  // The positions of the frames learned from [frame pixels], taken from their mean as every
  // later one is. The followed region reaches from one end's furthest swing to the other's: its
  // extent less the swing is the plate's length, when that is longer than the swing (a region
  // around one end holds the swing alone).
  unit_per_frame_px_ = 1.0;
  mean_cover_ = 0.0;
  std::vector<double> raw;
  for (const GrayFrame& f : learning_) raw.push_back(position(f));
  for (double r : raw) mean_cover_ += r / static_cast<double>(raw.size());
  const auto [lowest, highest] = std::minmax_element(raw.begin(), raw.end());
  const double swing = *highest - *lowest;
  if (patches.extent_px - swing > swing)
    track_.plate_length_px = (patches.extent_px - swing) / track_.scale;
  set_unit();
  for (std::size_t k = 0; k < frames; ++k) {
    track_.t_s.push_back(learning_[k].t_s);
    track_.x.push_back((raw[k] - mean_cover_) * unit_per_frame_px_);
  }
  mean_cover_ *= area_per_px_;
  std::vector<GrayFrame>().swap(learning_);
}

void PlateTracker::set_unit() {
  if (options_.mm_per_px) {
    track_.mm_per_px = *options_.mm_per_px;
    track_.scale_from = "scale";
  } else if (options_.plate_length_mm) {
    if (!track_.plate_length_px)
      throw std::domain_error(
          "the plate's length gives the scale only with both its ends in view; the tracker "
          "follows one patch: give the scale (millimetres per pixel) instead");
    track_.mm_per_px = *options_.plate_length_mm / *track_.plate_length_px;
    track_.scale_from = "plate length";
  }
  track_.unit = track_.mm_per_px ? "mm" : "px";
  unit_per_frame_px_ = (track_.mm_per_px ? *track_.mm_per_px : 1.0) / track_.scale;
}

double PlateTracker::position(const GrayFrame& frame) const {
  double covered = 0.0;
  for (std::size_t j = 0; j < pixels_.size(); ++j) {
    // Not clamped to the two states: the noise about each averages out over the pixels (a
    // glitch is held to half a step beyond them).
    const float e = std::clamp((frame.levels[pixels_[j]] - low_[j]) / span_[j], -0.5f, 1.5f);
    covered += static_cast<double>(sense_[j] > 0 ? e : 1.0f - e);
  }
  return (covered - mean_cover_) / area_per_px_ * unit_per_frame_px_;
}

PlateTrack PlateTracker::finish() {
  if (!learned_) learn();
  return std::move(track_);
}

}  // namespace fl
