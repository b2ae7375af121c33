// clrt's picture options as parsed, without a process: what reaches RenderOptions and the
// display transform of each mode.
#include <catch2/catch.hpp>
#include <cmath>

#include "cli/options.hpp"
#include "cli/picture_options.hpp"
#include "cli/word_choice.hpp"

using namespace clrt;

namespace {

CliOptions parsed(std::vector<std::string> args) {
  args.push_back("scene.ray");
  const ParseResult result = parse_arguments(args, false);
  REQUIRE_FALSE(result.exit_code);
  return result.options;
}

}  // namespace

TEST_CASE("the maximum sample value (--max-sample-value) reaches RenderOptions::max_sample_value", "[cli][picture]") {
  const Scene scene;
  CHECK(std::isinf(resolve_render_options(parsed({}), scene).max_sample_value));
  CHECK(resolve_render_options(parsed({"--max-sample-value", "4.5"}), scene).max_sample_value ==
        4.5f);
  CHECK(parse_arguments({"--max-sample-value", "-1", "scene.ray"}, false).exit_code == 2);
}

TEST_CASE("path mode's 8-bit outputs are sRGB-encoded, the Whitted modes' are not",
          "[cli][picture]") {
  const CliOptions none = parsed({});
  CHECK(display_transform(none, RenderMode::Trace).identity());
  CHECK(display_transform(none, RenderMode::Cast).identity());
  CHECK(display_transform(none, RenderMode::Path).srgb);
  const CliOptions asked = parsed({"--exposure", "-2.5", "--tonemap", "Filmic"});
  const DisplayTransform trace = display_transform(asked, RenderMode::Trace);
  CHECK(trace.exposure == -2.5);
  CHECK(trace.curve == ToneCurve::Filmic);
  CHECK_FALSE(trace.srgb);
  CHECK(renders_bytes({"a.png", ImageFormat::Png}, display_transform(none, RenderMode::Trace)));
  CHECK_FALSE(renders_bytes({"a.png", ImageFormat::Png}, display_transform(none, RenderMode::Path)));
  CHECK_FALSE(renders_bytes({"a.pfm", ImageFormat::Pfm}, display_transform(none, RenderMode::Trace)));
}

TEST_CASE("a word choice names the words and the nearest one", "[cli][words]") {
  CLI::Validator check = word_choice({"clamp", "filmic"});
  CHECK(check.get_description() == "{clamp,filmic}");
  std::string word = "FILMIC";
  CHECK(check(word).empty());
  CHECK(word == "filmic");
  word = "filmc";
  CHECK(check(word) == "filmc is not one of clamp, filmic (did you mean filmic?)");
  word = "xyz";
  CHECK(check(word) == "xyz is not one of clamp, filmic");
}
