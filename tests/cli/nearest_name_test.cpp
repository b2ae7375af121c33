// The "did you mean" of every tool: edits counted as users slip, and only close names offered.
#include <catch2/catch.hpp>

#include "text/nearest_name.hpp"

using clrt::edit_distance;
using clrt::nearest_name;

TEST_CASE("edit distance counts insertions, deletions, substitutions and swaps", "[cli][words]") {
  CHECK(edit_distance("spp", "spp") == 0);
  CHECK(edit_distance("sp", "spp") == 1);
  CHECK(edit_distance("sppp", "spp") == 1);
  CHECK(edit_distance("spq", "spp") == 1);
  CHECK(edit_distance("resolutoin", "resolution") == 1);
  CHECK(edit_distance("", "frame") == 5);
  CHECK(edit_distance("kitten", "sitting") == 3);
}

TEST_CASE("the nearest name is offered only when it is close", "[cli][words]") {
  const std::vector<std::string> names{"resolution", "spp", "threads", "nthreads", "frame",
                                       "frames", "o", "q"};
  CHECK(nearest_name("resolutoin", names) == "resolution");
  CHECK(nearest_name("resoltuoin", names) == "resolution");
  CHECK(nearest_name("sp", names) == "spp");
  CHECK(nearest_name("nthread", names) == "nthreads");
  CHECK(nearest_name("fram", names) == "frame");  // ties go to the earlier name
  CHECK_FALSE(nearest_name("x", names));           // a single letter is near everything
  CHECK_FALSE(nearest_name("xyz", names));
  CHECK_FALSE(nearest_name("resultion2x", names));  // three edits
  CHECK_FALSE(nearest_name("spp", {}));
}

TEST_CASE("did_you_mean words the suggestion, in_parentheses ends a message with it", "[cli][words]") {
  CHECK(clrt::did_you_mean("sphree", {"plane", "sphere"}) == "did you mean 'sphere'?");
  CHECK(clrt::did_you_mean("xyz", {"plane", "sphere"}).empty());
  CHECK(clrt::in_parentheses("did you mean 'sphere'?") == " (did you mean 'sphere'?)");
  CHECK(clrt::in_parentheses("").empty());
}
