#include "lab/sweep/sweep_spec.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "core/integrator_error.hpp"
#include "core/units.hpp"
#include "io/text_file.hpp"
#include "io/unknown_material.hpp"
#include "io/yaml_node.hpp"
#include "text/decimal.hpp"
#include "text/text.hpp"

namespace fl {
namespace {

// A scalar split into its leading number and the unit after it ("40 mm" -> 40, "mm").
struct NumberWithUnit {
  double number = 0.0;
  std::string unit;
};

std::optional<NumberWithUnit> split_number(std::string_view text) {
  std::string_view s = trim(text);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  NumberWithUnit out;
  const auto [end, ec] = read_decimal(s.data(), s.data() + s.size(), out.number);
  if (ec != std::errc() || !std::isfinite(out.number)) return std::nullopt;
  out.unit = trim(std::string_view(end, static_cast<std::size_t>(s.data() + s.size() - end)));
  return out;
}

// A YAML value as override text: scalars as written, lists and maps in flow style.
std::string value_text(const YamlNode& node) {
  if (node.is_scalar()) return node.text();
  YAML::Emitter out;
  out.SetMapFormat(YAML::Flow);
  out.SetSeqFormat(YAML::Flow);
  out << node.raw();
  return out.c_str();
}

std::string format_number(double value) {
  std::string s = fmt::format("{:.12g}", value);
  return s == "-0" ? "0" : s;
}

// The axis kinds and the keys each allows.
constexpr std::string_view kAxisKinds[] = {"key", "material", "paper_rows", "temperature", "seeds"};

SweepAxis read_key_axis(const YamlNode& n) {
  SweepAxis axis;
  axis.kind = SweepAxisKind::kKey;
  axis.key = n.at("key").text();
  if (axis.key.empty() || axis.key.front() == '.' || axis.key.back() == '.' ||
      axis.key.find("..") != std::string::npos)
    n.at("key").fail("expected a scene key path such as rollers.spacing, found \"" + axis.key +
                     "\"");
  axis.name = axis.key;
  n.allow_keys({"key", "name", "values", "from", "to", "steps", "scale"});
  const bool has_values = n.has("values");
  const bool has_range = n.has("from") || n.has("to") || n.has("steps");
  if (has_values && has_range)
    n.at("values").fail("give either values or a range (from, to, steps), not both");
  if (has_values) {
    n.allow_keys({"key", "name", "values"});
    const YamlNode values = n.at("values");
    values.expect_sequence();
    if (values.size() == 0) values.fail("expected at least one value");
    // The axis has a unit (and numbers) when every value is a number with the same unit.
    bool numeric = true;
    std::string unit;
    for (std::size_t i = 0; i < values.size(); ++i) {
      const YamlNode v = values[i];
      SweepValue value;
      value.label = value_text(v);
      value.overrides.push_back({axis.key, value.label});
      const auto split = v.is_scalar() ? split_number(value.label) : std::nullopt;
      if (split) {
        value.number = split->number;
        if (i == 0) unit = split->unit;
        numeric = numeric && split->unit == unit;
      } else {
        numeric = false;
      }
      axis.values.push_back(std::move(value));
    }
    if (numeric) {
      axis.unit = unit;
    } else {
      for (SweepValue& v : axis.values) v.number.reset();
    }
    return axis;
  }
  n.allow_keys({"key", "name", "from", "to", "steps", "scale"});
  if (!has_range) n.fail("an axis over a key needs values: [...] or from, to and steps");
  const YamlNode from_node = n.at("from");
  const YamlNode to_node = n.at("to");
  const YamlNode steps_node = n.at("steps");
  const auto from = split_number(from_node.text());
  if (!from) from_node.fail("expected a number with its unit, e.g. 40 mm");
  auto to = split_number(to_node.text());
  if (!to) to_node.fail("expected a number with its unit, e.g. 200 mm");
  if (to->unit.empty() && !from->unit.empty())
    to_node.fail("expected a number with the unit of from (\"" + from->unit + "\"), found \"" +
                 to_node.text() + "\" with none: a plain number is SI; write it with its unit");
  if (to->unit != from->unit)
    to_node.fail("from and to must be in the same unit (found \"" + from->unit + "\" and \"" +
                 to->unit + "\")");
  const std::int64_t steps = steps_node.integer();
  if (steps < 1 || steps > static_cast<std::int64_t>(kMaxSweepPoints))
    steps_node.fail(fmt::format("expected a whole number of values from 1 to {}", kMaxSweepPoints));
  if (steps == 1 && from->number != to->number)
    steps_node.fail("one step cannot go from one value to another; give steps >= 2");
  if (auto scale = n.find("scale")) {
    const std::string s = scale->text();
    if (s == "log")
      axis.log_scale = true;
    else if (s != "linear")
      scale->fail("expected linear or log, found \"" + s + "\"");
  }
  if (axis.log_scale && (from->number <= 0.0 || to->number <= 0.0))
    n.at("scale").fail("a log range needs from and to above zero");
  axis.unit = from->unit;
  for (std::int64_t i = 0; i < steps; ++i) {
    double x = from->number;
    if (steps > 1) {
      const double f = static_cast<double>(i) / static_cast<double>(steps - 1);
      x = axis.log_scale ? std::exp(std::log(from->number) +
                                    f * (std::log(to->number) - std::log(from->number)))
                         : from->number + f * (to->number - from->number);
      // The ends exactly as written.
      if (i == steps - 1) x = to->number;
    }
    SweepValue value;
    const std::string number = format_number(x);
    value.label = axis.unit.empty() ? number : number + " " + axis.unit;
    value.number = split_number(number)->number;
    value.overrides.push_back({axis.key, value.label});
    axis.values.push_back(std::move(value));
  }
  return axis;
}

// The Table I materials a list (or "all") names, checked against the table.
std::vector<const PaperMaterial*> read_materials(const YamlNode& node, const PaperTable& table) {
  std::vector<const PaperMaterial*> out;
  if (node.is_scalar() && node.text() == "all") {
    for (const PaperMaterial& m : table.materials) out.push_back(&m);
    return out;
  }
  if (!node.is_sequence()) node.fail("expected a list of Table I materials, or all");
  if (node.size() == 0) node.fail("expected at least one material");
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YamlNode item = node[i];
    const std::string key = item.text();
    const PaperMaterial* m = table.find(key);
    if (m == nullptr)
      item.fail("\"" + key + "\" is not a material of the paper's Table I; " +
                unknown_material_note(table, key));
    out.push_back(m);
  }
  return out;
}

std::string temperature_label(double kelvin) {
  return format_number(kelvin) + " K";
}

// Temperatures: a list of "300 K", "77 K" (or "all" where `all` is given).
std::vector<double> read_temperatures(const YamlNode& node, const std::vector<double>& all = {}) {
  std::vector<double> out;
  if (!all.empty() && node.is_scalar() && node.text() == "all") return all;
  if (!node.is_sequence())
    node.fail(all.empty() ? "expected a list of temperatures, e.g. [300 K, 77 K]"
                          : "expected a list of temperatures, e.g. [300 K, 77 K], or all");
  if (node.size() == 0) node.fail("expected at least one temperature");
  for (std::size_t i = 0; i < node.size(); ++i) {
    const double t = node[i].quantity(Dimension::kTemperature);
    if (!(t > 0.0)) node[i].fail("expected a temperature above 0 K");
    out.push_back(t);
  }
  return out;
}

SweepAxis read_axis(const YamlNode& n, const PaperTableSource& paper) {
  n.expect_map();
  // Exactly one kind key says what the axis sweeps.
  std::vector<std::string_view> kinds;
  for (const std::string_view kind : kAxisKinds)
    if (n.has(kind)) kinds.push_back(kind);
  if (kinds.empty())
    n.fail(
        "an axis needs one of: key (a scene key path), material, paper_rows, temperature, seeds");
  if (kinds.size() > 1)
    n.at(kinds[1]).fail("an axis sweeps one thing; found both " + std::string(kinds[0]) + " and " +
                        std::string(kinds[1]) + " (use zip: to pair axes)");
  SweepAxis axis;
  const std::string_view kind = kinds.front();
  if (kind == "key") {
    axis = read_key_axis(n);
  } else if (kind == "material") {
    n.allow_keys({"material", "name"});
    axis.kind = SweepAxisKind::kMaterial;
    axis.name = "material";
    for (const PaperMaterial* m : read_materials(n.at("material"), paper())) {
      SweepValue v;
      v.label = m->key;
      v.overrides = {{"friction.mu_k", m->key}, {"plate.material", m->key}};
      axis.values.push_back(std::move(v));
    }
  } else if (kind == "paper_rows") {
    n.allow_keys({"paper_rows", "name"});
    axis.kind = SweepAxisKind::kPaperRows;
    axis.name = "paper_row";
    const PaperTable& table = paper();
    const YamlNode node = n.at("paper_rows");
    for (const double t : read_temperatures(node, {300.0, 77.0})) {
      bool any = false;
      for (const PaperMaterial& m : table.materials) {
        if (PaperTable::at(m, t) == nullptr) continue;
        any = true;
        SweepValue v;
        v.label = m.key + " " + temperature_label(t);
        v.overrides = {{"friction.mu_k", m.key},
                       {"plate.material", m.key},
                       {"friction.temperature", temperature_label(t)}};
        axis.values.push_back(std::move(v));
      }
      if (!any)
        node.fail("the paper measured no material at " + temperature_label(t) +
                  " (its rows are at 300 K and 77 K)");
    }
  } else if (kind == "temperature") {
    n.allow_keys({"temperature", "name"});
    axis.kind = SweepAxisKind::kTemperature;
    axis.name = "temperature";
    axis.key = "friction.temperature";
    axis.unit = "K";
    for (const double t : read_temperatures(n.at("temperature"))) {
      SweepValue v;
      v.label = temperature_label(t);
      v.number = t;
      v.overrides = {{"friction.temperature", v.label}};
      axis.values.push_back(std::move(v));
    }
  } else {
    n.allow_keys({"seeds", "name"});
    axis.kind = SweepAxisKind::kSeed;
    axis.name = "seed";
    axis.key = "world.seed";
    const YamlNode node = n.at("seeds");
    std::vector<std::int64_t> seeds;
    if (node.is_scalar()) {
      const std::int64_t count = node.integer();
      if (count < 1 || count > static_cast<std::int64_t>(kMaxSweepPoints))
        node.fail("expected a number of seeds (1, 2, ... N) or a list of seeds");
      for (std::int64_t s = 1; s <= count; ++s) seeds.push_back(s);
    } else {
      if (node.size() == 0) node.fail("expected at least one seed");
      for (std::size_t i = 0; i < node.size(); ++i) {
        const std::int64_t s = node[i].integer();
        if (s < 0) node[i].fail("expected a whole number >= 0");
        seeds.push_back(s);
      }
    }
    for (const std::int64_t s : seeds) {
      SweepValue v;
      v.label = std::to_string(s);
      v.number = static_cast<double>(s);
      v.overrides = {{"world.seed", v.label}};
      axis.values.push_back(std::move(v));
    }
  }
  if (auto name = n.find("name")) {
    axis.name = name->text();
    if (axis.name.empty() || axis.name.find_first_of(",\"\n\r") != std::string::npos)
      name->fail("expected a column name without commas, quotes or line breaks");
  }
  axis.where = n.location();
  return axis;
}

// The axis's problem is its key path when the scene loader refused the path itself (an unknown
// key, or a key below a value that is not a map), rather than the value.
bool is_key_path_problem(const InputError& e, const std::string& path) {
  const std::string what = e.what();
  if (what.find("not a map of keys") != std::string::npos ||
      what.find("empty part") != std::string::npos)
    return located_at_override(e, path);
  if (what.find(": unknown key") == std::string::npos) return false;
  // "...error: rollers.spaceing: unknown key": a prefix of the path is the unknown key.
  std::string prefix;
  std::string_view rest = path;
  while (true) {
    const std::size_t dot = rest.find('.');
    prefix += (prefix.empty() ? "" : ".") + std::string(rest.substr(0, dot));
    if (what.find("error: " + prefix + ": unknown key") != std::string::npos) return true;
    if (dot == std::string_view::npos) return false;
    rest.remove_prefix(dot + 1);
  }
}

// Why a sweep cannot take this accuracy, or empty when it can.
std::string accuracy_problem(const SweepSpec& spec, double accuracy) {
  if (!(accuracy > 0.0) || accuracy > kLoosestPeriodAccuracy)
    return fmt::format("expected a period accuracy above 0 and at most 10 % (e.g. 0.01%), found {}",
                       format_number(accuracy));
  const std::string step = "world.time_step";
  bool sets_step = false;
  for (const SceneOverride& o : spec.set) sets_step = sets_step || o.path == step;
  for (const SweepAxis* a : spec.axes())
    for (const SceneOverride& o : a->values.front().overrides)
      sets_step = sets_step || o.path == step;
  if (sets_step)
    return "the accuracy picks each point's time step, and the sweep sets " + step +
           " as well; drop one of them";
  return {};
}

// Loads the base scene with some overrides; an error that is about `path` itself is rethrown
// located at `where` in the sweep file, any other (a value the point will report) is ignored.
void probe_key(const SweepSpec& spec, const std::vector<SceneOverride>& overrides,
               const std::string& path, const SourceLocation& where, const std::string& what,
               const SceneInputs& inputs) {
  try {
    load_scene_text(spec.scene_text, spec.scene_file, overrides, inputs.paper, inputs.parts);
  } catch (const InputError& e) {
    if (is_key_path_problem(e, path))
      throw InputError(where, what + ": \"" + path + "\" is not a key of the scene " +
                                  spec.scene_file + " (" + e.what() + ")");
  } catch (const std::exception&) {
    // Values are the points' business.
  }
}

SweepSpec read_sweep(const YamlNode& root, const std::string& name, const std::string& base_dir,
                     const SceneInputs& inputs) {
  const PaperTableSource& paper = inputs.paper;
  root.expect_map();
  root.allow_keys(
      {"format", "name", "description", "scene", "set", "cycles", "accuracy", "period", "axes"});
  const YamlNode format = root.at("format");
  if (format.integer() != 1) format.fail("this build reads sweep format 1, found " + format.text());
  SweepSpec spec;
  spec.file = name;
  spec.name = std::filesystem::path(name).stem().string();
  if (auto v = root.find("name")) spec.name = v->text();
  if (auto v = root.find("description")) v->text();
  if (auto v = root.find("cycles")) spec.cycles = v->boolean();
  if (auto v = root.find("period")) {
    const std::string text = v->text();
    if (text != "hall" && text != "trajectory")
      v->fail(
          "expected hall (the rig's estimator on the simulated Hall signal, and the "
          "trajectory's period) or trajectory (the trajectory's period only, no sensor), "
          "found \"" +
          text + "\"");
    spec.hall = text == "hall";
  }

  const YamlNode scene = root.at("scene");
  std::filesystem::path scene_path(scene.text());
  if (scene_path.is_relative() && !base_dir.empty())
    scene_path = std::filesystem::path(base_dir) / scene_path;
  spec.scene_file = scene_path.lexically_normal().string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(spec.scene_file, ec))
    scene.fail("no scene file at " + spec.scene_file +
               " (a relative path is read from the sweep "
               "file's folder)");
  spec.scene_text = read_text_file(spec.scene_file);

