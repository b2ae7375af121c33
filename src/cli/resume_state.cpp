#include "cli/resume_state.hpp"

#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "image/atomic_file.hpp"
#include "math/fnv1a.hpp"
#include "render/usage_error.hpp"

namespace clrt {
namespace {

// The first line of every state; a later layout gets another number.
constexpr const char* kMagic = "clrt resume state 1";

// The floats are stored as this machine holds them; a state moved to a machine of the other
// byte order reads this word wrong and is refused.
constexpr std::uint32_t kByteOrderMark = 0x01020304u;

const char* mode_word(RenderMode mode) {
  switch (mode) {
    case RenderMode::Trace: return "trace";
    case RenderMode::Cast: return "cast";
    case RenderMode::Path: return "path";
  }
  return "?";
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The words of `options` that `theirs` lacks, for the message that refuses a state.
std::string differing_words(const std::string& ours, const std::string& theirs) {
  std::istringstream words(ours);
  std::string word, differing;
  while (words >> word)
    if ((" " + theirs + " ").find(" " + word + " ") == std::string::npos)
      differing += (differing.empty() ? "" : " ") + word;
  return differing;
}

}  // namespace

std::vector<std::string> scene_files(const Scene& scene) {
  std::vector<std::string> paths{scene.path};
  for (const MeshData& mesh : scene.meshes) paths.push_back(mesh.path);
  for (const TextureImage& image : scene.texture_images) paths.push_back(image.path);
  if (scene.environment) paths.push_back(scene.environment->path);
  return paths;
}

ResumeKey resume_key(const std::vector<std::string>& paths, const RenderOptions& options,
                     const FramePlan& frames) {
  std::uint64_t files = kFnv1aBasis;
  for (const std::string& path : paths) {
    const std::string bytes = file_bytes(path);
    // Each file's length first: moving bytes from one file to the next changes the hash.
    files = fnv1a(std::to_string(bytes.size()) + ":" + bytes, files);
  }
  const PixelRect region =
      options.region.value_or(PixelRect{0, 0, static_cast<std::uint32_t>(options.width),
                                        static_cast<std::uint32_t>(options.height)});
  std::ostringstream words;
  words.precision(9);
  words << "resolution=" << options.width << "x" << options.height << " region=" << region.x
        << "," << region.y << "," << region.width << "x" << region.height
        << " mode=" << mode_word(options.mode) << " max-depth=" << options.max_depth
        << " seed=" << options.seed << " max-sample-value=" << options.max_sample_value
        << " glossy=" << (options.glossy ? "yes" : "no");
  if (options.mode != RenderMode::Path) words << " spp=" << options.samples;
  if (frames.animated)
    words << " frames=" << frames.frames << " orbit=" << frames.orbit_degrees
          << " frame-range=" << frames.first << ":" << frames.last;
  return {hex(files), words.str()};
}

std::string resume_state_path(const std::string& output) { return output + ".clrt-resume"; }

void write_resume_state(const std::string& path, const ResumeKey& key, const ResumeState& state) {
  std::ostringstream header;
  header << kMagic << "\nfiles " << key.files << "\noptions " << key.options << "\nframe "
         << state.frame << "\nsamples " << state.samples << "\npixels " << state.sums.size()
         << "\n\n";
  image_detail::AtomicFile file(path, path);
  const std::string text = header.str();
  file.write(text.data(), text.size());
  file.write(&kByteOrderMark, sizeof kByteOrderMark);
  file.write(state.sums.data(), state.sums.size() * sizeof(dev::f4));
  file.finish();
}

std::optional<ResumeState> read_resume_state(const std::string& path, const ResumeKey& key,
                                             std::uint64_t pixels) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  const auto refuse = [&](const std::string& why) {
    return UsageError("--resume: " + path + " " + why);
  };
  std::string magic, files, options;
  std::getline(in, magic);
  if (magic != kMagic) throw refuse("is not a clrt resume state");
  ResumeState state;
  std::uint64_t count = 0;
  std::string word;
  in >> word >> files;
  if (word != "files") throw refuse("is not a clrt resume state");
  in.ignore(1);
  std::getline(in, word, ' ');
  if (word != "options") throw refuse("is not a clrt resume state");
  std::getline(in, options);
  if (!(in >> word >> state.frame) || word != "frame" || !(in >> word >> state.samples) ||
      word != "samples" || !(in >> word >> count) || word != "pixels")
    throw refuse("is not a clrt resume state");
  in.ignore(2);
  if (files != key.files)
    throw refuse("was rendered from other scene files (the scene, its meshes or images have "
                 "changed since); render without --resume to start over");
  if (options != key.options) {
    const std::string theirs = differing_words(options, key.options);
    // Outside path mode a sample's place in its pixel depends on the samples per pixel.
    const std::string why = theirs.rfind("spp=", 0) == 0 && theirs.find(' ') == std::string::npos
                                ? " (outside path mode the samples per pixel cannot grow: each "
                                  "sample's place in its pixel depends on them)"
                                : "";
    throw refuse("was rendered with " + theirs + ", not " + differing_words(key.options, options) +
                 why + "; give the same options, or render without --resume to start over");
  }
  // A state between an animation's frames holds no sums.
  if (count != pixels && !(count == 0 && state.samples == 0))
    throw refuse("holds " + std::to_string(count) + " pixels, not " + std::to_string(pixels));
  std::uint32_t mark = 0;
  in.read(reinterpret_cast<char*>(&mark), sizeof mark);
  if (!in || mark != kByteOrderMark) throw refuse("was written on a machine of another byte order");
  state.sums.resize(count);
  in.read(reinterpret_cast<char*>(state.sums.data()),
          static_cast<std::streamsize>(count * sizeof(dev::f4)));
  if (!in || in.peek() != std::char_traits<char>::eof()) throw refuse("is cut short or too long");
  return state;
}

}  // namespace clrt
