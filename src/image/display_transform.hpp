// What turns linear values into the values an 8-bit image stores, in this order: exposure, a
// tone curve, an encoding (sRGB's, or a plain gamma), then the contract's quantisation. One
// implementation serves the writers (clrt, clrt-mpi, clrt-img convert) and clrt-view's screen,
// so that a file and the window showing its floats agree byte for byte (docs/images.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace clrt {

enum class ToneCurve {
  Clamp,   // none: every channel clipped to [0, 1], as the contract's quantisation does anyway
  Filmic,  // Narkowicz's 2015 fit of the ACES curve: highlights roll off towards white
};

struct DisplayTransform {
  // Exposure and gamma first, so that clrt-view's {stops, gamma} reads as it always did.
  double exposure = 0;  // stops: each +1 doubles every value
  double gamma = 1;     // without `srgb`: the value written is value^(1/gamma)
  ToneCurve curve = ToneCurve::Clamp;
  bool srgb = false;    // encode with sRGB's transfer function, which takes the gamma's place

  // The contract's quantisation alone: every value written as computed.
  bool identity() const {
    return exposure == 0 && gamma == 1 && curve == ToneCurve::Clamp && !srgb;
  }
};

// IEC 61966-2-1's encoding of a linear value in [0, 1].
double srgb_encode(double linear);
// x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14) for x >= 0, clamped to [0, 1].
double filmic_curve(double x);
// A linear value through exposure, curve and encoding: in [0, 1]; 0 for NaN and for values
// that exposure leaves at 0 or below.
double display_value(double linear, const DisplayTransform& display);
// display_value() quantised as the contract says (the contract's quantisation alone when
// `display` is the identity).
std::uint8_t display_byte(float linear, const DisplayTransform& display);

// The words the tools take for the curves: clamp, filmic.
std::vector<std::string> tone_curve_names();
std::string tone_curve_name(ToneCurve curve);
std::optional<ToneCurve> tone_curve_from_name(const std::string& name);

}  // namespace clrt