  std::vector<std::pair<std::string, SourceLocation>> set_paths;
  if (auto set = root.find("set")) {
    set->expect_map();
    for (const auto& entry : set->raw()) {
      if (!entry.first.IsScalar())
        set->fail("a key must be a scene key path such as world.duration");
      const std::string path = entry.first.Scalar();
      const YamlNode value = set->at(path);
      spec.set.push_back({path, value_text(value)});
      set_paths.emplace_back(path, value.location());
    }
  }

  const YamlNode axes = root.at("axes");
  axes.expect_sequence();
  if (axes.size() == 0) axes.fail("expected at least one axis");
  for (std::size_t i = 0; i < axes.size(); ++i) {
    const YamlNode entry = axes[i];
    SweepGroup group;
    if (entry.is_map() && entry.has("zip")) {
      entry.allow_keys({"zip"});
      const YamlNode zipped = entry.at("zip");
      zipped.expect_sequence();
      if (zipped.size() < 2) zipped.fail("zip pairs two or more axes");
      for (std::size_t j = 0; j < zipped.size(); ++j)
        group.axes.push_back(read_axis(zipped[j], paper));
      for (const SweepAxis& a : group.axes) {
        if (a.values.size() != group.axes.front().values.size())
          zipped.fail(fmt::format("zipped axes need as many values each: {} has {}, {} has {}",
                                  group.axes.front().name, group.axes.front().values.size(), a.name,
                                  a.values.size()));
      }
    } else {
      group.axes.push_back(read_axis(entry, paper));
    }
    spec.groups.push_back(std::move(group));
  }

