// Comparing two renders of the same frame (`clrt-img diff`).
#pragma once

#include <cstdint>

#include "image/image.hpp"

namespace clrt {

struct ImageDifference {
  // Two float images (PFM, EXR) are compared as floats, in linear units; any other pair as 8-bit
  // samples in steps of 1/255, a float image quantised as clrt quantises its PNG output.
  bool floats = false;
  std::uint64_t pixels = 0;
  std::uint64_t differing = 0;  // pixels with a channel differing by more than the threshold
  double largest = 0;           // the largest channel difference (infinite against NaN/inf)
  double psnr = 0;              // dB over R, G and B, peak 255 or 1; infinite when identical
  // |a - b| per channel, scaled so the largest finite difference is 1 (non-finite ones are 1).
  FloatImage difference;
};

// Compares R, G and B (alpha and placement are not compared) of two one-frame images of the
// same size; ImageError otherwise. Floats that are bit for bit equal (NaN included) do not
// differ.
ImageDifference compare_images(const AnyImage& a, const AnyImage& b, double threshold);

}  // namespace clrt
