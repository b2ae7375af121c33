// texture SLOT ...: a copy of the current material with one of its terms textured
// (docs/scene-format.md#textures).
#include <algorithm>
#include <filesystem>
#include <optional>
#include <vector>

#include "scene/command_table.hpp"
#include "scene/limits.hpp"
#include "scene/texture_images.hpp"
#include "scene/texture_rules.hpp"
#include "shared/texture.h"
#include "text/nearest_name.hpp"

namespace clrt {
namespace {

// In the order of the slots: CLRT_TEXTURE_SLOT_COLOR, _KS, _KR, _KT.
const std::vector<std::string> kTerms = {"color", "ks", "kr", "kt"};
const std::vector<std::string> kKinds = {"image", "checker", "noise", "off"};

// The slot a TERM word names (in lower case), or -1.
int texture_slot(const std::string& word) {
  const auto found = std::find(kTerms.begin(), kTerms.end(), word);
  return found == kTerms.end() ? -1 : static_cast<int>(found - kTerms.begin());
}

const char* kind_name(TextureSpec::Kind kind) {
  switch (kind) {
    case TextureSpec::Kind::Image:
      return "image";
    case TextureSpec::Kind::Checker:
      return "checker";
    case TextureSpec::Kind::Noise:
      break;
  }
  return "noise";
}

// The options and the one kind each belongs to (none: every kind).
struct TextureOption {
  std::string name;
  std::optional<TextureSpec::Kind> only;
};
const std::vector<TextureOption> kOptions = {
    {"scale", std::nullopt}, {"offset", std::nullopt}, {"wrap", TextureSpec::Kind::Image},
    {"octaves", TextureSpec::Kind::Noise}};

std::vector<std::string> option_names() {
  std::vector<std::string> names;
  for (const TextureOption& o : kOptions) names.push_back(o.name);
  return names;
}

// The options from word `first` on: scale SU SV, offset OU OV, wrap repeat|clamp (images),
// octaves N (noise). One that belongs to another kind is read and checked all the same, and a
// warning: written for a checker, `wrap clamp` would otherwise vanish without a word.
void read_options(LoaderState& s, const CommandArgs& a, std::size_t first, TextureSpec& t) {
  for (std::size_t i = first; i < a.count();) {
    const std::string option = lower_case(a.word(i).text);
    const auto known = std::find_if(kOptions.begin(), kOptions.end(),
                                    [&](const TextureOption& o) { return o.name == option; });
    if (known == kOptions.end()) {
      const std::string near = did_you_mean(option, option_names());
      throw a.error_at(i, "unknown texture option '" + excerpt(a.word(i).text) + "' (" + (near.empty() ? "" : near + " ") +
                              "the options are scale, offset, wrap for images, octaves for noise)");
    }
    const auto needs = [&](std::size_t n) {
      if (i + n >= a.count())
        throw a.error_past_end("the texture option " + excerpt(a.word(i).text) + " takes " + std::to_string(n) +
                               (n == 1 ? " word" : " numbers"));
    };
    const bool applies = !known->only || *known->only == t.kind;
    if (!applies)
      s.scene.warnings.push_back(scene_warning(
          a.error_at(i, "").where(), option + " applies to " + kind_name(*known->only) + " textures only (this is a " +
                                         kind_name(t.kind) + " texture); ignored"));
    if (option == "scale" || option == "offset") {
      needs(2);
      double* target = option == "scale" ? t.scale : t.offset;
      for (std::size_t k = 0; k < 2; ++k) {
        target[k] = a.number_in(i + 1 + k, -limits::kMaxNumber, limits::kMaxNumber, "the texture's " + option);
        if (option != "scale") continue;
        if (const auto problem = texture_scale_problem(target[k])) throw a.error_at(i + 1 + k, *problem);
      }
      i += 3;
    } else if (option == "wrap") {
      needs(1);
      const std::string mode = lower_case(a.word(i + 1).text);
      if (mode != "repeat" && mode != "clamp") {
        const std::string near = did_you_mean(mode, {"repeat", "clamp"});
        throw a.error_at(i + 1, "wrap takes repeat or clamp, found '" + excerpt(a.word(i + 1).text) + "'" +
                                    in_parentheses(near));
      }
      if (applies) t.clamp = mode == "clamp";
      i += 2;
    } else {
      needs(1);
      const int octaves = a.whole_number(i + 1, 1, 16, "the noise's octaves");
      if (applies) t.octaves = octaves;
      i += 2;
    }
  }
}

Vec3 colour_at(const CommandArgs& a, std::size_t first) {
  Vec3 c;
  double* channel[3] = {&c.x, &c.y, &c.z};
  for (std::size_t k = 0; k < 3; ++k) *channel[k] = a.number_in(first + k, 0, limits::kMaxNumber, "a texture colour");
  return c;
}

void texture(LoaderState& s, const CommandArgs& a) {
  if (a.count() < 2) a.require_count({2});
  const int slot = texture_slot(lower_case(a.word(0).text));
  if (slot < 0) {
    const std::string near = did_you_mean(lower_case(a.word(0).text), kTerms);
    throw a.error_at(0, "texture takes a term first: color, ks, kr or kt, found '" + excerpt(a.word(0).text) + "'" +
                            in_parentheses(near));
  }
  const std::string kind = lower_case(a.word(1).text);
  MaterialSpec m = s.scene.materials.at(static_cast<std::size_t>(s.material));
  if (kind == "off") {
    a.require_count({2});
    m.textures[static_cast<std::size_t>(slot)] = -1;
  } else {
    TextureSpec t;
    std::size_t options = 0;
    if (kind == "image") {
      if (a.count() < 3) throw a.error_past_end("texture ... image needs a file name");
      options = 3;
    } else if (kind == "checker" || kind == "noise") {
      t.kind = kind == "checker" ? TextureSpec::Kind::Checker : TextureSpec::Kind::Noise;
      if (a.count() < 8) throw a.error_past_end("texture ... " + kind + " needs two colours, R G B R G B");
      t.color0 = colour_at(a, 2);
      t.color1 = colour_at(a, 5);
      options = 8;
    } else {
      const std::string near = did_you_mean(kind, kKinds);
      throw a.error_at(1, "unknown texture '" + excerpt(a.word(1).text) + "' (" + (near.empty() ? "" : near + " ") +
                              "image, checker, noise, or off)");
    }
    read_options(s, a, options, t);
    // The file is read last, once every word is known to be right.
    if (kind == "image") {
      const std::string path =
          (std::filesystem::path(s.scene_folder) / a.word(2).text).lexically_normal().generic_string();
      t.image = texture_image(s, path, a.error_at(2, "").where());
    }
    s.scene.textures.push_back(t);
    m.textures[static_cast<std::size_t>(slot)] = static_cast<int>(s.scene.textures.size()) - 1;
  }
  s.scene.materials.push_back(m);
  s.material = static_cast<int>(s.scene.materials.size()) - 1;
}

}  // namespace

void add_texture_commands(CommandTable& table) { table["texture"] = texture; }

}  // namespace clrt