  // Column names are unique, and no two axes set the same key.
  const auto all = spec.axes();
  for (std::size_t i = 0; i < all.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (all[i]->name == all[j]->name)
        throw InputError(all[i]->where, "two axes are named \"" + all[i]->name +
                                            "\"; give one a name: for its column");
      for (const SceneOverride& a : all[i]->values.front().overrides)
        for (const SceneOverride& b : all[j]->values.front().overrides)
          if (a.path == b.path)
            throw InputError(all[i]->where, "two axes set " + a.path + "; sweep it once");
    }
  }
  // Guard the product against overflow and against typos that would fill a disk.
  double count = 1.0;
  for (const SweepGroup& g : spec.groups) count *= static_cast<double>(g.size());
  if (count > static_cast<double>(kMaxSweepPoints))
    axes.fail(fmt::format("the axes make {:.0f} points; a sweep holds at most {}", count,
                          kMaxSweepPoints));

  // Key paths must be keys of the scene (their values are each point's business).
  for (const auto& [path, where] : set_paths) probe_key(spec, spec.set, path, where, "set", inputs);
  for (const SweepAxis* a : all) {
    if (a->kind != SweepAxisKind::kKey) continue;
    std::vector<SceneOverride> overrides = spec.set;
    overrides.insert(overrides.end(), a->values.front().overrides.begin(),
                     a->values.front().overrides.end());
    probe_key(spec, overrides, a->key, a->where, "axis " + a->name, inputs);
  }
  if (auto v = root.find("accuracy")) {
    const double accuracy = v->quantity(Dimension::kDimensionless);
    const std::string problem = accuracy_problem(spec, accuracy);
    if (!problem.empty()) v->fail(problem);
    spec.accuracy = accuracy;
  }
  return spec;
}

}  // namespace

