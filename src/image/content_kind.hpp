// What a file's first bytes say it holds, whatever its name says: a JPEG named .png is told as a
// JPEG rather than as a PNG whose first chunk is absurd.
#pragma once

#include <string>

#include "image/byte_span.hpp"
#include "image/image.hpp"

namespace clrt::image_detail {

// The bytes a signature needs at most.
constexpr std::size_t kContentHeadBytes = 16;

// The name of the image format `head` (a file's first bytes) starts with, as a user knows it
// ("PNG", "JPEG", "OpenEXR"); empty when no known signature matches.
std::string content_kind(ByteSpan head);

// Throws ImageError("<name>: the name says PNG, but the file holds a JPEG image; ...") when the
// bytes are of a known kind other than `format`, saying how to read it; otherwise returns, and
// the decoder's own checks go on.
void check_content(ByteSpan head, ImageFormat format, const std::string& name);

}  // namespace clrt::image_detail
