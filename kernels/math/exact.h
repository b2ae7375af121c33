/* Arithmetic whose bits OpenCL fixes, so that every implementation renders the same image.
 *
 * OpenCL pins down +, -, * (correctly rounded, and never fused while FP_CONTRACT is off) and,
 * where the device reports CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT and the host builds with
 * -cl-fp32-correctly-rounded-divide-sqrt, / and sqrt. Its geometric and exponential builtins
 * are only bounded (dot, normalize and length may sum in any order or fuse; normalize may use
 * rsqrt; exp2 and log2 are allowed 3 ulp), and implementations do differ: Intel's CPU runtime
 * and PoCL gave other bits for normalize() on 65% of random vectors. So the kernels use these
 * instead, which spell out each operation and its order. */
#ifndef CLRT_MATH_EXACT_H
#define CLRT_MATH_EXACT_H

#pragma OPENCL FP_CONTRACT OFF

#include "shared/common.h"

CLRT_INLINE float dot2(float2 a, float2 b) { return a.x * b.x + a.y * b.y; }
CLRT_INLINE float dot3(float3 a, float3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
CLRT_INLINE float dot4(float4 a, float4 b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }

CLRT_INLINE float3 cross3(float3 a, float3 b) {
  return (float3)(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

/* Whether v's squared length s = dot3(v, v) is a normal float, as it is for every vector whose
 * largest component lies between about 1e-19 and 1e19. Beyond that the squares overflow to
 * infinity (a triangle's normal at coordinates of 1e10 is 1e20 long) or lose their digits in
 * the subnormals, and the length is taken from v over its largest component instead. */
CLRT_INLINE bool squares_in_range(float s) { return s >= 1.17549435e-38f && s <= 3.40282347e38f; }

CLRT_INLINE float largest_magnitude(float3 v) { return fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z))); }

/* |v|: sqrt(dot3(v, v)) where the squares stay in range, and |v / m| m for v's largest component
 * m elsewhere (within 2 ulp; infinity only where |v| itself exceeds the floats). */
CLRT_INLINE float length3(float3 v) {
  const float s = dot3(v, v);
  if (squares_in_range(s)) return sqrt(s);
  const float m = largest_magnitude(v);
  if (!(m > 0.0f)) return m; /* 0, or NaN */
  const float3 w = v / m;
  return sqrt(dot3(w, w)) * m;
}

/* v / |v|, the squares kept in range as in length3; a zero vector gives NaNs, as no direction. */
CLRT_INLINE float3 normalize3(float3 v) {
  const float s = dot3(v, v);
  if (squares_in_range(s)) return v / sqrt(s);
  const float3 w = v / largest_magnitude(v);
  return w / sqrt(dot3(w, w));
}

/* log2((1 + s) / (1 - s)) = 2 atanh(s) / ln 2 for |s| < 0.172, as its odd series in s, exact
 * to float in 6 terms there. */
CLRT_INLINE float log2_ratio_series(float s) {
  const float s2 = s * s;
  return s * (2.88539008f + s2 * (0.961796694f + s2 * (0.577078016f + s2 * (0.412198583f +
              s2 * (0.320598900f + s2 * 0.262308189f)))));
}

/* e^g - 1 for |g| <= ln 2 / 2, as its Taylor series (7 terms), without the cancellation of
 * subtracting 1 from e^g near g = 0. */
CLRT_INLINE float expm1_series(float g) {
  return g * (1.0f + g * (0.5f + g * (0.166666672f + g * (0.0416666679f + g * (0.00833333377f +
              g * (0.00138888892f + g * 0.000198412701f))))));
}

/* log2(x) for finite x > 0 (subnormals included), within about 2 ulp of the true value: x =
 * m 2^e with m in [sqrt(1/2), sqrt(2)), and log2(m) = log2_ratio_series(s) for
 * s = (m-1)/(m+1), |s| < 0.172. */
CLRT_INLINE float exact_log2(float x) {
  int e = 0;
  if (x < 1.17549435e-38f) {  /* subnormal: scale into the normal range first */
    x *= 16777216.0f;
    e = -24;
  }
  int bits = as_int(x);
  e += ((bits >> 23) & 0xff) - 127;
  bits = (bits & 0x007fffff) | 0x3f800000;  /* m in [1, 2) */
  float m = as_float(bits);
  if (m > 1.41421356f) {
    m *= 0.5f;
    e += 1;
  }
  return (float)e + log2_ratio_series((m - 1.0f) / (m + 1.0f));
}

/* 2^y within about 2 ulp: y = n + f with n an integer and |f| <= 1/2, 2^f as its Taylor series
 * in f ln 2 (8 terms), scaled by 2^n in two steps so that results near the ends of the float
 * range (subnormals, overflow to infinity) come out right. */