std::string_view sweep_axis_kind_name(SweepAxisKind kind) {
  switch (kind) {
    case SweepAxisKind::kKey:
      return "key";
    case SweepAxisKind::kMaterial:
      return "material";
    case SweepAxisKind::kPaperRows:
      return "paper_rows";
    case SweepAxisKind::kTemperature:
      return "temperature";
    case SweepAxisKind::kSeed:
      return "seeds";
  }
  return "key";
}

std::size_t SweepSpec::point_count() const {
  std::size_t n = 1;
  for (const SweepGroup& g : groups) n *= g.size();
  return groups.empty() ? 0 : n;
}

std::vector<const SweepAxis*> SweepSpec::axes() const {
  std::vector<const SweepAxis*> out;
  for (const SweepGroup& g : groups)
    for (const SweepAxis& a : g.axes) out.push_back(&a);
  return out;
}

SweepSpec load_sweep_text(std::string_view text, const std::string& name,
                          const std::string& base_dir, const SceneInputs& inputs) {
  return read_sweep(load_yaml_text(text, name), name, base_dir, inputs);
}

SweepSpec load_sweep_file(const std::string& file, const SceneInputs& inputs) {
  return read_sweep(load_yaml_file(file), file, std::filesystem::path(file).parent_path().string(),
                    inputs);
}

