// Output names with a printf-style frame number, 'turn-%04d.png', as POV-Ray and ffmpeg name
// the files of an animation: convert writes one file per frame through them.
#pragma once

#include <string>

namespace clrt::img {

// Whether `name` is meant as a pattern: it holds a %.
bool is_frame_pattern(const std::string& name);

// `pattern` with `frame` in place of its one %d (or %0Nd: at least N digits, zero-padded) and
// each %% as a %. Throws UsageError for any other use of %, or not exactly one number.
std::string frame_file_name(const std::string& pattern, int frame);

}  // namespace clrt::img