CLRT_INLINE float exact_exp2(float y) {
  if (y >= 128.0f) return INFINITY;
  if (y < -150.0f) return 0.0f;
  const float n = rint(y);
  const float g = (y - n) * 0.693147182f;
  const float p = 1.0f + expm1_series(g);
  const int k = (int)n;
  const int k_low = k / 2;
  return p * as_float((k_low + 127) << 23) * as_float((k - k_low + 127) << 23);
}

/* 1 - 2^y for y <= 0, keeping the digits of a y near 0 (where 2^y rounds to 1). */
CLRT_INLINE float one_minus_exp2(float y) {
  const float g = y * 0.693147182f;
  return g < -0.25f ? 1.0f - exact_exp2(y) : -expm1_series(g);
}

/* sin(2 pi u) and cos(2 pi u) for u in [0, 1), within about 2 ulp: the quarter turn of u
 * picks the quadrant, and the rest, an angle x in [-pi/4, pi/4], goes into the Taylor series of
 * sin and cos, whose first omitted terms are below 2e-9 there. OpenCL's sin and cos are only
 * bounded, so path sampling uses these. */
CLRT_INLINE void sincos_turns(float u, float* s, float* c) {
  const float q = rint(u * 4.0f);                   /* the nearest quarter turn, 0 to 4 */
  const float x = (u * 4.0f - q) * 1.57079637f;     /* the rest, in radians */
  const float x2 = x * x;
  const float sx = x * (1.0f - x2 * (0.166666672f - x2 * (0.00833333377f - x2 *
                   (0.000198412701f - x2 * 2.75573188e-06f))));
  const float cx = 1.0f - x2 * (0.5f - x2 * (0.0416666679f - x2 * (0.00138888892f - x2 *
                   (2.48015876e-05f - x2 * 2.75573188e-07f))));
  switch ((int)q & 3) {
    case 0: *s = sx; *c = cx; break;
    case 1: *s = cx; *c = -sx; break;
    case 2: *s = -sx; *c = -cx; break;
    default: *s = -cx; *c = sx; break;
  }
}

/* atan(t) for any finite t, within about 2 ulp: |t| > 1 goes to pi/2 - atan(1/|t|), above
 * tan(pi/8) to pi/4 + atan((t - 1) / (t + 1)), and the rest, |r| <= 0.4143, into atan's odd
 * Taylor series, whose first omitted term (r^19 / 19) is below 3e-9 there. */
CLRT_INLINE float exact_atan(float t) {
  const float a = fabs(t);
  const bool inverted = a > 1.0f;
  const float b = inverted ? 1.0f / a : a;
  const bool shifted = b > 0.414213568f;
  const float r = shifted ? (b - 1.0f) / (b + 1.0f) : b;
  const float r2 = r * r;
  float series = 0.0588235296f;
  series = 0.0666666701f - r2 * series;
  series = 0.0769230798f - r2 * series;
  series = 0.0909090936f - r2 * series;
  series = 0.111111112f - r2 * series;
  series = 0.142857149f - r2 * series;
  series = 0.200000003f - r2 * series;
  series = 0.333333343f - r2 * series;
  /* pi/4 and pi/2 each as a float and its remainder, added last, so that neither constant's
   * rounding (half an ulp of the result) adds to the series'. */
  float angle = r - r * (r2 * series);
  if (shifted) angle = 0.785398185f + (angle - 2.18556941e-08f);
  if (inverted) angle = 1.57079637f - (angle + 4.37113883e-08f);
  return t < 0.0f ? -angle : angle;
}

/* atan2(y, x) in [-pi, pi] from exact_atan: the angle of (|x|, |y|) from the x axis, taken from
 * whichever ratio is at most 1 and carried into the quadrant of (x, y); 0 for (0, 0). pi/2 and
 * pi are each a float and its remainder, as in exact_atan. */
CLRT_INLINE float exact_atan2(float y, float x) {
  const float ax = fabs(x), ay = fabs(y);
  if (ax == 0.0f && ay == 0.0f) return 0.0f;
  float a = ay <= ax ? exact_atan(ay / ax) : 1.57079637f - (exact_atan(ax / ay) + 4.37113883e-08f);
  if (x < 0.0f) a = 3.14159274f - (a + 8.74227766e-08f);
  return y < 0.0f ? -a : a;
}

/* x^y for x >= 0, with 0^0 = 1 as pow() has it. PoCL's pow() made the whole shade kernel 3.5x
 * slower (250 ms against 72 ms on reflect.ray at 1280x720); this costs two short series. */
CLRT_INLINE float power(float x, float y) {
  if (x > 0.0f) return exact_exp2(y * exact_log2(x));
  return y == 0.0f ? 1.0f : 0.0f;
}

#endif