SweepPoint sweep_point(const SweepSpec& spec, std::size_t index) {
  SweepPoint p;
  p.index = index;
  // Mixed radix, the last group fastest.
  std::vector<std::size_t> digit(spec.groups.size());
  std::size_t rest = index;
  for (std::size_t g = spec.groups.size(); g-- > 0;) {
    digit[g] = rest % spec.groups[g].size();
    rest /= spec.groups[g].size();
  }
  p.overrides = spec.set;
  for (std::size_t g = 0; g < spec.groups.size(); ++g) {
    for (const SweepAxis& a : spec.groups[g].axes) {
      const SweepValue& v = a.values[digit[g]];
      p.labels.push_back(v.label);
      p.overrides.insert(p.overrides.end(), v.overrides.begin(), v.overrides.end());
    }
  }
  return p;
}

std::vector<SweepPoint> expand_sweep(const SweepSpec& spec) {
  std::vector<SweepPoint> out;
  const std::size_t n = spec.point_count();
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.push_back(sweep_point(spec, i));
  return out;
}

std::string text_digest(std::string_view text) {
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return fmt::format("{:016x}", h);
}

void set_sweep_accuracy(SweepSpec& spec, double accuracy, const SourceLocation& where) {
  const std::string problem = accuracy_problem(spec, accuracy);
  if (!problem.empty()) throw InputError(where, problem);
  spec.accuracy = accuracy;
}

