// Groups NFF's lines into entities: NFF writes an entity's numbers on as many lines as it likes
// (`c` on one line or three, `p` one vertex per line), and only entity names and view keywords
// start with something other than a number.
#pragma once

#include <string>
#include <vector>

#include "scene/lexer.hpp"

namespace clrt {

// Each returned Line is one entity: its name, then every word of its own line and of the lines
// after it that start with a number. A first line that starts with a number is a SceneError.
std::vector<Line> group_nff_entities(std::vector<Line> lines, const std::string& file);

}  // namespace clrt
