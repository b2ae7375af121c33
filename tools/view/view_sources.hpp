// The pictures clrt-view can show: the frames of image A, of image B when comparing, and of
// their difference, each as linear floats (an 8-bit image as value / 255).
#pragma once

#include <string>
#include <vector>

#include "image/image.hpp"

namespace clrt::view {

struct ViewSources {
  std::vector<FloatImage> a, b, difference;  // b and difference are empty without a second image
  int width = 0, height = 0;
  // Whether A holds linear values (a PFM, an EXR, the render of --preview) rather than 8-bit
  // display bytes: such an image opens through sRGB, as other HDR viewers show it.
  bool linear = false;
  bool comparing() const { return !b.empty(); }
  int frame_count() const;
  // Frame `frame` of a list, or its last when it has fewer (a still against an animation).
  static const FloatImage& frame_of(const std::vector<FloatImage>& frames, int frame);
};

// Every frame of an image as floats.
std::vector<FloatImage> float_frames(const AnyImage& image);

// A alone, or A against B: ImageError when their sizes differ. The difference is clrt-img
// diff's: |A - B| per channel, scaled so that the largest is 1.
ViewSources make_sources(const AnyImage& a, const AnyImage* b);

}  // namespace clrt::view