nlohmann::json sweep_plan(const SweepSpec& spec) {
  nlohmann::json axes = nlohmann::json::array();
  for (const SweepAxis* a : spec.axes()) {
    nlohmann::json values = nlohmann::json::array();
    nlohmann::json numbers = nlohmann::json::array();
    for (const SweepValue& v : a->values) {
      values.push_back(v.label);
      numbers.push_back(v.number ? nlohmann::json(*v.number) : nlohmann::json(nullptr));
    }
    axes.push_back({{"name", a->name},
                    {"kind", std::string(sweep_axis_kind_name(a->kind))},
                    {"key", a->key},
                    {"unit", a->unit},
                    {"scale", a->log_scale ? "log" : "linear"},
                    {"values", values},
                    {"numbers", numbers}});
  }
  nlohmann::json points = nlohmann::json::array();
  for (std::size_t i = 0; i < spec.point_count(); ++i) {
    nlohmann::json set = nlohmann::json::array();
    for (const SceneOverride& o : sweep_point(spec, i).overrides)
      set.push_back(o.path + "=" + o.value);
    points.push_back(std::move(set));
  }
  nlohmann::json plan{{"format", 1},
                      {"sweep", spec.name},
                      {"scene", std::filesystem::path(spec.scene_file).stem().string()},
                      {"scene_digest", text_digest(spec.scene_text)},
                      {"axes", axes},
                      {"points", points}};
  // Only a sweep that records cycles says so: other plans keep their bytes.
  if (spec.cycles) plan["cycles"] = true;
  if (spec.accuracy) plan["accuracy"] = *spec.accuracy;
  if (!spec.hall) plan["period"] = "trajectory";
  return plan;
}

Shard parse_shard(std::string_view text) {
  const SourceLocation where = SourceLocation::of_field("shard", std::string(text));
  const std::size_t slash = text.find('/');
  std::size_t k = 0, n = 0;
  const auto parse = [](std::string_view s, std::size_t& out) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size() && !s.empty();
  };
  if (slash == std::string_view::npos || !parse(text.substr(0, slash), k) ||
      !parse(text.substr(slash + 1), n))
    throw InputError(where, "expected K/N, e.g. 2/8 (shard K of N, K from 1 to N)");
  if (n < 1 || k < 1 || k > n)
    throw InputError(where, "K must be from 1 to N (shard K of N), found " + std::string(text));
  return Shard{k, n};
}

}  // namespace fl
