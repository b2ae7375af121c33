// What a scene file must be before the lexer reads it: text. An image or an archive given as
// the scene would otherwise fail somewhere deep inside with an error about its bytes
// ("unterminated quoted word" at line 62 of a PNG).
#pragma once

#include <string>
#include <string_view>

namespace clrt {

// Throws SceneError when `text` (the file at `path`, without its byte order mark) is not a
// scene's text: a known binary format, named by its magic number, at the file as a whole; a NUL
// byte or a byte that is not UTF-8 at its line and column.
void check_scene_is_text(const std::string& path, std::string_view text);

}  // namespace clrt
