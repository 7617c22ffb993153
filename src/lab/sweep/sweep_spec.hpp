// Sweep files (scenes/sweeps/*.yaml, format 1; docs/sweep-format.md): a base scene and axes over
// its keys, read strictly (unknown keys are located errors), and expanded into points. Each point
// is the base scene with a list of `--set`-style overrides, run on its own.
//
// One immutable description: the spec and its points never change once loaded, so workers,
// ranks and shards all see the same numbered points.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/input_error.hpp"
#include "scene/scene_yaml.hpp"

namespace fl {

enum class SweepAxisKind {
  kKey,          // any scene key path, with a list of values or a range
  kMaterial,     // Table I materials by name: friction.mu_k and plate.material
  kPaperRows,    // Table I rows (material, temperature) at the temperatures named
  kTemperature,  // friction.temperature
  kSeed,         // world.seed
};

// "key", "material", "paper_rows", "temperature", "seed".
std::string_view sweep_axis_kind_name(SweepAxisKind kind);

// One value of an axis: its label in the results, and the scene keys it sets.
struct SweepValue {
  std::string label;             // "44.1025641026 mm", "lego", "lego 77 K"
  std::optional<double> number;  // the label's number in the axis's unit, when it has one
  std::vector<SceneOverride> overrides;
};

struct SweepAxis {
  std::string name;  // the results' column: the key path, "material", "paper_row", ...
  SweepAxisKind kind = SweepAxisKind::kKey;
  std::string key;   // the scene key path a kKey axis sets
  std::string unit;  // the unit of `number` ("mm", "rpm", "K"); empty when none
  bool log_scale = false;
  std::vector<SweepValue> values;
  SourceLocation where;  // the axis in the sweep file
};

// The axes of a group are zipped (value i of each goes together; equal lengths); the points are
// the product over the groups, the last group varying fastest.
struct SweepGroup {
  std::vector<SweepAxis> axes;
  std::size_t size() const { return axes.empty() ? 0 : axes.front().values.size(); }
};

struct SweepSpec {
  std::string file;                // the sweep file as named
  std::string name;                // `name:` or the file's stem
  std::string scene_file;          // the base scene, resolved against the sweep file's folder
  std::string scene_text;          // its content when loaded (resuming checks it did not change)
  std::vector<SceneOverride> set;  // `set:`, applied to every point before its axes
  bool cycles = false;             // `cycles:`: each point's cycles to cycles/NNNNNNNN.csv
  // `accuracy:` (or `sweep --accuracy`): each point runs at the largest step whose predicted
  // period error stays within it (relative; lab/run/step_choice.hpp), not the scene's step.
  std::optional<double> accuracy;
  // `period: trajectory`: the points measure only the trajectory's period; the Hall sensor is
  // not simulated and the estimator's columns are null. `period: hall` (the default): both.
  bool hall = true;
  std::vector<SweepGroup> groups;

  std::size_t point_count() const;
  // Every axis, in file order (the results' parameter columns).
  std::vector<const SweepAxis*> axes() const;
};

struct SweepPoint {
  std::size_t index = 0;
  std::vector<std::string> labels;       // one per axis, in axes() order
  std::vector<SceneOverride> overrides;  // `set:` then each axis's, in order
};

// More points than this is refused (a typo in `steps` should not fill a disk).
inline constexpr std::size_t kMaxSweepPoints = 1'000'000;

// Reads a sweep file; the base scene must exist. Table I is asked for only when the file names
// materials. Every key path an axis or `set:` names is checked against the base scene: an
// unknown key is an error located in the sweep file. Throws InputError.
SweepSpec load_sweep_file(const std::string& file, const SceneInputs& inputs);

// The same from text: `name` stands for the file in messages, and a relative `scene:` is
// resolved against `base_dir`.
SweepSpec load_sweep_text(std::string_view text, const std::string& name,
                          const std::string& base_dir, const SceneInputs& inputs);

// Sets the sweep's accuracy (`sweep --accuracy`, over the file's `accuracy:`); `where` names the
// option in errors. Throws InputError when it is not a fraction in (0, 10 %], or when the sweep
// sets world.time_step, which the accuracy would override.
void set_sweep_accuracy(SweepSpec& spec, double accuracy, const SourceLocation& where);

// Point `index` (0 <= index < point_count()).
SweepPoint sweep_point(const SweepSpec& spec, std::size_t index);
std::vector<SweepPoint> expand_sweep(const SweepSpec& spec);

// The plan: every point's overrides, the axes and a digest of the base scene's text, as JSON.
// Two runs of a sweep share results only if their plans are equal.
nlohmann::json sweep_plan(const SweepSpec& spec);
// FNV-1a 64 of a text, as 16 hex digits (names a plan in point files).
std::string text_digest(std::string_view text);

// "--shard K/N": shard K (1-based) of N runs the points whose index % N == K - 1.
struct Shard {
  std::size_t k = 1;
  std::size_t n = 1;
  bool contains(std::size_t index) const { return index % n == k - 1; }
};
// Parses "K/N"; throws InputError naming the option.
Shard parse_shard(std::string_view text);

}  // namespace fl
