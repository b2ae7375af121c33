// Assembling kernel sources: includes resolved from the embedded kernels/ files, each once, with
// #line markers naming the real files.
#include <catch2/catch.hpp>

#include <regex>
#include <string>

#include "device/kernel_source.hpp"

using namespace clrt;

namespace {

int occurrences(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("every file of kernels/ is embedded with its contents", "[kernel-source]") {
  const std::string& ray = kernel_file("shared/ray.h");
  CHECK(ray.find("typedef struct Ray") != std::string::npos);
  CHECK(kernel_file("shade.cl").find("__kernel void shade(") != std::string::npos);
  CHECK_THROWS_WITH(kernel_file("nope.cl"), Catch::Contains("kernels/nope.cl"));
}

TEST_CASE("includes are expanded once, relative to the includer or to kernels/", "[kernel-source]") {
  const std::string text =
      "#include \"shared/ray.h\"\n#include \"render/common.h\"\n  # include \"shared/ray.h\"\nint x;\n";
  const std::string out = assemble_kernel_source(text, "mine.cl");
  // render/common.h includes ../shared/ray.h and ../shared/scene.h: each header appears once.
  CHECK(occurrences(out, "typedef struct Ray {") == 1);
  CHECK(occurrences(out, "typedef struct Camera {") == 1);
  CHECK(out.find("#include \"") == std::string::npos);
  CHECK(out.find("#line 1 \"kernels/shared/ray.h\"") != std::string::npos);
  CHECK(out.find("#line 1 \"kernels/render/common.h\"") != std::string::npos);
  // After the third include line the text resumes at line 4 of mine.cl.
  CHECK(out.find("#line 4 \"kernels/mine.cl\"\nint x;") != std::string::npos);
}

TEST_CASE("an include naming no kernel file is an error naming both files", "[kernel-source]") {
  CHECK_THROWS_WITH(assemble_kernel_source("#include \"missing.h\"\n", "broken.cl"),
                    Catch::Contains("kernels/broken.cl") && Catch::Contains("missing.h"));
}

TEST_CASE("the renderer's program holds every stage kernel", "[kernel-source]") {
  const std::string program = renderer_program_source();
  for (const char* kernel :
       {"generate", "intersect", "shade", "shadow", "compact_count", "compact_scan",
        "compact_scatter", "gather_shadows", "accumulate_samples", "resolve", "count_ray_kinds",
        "fold_ray_counts", "add_ray_kinds", "add_shadow_rays", "commit_ray_counts", "megakernel"}) {
    INFO(kernel);
    CHECK(std::regex_search(program, std::regex(std::string("__kernel void ") + kernel + "\\(")));
  }
}

namespace {

// The definitions in `text` (functions, not prototypes, macros, or enumerations written from an
// X-list, whose lines also hold a parenthesis): the words before the name and
// the whole head up to its opening brace, comments removed.
struct FunctionHead {
  std::string file, head;
};

std::string without_comments(const std::string& text) {
  return std::regex_replace(std::regex_replace(text, std::regex(R"(/\*[\s\S]*?\*/)"), " "),
                            std::regex(R"(//[^\n]*)"), " ");
}

std::vector<FunctionHead> function_heads(const EmbeddedFile& file) {
  std::vector<FunctionHead> out;
  const std::string text = without_comments(file.text);
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = text.find('\n', at);
    const std::string line = text.substr(at, end == std::string::npos ? std::string::npos : end - at);
    const bool starts_definition =
        !line.empty() && (std::isalpha(static_cast<unsigned char>(line[0])) || line[0] == '_') &&
        line.find('(') != std::string::npos && line.rfind("typedef", 0) != 0 &&
        line.rfind("struct", 0) != 0 && line.rfind("enum", 0) != 0;
    if (starts_definition) {
      const std::size_t brace = text.find('{', at), semicolon = text.find(';', at);
      if (brace != std::string::npos && brace < semicolon)
        out.push_back({file.path, text.substr(at, brace - at)});
    }
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return out;
}

}  // namespace

TEST_CASE("no 3-component vector crosses a call that a compiler may keep", "[kernel-source]") {
  // kernels/shared/common.h's rule: a device function is forced inline (CLRT_INLINE), or it is
  // CLRT_CALLABLE and neither takes nor returns a 3-vector; kernels are __kernel.
  const std::regex vector3(R"(\b(float|int|uint|char|uchar|short|ushort|long|ulong|half|double)3\b)");
  int functions = 0;
  for (const EmbeddedFile& file : embedded_kernel_files()) {
    for (const FunctionHead& f : function_heads(file)) {
      ++functions;
      INFO("kernels/" << f.file << ": " << f.head);
      const bool forced = f.head.rfind("CLRT_INLINE ", 0) == 0;
      const bool callable = f.head.rfind("CLRT_CALLABLE ", 0) == 0;
      const bool kernel = f.head.rfind("__kernel ", 0) == 0;
      CHECK((forced || callable || kernel));
      if (callable || kernel) CHECK_FALSE(std::regex_search(f.head, vector3));
    }
  }
  CHECK(functions > 80);  // the scan sees the kernels' functions at all
}

TEST_CASE("the scan for function heads finds definitions and skips the rest", "[kernel-source]") {
  const EmbeddedFile sample{"sample.h",
                            "/* float3 f(float3 a) { } */\n#define M(x) (x)\nfloat3 g(float3 a);\n"
                            "typedef struct S { float3 v; } S;\nCLRT_INLINE float3 h(float3 a,\n"
                            "                       float3 b) {\n  return a;\n}\n"};
  const std::vector<FunctionHead> heads = function_heads(sample);
  REQUIRE(heads.size() == 1);
  CHECK(heads[0].head.find("CLRT_INLINE float3 h(float3 a,") == 0);
}

TEST_CASE("the kernels use no built-in whose bits OpenCL leaves to the implementation",
          "[kernel-source]") {
  // Geometric, exponential, trigonometric and native built-ins are only bounded, and
  // implementations differ in their last bits: kernels/math/exact.h spells them out instead.
  const std::regex loose(
      R"(\b(dot|cross|normalize|length|distance|fast_\w+|native_\w+|half_\w+|exp|exp2|exp10|expm1|)"
      R"(log|log2|log10|log1p|pow|powr|pown|rootn|rsqrt|cbrt|hypot|sin|cos|tan|sincos|asin|acos|)"
      R"(atan|atan2|sinh|cosh|tanh|sinpi|cospi|tanpi|mad|mix|smoothstep|degrees|radians)\s*\()");
  for (const EmbeddedFile& file : embedded_kernel_files()) {
    if (std::string(file.path) == "math/exact.h") continue;
    const std::string text = without_comments(file.text);
    std::smatch m;
    const bool found = std::regex_search(text, m, loose);
    INFO("kernels/" << file.path << (found ? " uses " + m.str() : std::string()));
    CHECK_FALSE(found);
  }
}
