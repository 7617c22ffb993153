// The teaching overlay's colours, shared by its panels (rig_overlay, force_overlay,
// motion_strip, phase_portrait): the translucent panel, the text, the grid, and the Hall plot's
// pulse green that the motion strip's turning points repeat.
#pragma once

#include "render/mesh_data.hpp"

namespace fl::render::palette {

inline constexpr Color kPanel{0.05f, 0.07f, 0.10f, 0.74f};
inline constexpr Color kWhite{1.0f, 1.0f, 1.0f, 1.0f};
inline constexpr Color kSoft{0.80f, 0.85f, 0.92f, 1.0f};  // labels, axes, secondary text
inline constexpr Color kGrid{1.0f, 1.0f, 1.0f, 0.18f};
inline constexpr Color kPulse{0.35f, 0.92f, 0.45f, 1.0f};  // a timed pulse, a turning point
inline constexpr Color kTheory{0.45f, 0.85f, 1.0f, 0.9f};  // the thick-plate theory, dashed

}  // namespace fl::render::palette
