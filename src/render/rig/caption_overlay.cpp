#include "render/rig/caption_overlay.hpp"

#include <algorithm>
#include <limits>

#include "render/rig/rig_overlay.hpp"

namespace fl::render {
namespace {

const Color kCaptionBox{0.02f, 0.03f, 0.05f, 0.72f};
const Color kCaptionText{1.0f, 1.0f, 0.96f, 1.0f};

// At 640x360: the text's largest and smallest sizes, the widest line, the box's margins, and the
// gap above the Hall plot (whose top is 104 px above the frame's bottom).
constexpr float kLargest = 15.0f;
constexpr float kSmallest = 12.0f;
constexpr float kWidest = 520.0f;
constexpr float kPadX = 10.0f;
constexpr float kPadY = 5.0f;
constexpr float kLineStep = 1.25f;  // baseline to baseline, in text sizes
constexpr float kBottom = 112.0f;   // the box's bottom edge above the frame's bottom

constexpr std::string_view kEllipsis = "\xe2\x80\xa6";

bool continuation(char c) {
  return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}

// `text` without its last character (a whole UTF-8 sequence).
std::string_view drop_last(std::string_view text) {
  std::size_t end = text.size();
  while (end > 0 && continuation(text[end - 1])) --end;
  return text.substr(0, end > 0 ? end - 1 : 0);
}

// Appends `word` to `lines`, broken between characters where it is wider than `max_width`.
void add_long_word(std::string_view word, float max_width,
                   const std::function<float(std::string_view)>& width_of,
                   std::vector<std::string>* lines) {
  while (!word.empty()) {
    std::string_view piece = word;
    while (width_of(piece) > max_width) {
      const std::string_view shorter = drop_last(piece);
      if (shorter.empty()) break;  // one character wider than the line: it stands alone
      piece = shorter;
    }
    lines->emplace_back(piece);
    word.remove_prefix(piece.size());
  }
}

}  // namespace

std::optional<std::string> caption_at(std::span<const Caption> captions, double t) {
  constexpr double kSlack = 1e-9;  // s: frame times are sums of rounded intervals
  for (std::size_t i = 0; i < captions.size(); ++i) {
    const Caption& c = captions[i];
    const double end = c.until                   ? *c.until
                       : i + 1 < captions.size() ? captions[i + 1].at
                                                 : std::numeric_limits<double>::infinity();
    if (t + kSlack >= c.at && t + kSlack < end) return c.text;
  }
  return std::nullopt;
}

std::vector<std::string> wrap_text(std::string_view text, float max_width,
                                   const std::function<float(std::string_view)>& width_of) {
  std::vector<std::string> lines;
  while (!text.empty()) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    std::string_view paragraph = text.substr(0, end);
    text.remove_prefix(std::min(end + 1, text.size()));
    std::string line;
    while (!paragraph.empty()) {
      const std::size_t space = std::min(paragraph.find_first_of(" \t\r"), paragraph.size());
      const std::string_view word = paragraph.substr(0, space);
      paragraph.remove_prefix(std::min(space + 1, paragraph.size()));
      if (word.empty()) continue;
      const std::string joined = line.empty() ? std::string(word) : line + " " + std::string(word);
      if (width_of(joined) <= max_width) {
        line = joined;
        continue;
      }
      if (!line.empty()) lines.push_back(line);
      line.clear();
      if (width_of(word) <= max_width) {
        line = std::string(word);
      } else {
        add_long_word(word, max_width, width_of, &lines);
        line = lines.back();  // its last piece may take the next words
        lines.pop_back();
      }
    }
    if (!line.empty()) lines.push_back(line);
  }
  return lines;
}

FittedText fit_text(Overlay& o, std::string_view text, float max_width, float largest,
                    float smallest, float scale, std::size_t most_lines) {
  FittedText out;
  for (float size = largest;; size -= 1.0f) {
    out.pixel_size = size * scale;
    const auto width_of = [&](std::string_view t) {
      return o.measure_text(t, out.pixel_size).width;
    };
    out.lines = wrap_text(text, max_width, width_of);
    if (out.lines.size() <= most_lines || size <= smallest) {
      if (out.lines.size() > most_lines) {
        out.lines.resize(most_lines);
        std::string_view last = out.lines.back();
        while (!last.empty() && width_of(std::string(last) + std::string(kEllipsis)) > max_width)
          last = drop_last(last);
        while (!last.empty() && last.back() == ' ') last.remove_suffix(1);
        out.lines.back() = std::string(last) + std::string(kEllipsis);
      }
      return out;
    }
  }
}

CaptionLayout layout_caption(Overlay& o, int width, int height, std::string_view text) {
  CaptionLayout layout;
  const float s = overlay_scale(width, height);
  if (s < kSmallestOverlayScale) return layout;
  const float w = static_cast<float>(width);
  const float h = static_cast<float>(height);
  const float max_width = std::min(kWidest * s, w - 2.0f * (kPadX + 8.0f) * s);
  // The largest size (in steps of a pixel at 640x360) that keeps the text to three lines.
  FittedText fitted = fit_text(o, text, max_width, kLargest, kSmallest, s, kCaptionLines);
  layout.pixel_size = fitted.pixel_size;
  layout.lines = std::move(fitted.lines);
  if (layout.lines.empty()) return layout;  // nothing but spaces
  float widest = 0.0f;
  for (const std::string& line : layout.lines)
    widest = std::max(widest, o.measure_text(line, layout.pixel_size).width);
  const float step = kLineStep * layout.pixel_size;
  const float box_height =
      static_cast<float>(layout.lines.size() - 1) * step + layout.pixel_size + 2.0f * kPadY * s;
  const float box_width = widest + 2.0f * kPadX * s;
  layout.box = Rect{(w - box_width) / 2.0f, h - kBottom * s - box_height, box_width, box_height};
  return layout;
}

void draw_caption(Overlay& o, int width, int height, std::string_view text) {
  const CaptionLayout layout = layout_caption(o, width, height, text);
  if (layout.lines.empty()) return;
  const float s = overlay_scale(width, height);
  o.rect(layout.box, kCaptionBox);
  float y = layout.box.y + kPadY * s;
  for (const std::string& line : layout.lines) {
    o.text(line, Eigen::Vector2f(static_cast<float>(width) / 2.0f, y), layout.pixel_size,
           kCaptionText, TextAlign::kCenter);
    y += kLineStep * layout.pixel_size;
  }
}

}  // namespace fl::render
