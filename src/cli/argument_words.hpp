// The words of a command line made regular before the option parser sees them, so that clrt
// takes the spellings users know from other tools:
//   --pixel-bounds A B C D, --crop-window A B C D   ->  --pixel-bounds=A,B,C,D
//   (and pbrt's spellings --pixelbounds, --cropwindow)
//   --stats=json                                   ->  --stats --stats-format=json
//   --stats=text                                   ->  --stats
// `--stats` itself stays a flag, so it never takes the scene's name as its value.
#pragma once

#include <string>
#include <vector>

namespace clrt {

std::vector<std::string> regular_argument_words(std::vector<std::string> args);

}  // namespace clrt
