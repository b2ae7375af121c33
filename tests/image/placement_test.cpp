#include "image/placement.hpp"

#include <catch2/catch.hpp>

using clrt::ImageError;
using clrt::Placement;
using Catch::Matchers::Contains;
using namespace clrt::image_detail;

TEST_CASE("placement text is X,Y WxH of FULL_WxFULL_H and parses back exactly",
          "[image][placement]") {
  CHECK(placement_text(Placement{64, 0, 256, 128}, 64, 32) == "64,0 64x32 of 256x128");
  CHECK(parse_placement_text("64,0 64x32 of 256x128", 64, 32, "t") == Placement{64, 0, 256, 128});
  CHECK(parse_placement_text("0,0 1x1 of 1x1", 1, 1, "t") == Placement{0, 0, 1, 1});
  for (const char* bad : {"64,0 64x32 of 256x128\n", "64, 0 64x32 of 256x128", "-1,0 1x1 of 2x2",
                          "00,0 64x32 of 256x128", "64,0 64X32 of 256x128", ""})
    CHECK_THROWS_WITH(parse_placement_text(bad, 64, 32, "ctx"),
                      Contains("ctx: the placement") && Contains("not of the form"));
}

TEST_CASE("a placement must keep the image inside its frame", "[image][placement]") {
  CHECK_NOTHROW(check_placement(Placement{6, 3, 10, 5}, 4, 2, "t"));
  CHECK_THROWS_WITH(check_placement(Placement{7, 3, 10, 5}, 4, 2, "t"),
                    Contains("a 4x2 image placed at 7,3 does not fit in its 10x5 frame"));
  CHECK_THROWS_AS(check_placement(Placement{6, 4, 10, 5}, 4, 2, "t"), ImageError);
  CHECK_THROWS_AS(check_placement(Placement{-1, 0, 10, 5}, 4, 2, "t"), ImageError);
  CHECK_THROWS_AS(check_placement(Placement{2147483647, 0, 2147483647, 5}, 4, 2, "t"), ImageError);
}

TEST_CASE("a whole-frame placement is recorded as none", "[image][placement]") {
  CHECK(recorded_placement(Placement{0, 0, 4, 2}, 4, 2) == std::nullopt);
  CHECK(recorded_placement(std::nullopt, 4, 2) == std::nullopt);
  CHECK(recorded_placement(Placement{0, 0, 4, 3}, 4, 2) == Placement{0, 0, 4, 3});
}
