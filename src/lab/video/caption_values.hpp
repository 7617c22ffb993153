// Narration that cannot lie: a caption may name the run's own values ({mu_k}, {material}, {T},
// {temperature}, {spacing}), filled in from the compiled rig before the frames are drawn, and a
// caption that names another of the paper's materials, or a mu_k the run does not have, is
// warned about. Also the one name of the run's material the video shows, which tells the plate's
// look from its friction when the two differ.
#pragma once

#include <string>
#include <vector>

#include "core/paper_table.hpp"
#include "scene/captions_yaml.hpp"
#include "scene/compiled_rig.hpp"

namespace fl {

// "LEGO blocks"; "LEGO blocks plate, Plexiglas's μₖ" when the friction is another material's
// row of the paper's table than the plate's own; the plate's key when the table lacks it.
std::string run_material_name(const CompiledRig& rig, const PaperTable& table);

// The captions with their placeholders filled: {mu_k} "0.29", {material} as above, {T} the
// theory's period "0.777 s" (the thick plate's where it has one), {temperature} "300 K",
// {spacing} "89 mm".
std::vector<Caption> filled_captions(std::vector<Caption> captions, const CompiledRig& rig,
                                     const PaperTable& table);

// Warnings for captions (filled) that contradict the run: a material of the paper's table other
// than the run's, or "μₖ 0.29" (or mu_k) where the run's mu_k rounds otherwise.
std::vector<std::string> caption_contradictions(const std::vector<Caption>& captions,
                                                const CompiledRig& rig, const PaperTable& table);

}  // namespace fl
