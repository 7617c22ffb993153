#include "lab/video/caption_values.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "text/text.hpp"

namespace fl {
namespace {

const char* const kMuK = "\xce\xbc\xe2\x82\x96";  // μₖ

// Whether `word` stands in `text` as a word of its own (case-insensitive).
bool names(const std::string& text, const std::string& word) {
  const std::string t = ascii_lower(text);
  const std::string w = ascii_lower(word);
  for (std::size_t at = t.find(w); at != std::string::npos; at = t.find(w, at + 1)) {
    const bool starts = at == 0 || !std::isalnum(static_cast<unsigned char>(t[at - 1]));
    const std::size_t end = at + w.size();
    const bool ends = end == t.size() || !std::isalnum(static_cast<unsigned char>(t[end]));
    if (starts && ends) return true;
  }
  return false;
}

std::string period_text(const CompiledRig& rig) {
  return fmt::format("{:.3f} s", rig.period_thick.value_or(rig.period_thin));
}

}  // namespace

std::string run_material_name(const CompiledRig& rig, const PaperTable& table) {
  const PaperMaterial* plate = table.find(rig.plate_desc.material);
  const std::string plate_name = plate != nullptr ? plate->name : rig.plate_desc.material;
  if (!rig.friction_source.paper_material) return plate_name;
  const PaperMaterial* friction = table.find(*rig.friction_source.paper_material);
  if (friction == nullptr || friction == plate) return plate_name;
  return fmt::format("{} plate, {}'s {}", plate_name, friction->name, kMuK);
}

std::vector<Caption> filled_captions(std::vector<Caption> captions, const CompiledRig& rig,
                                     const PaperTable& table) {
  const std::pair<const char*, std::string> values[] = {
      {"{mu_k}", fmt::format("{:.2f}", rig.friction.mu_k)},
      {"{material}", run_material_name(rig, table)},
      {"{T}", period_text(rig)},
      {"{temperature}", fmt::format("{:.0f} K", rig.friction_source.temperature)},
      {"{spacing}", fmt::format("{:.0f} mm", rig.rollers.spacing * 1e3)}};
  for (Caption& c : captions)
    for (const auto& [key, value] : values)
      for (std::size_t at = c.text.find(key); at != std::string::npos;
           at = c.text.find(key, at + value.size()))
        c.text.replace(at, std::string_view(key).size(), value);
  return captions;
}

std::vector<std::string> caption_contradictions(const std::vector<Caption>& captions,
                                                const CompiledRig& rig, const PaperTable& table) {
  std::vector<std::string> out;
  const std::string material = run_material_name(rig, table);
  const double mu_k = rig.friction.mu_k;
  for (const Caption& c : captions) {
    for (const PaperMaterial& m : table.materials) {
      if (names(material, m.name) || names(material, m.key)) continue;
      // "Paper" is also how a narration names the article: as a material, only "paper plate".
      const bool article = ascii_lower(m.name) == "paper";
      if (names(c.text, article ? m.name + " plate" : m.name))
        out.push_back(
            fmt::format("the caption at {:g} s names {}, but this run's plate is {}: "
                        "write {{material}} to name the run's own",
                        c.at, m.name, material));
    }
    // "μₖ 0.29", "μₖ = 0.29", "mu_k: 0.29": the number said of mu_k.
    for (const std::string_view word : {std::string_view(kMuK), std::string_view("mu_k")}) {
      for (std::size_t at = c.text.find(word); at != std::string::npos;
           at = c.text.find(word, at + 1)) {
        std::size_t i = at + word.size();
        while (i < c.text.size() && (c.text[i] == ' ' || c.text[i] == '=' || c.text[i] == ':')) ++i;
        if (i >= c.text.size() || !std::isdigit(static_cast<unsigned char>(c.text[i]))) continue;
        const char* begin = c.text.c_str() + i;
        char* end = nullptr;
        const double said = std::strtod(begin, &end);
        const std::string_view digits(begin, static_cast<std::size_t>(end - begin));
        // A number that goes on into a formula ("μₖ = 2π²l/(gT²)") is not a value of mu_k.
        const char next = *end;
        if (next != '\0' && (std::isalnum(static_cast<unsigned char>(next)) ||
                             (static_cast<unsigned char>(next) & 0x80) != 0 || next == '(' ||
                             next == '/' || next == '*' || next == '^'))
          continue;
        const std::size_t point = digits.find('.');
        const int decimals =
            point == std::string_view::npos ? 0 : static_cast<int>(digits.size() - point - 1);
        if (std::fabs(said - mu_k) > 0.5 * std::pow(10.0, -decimals) + 1e-12)
          out.push_back(
              fmt::format("the caption at {:g} s says {} {}, but this run's mu_k is "
                          "{:.3g}: write {{mu_k}} to say the run's own",
                          c.at, kMuK, digits, mu_k));
      }
    }
  }
  return out;
}

}  // namespace fl
