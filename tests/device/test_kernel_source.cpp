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
