// The chi-square test of sampled directions against a claimed density, as Mitsuba 3's and
// pbrt's test suites run it: directions binned over the sphere (16 bands of z about a normal by
// 32 of azimuth, equal solid angles), bins expecting fewer than 5 pooled into one, and the
// statistic's p-value by the Wilson-Hilferty approximation.
#pragma once

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "shared/common.h"

namespace clrt::test {

struct V3 {
  double x, y, z;
};
inline V3 operator*(double s, V3 v) { return {s * v.x, s * v.y, s * v.z}; }
inline V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline V3 unit(V3 v) { return (1.0 / std::sqrt(dot(v, v))) * v; }
inline V3 of(const dev::f4& v) { return {v.x, v.y, v.z}; }

constexpr double kPi = 3.14159265358979323846;

struct Frame {
  V3 n, t, b;
};

inline Frame frame_of(V3 n) {
  const V3 a = std::fabs(n.x) < 0.9 ? V3{1, 0, 0} : V3{0, 1, 0};
  const V3 t = unit(a + (-dot(a, n)) * n);
  return {n, t, cross(n, t)};
}

constexpr int kZBins = 16, kPhiBins = 32;

inline int bin_of(const Frame& f, V3 w) {
  const double z = std::clamp(dot(f.n, w), -1.0, 1.0);
  const double phi = std::atan2(dot(f.b, w), dot(f.t, w));
  const int zi = std::min(kZBins - 1, static_cast<int>((z + 1) / 2 * kZBins));
  const int pi = std::min(kPhiBins - 1, static_cast<int>((phi + kPi) / (2 * kPi) * kPhiBins));
  return zi * kPhiBins + pi;
}

// Calls visit(bin, w, d_omega) at the midpoints of a sub x sub grid in z and phi within every
// bin (d omega = dz dphi), for integrating a density over the bins.
template <class Visit>
void for_each_bin_point(const Frame& f, int sub, const Visit& visit) {
  const double dz = 2.0 / kZBins / sub, dphi = 2 * kPi / kPhiBins / sub;
  for (int zi = 0; zi < kZBins * sub; ++zi) {
    const double z = -1 + (zi + 0.5) * dz, r = std::sqrt(std::max(0.0, 1 - z * z));
    for (int pi = 0; pi < kPhiBins * sub; ++pi) {
      const double phi = -kPi + (pi + 0.5) * dphi;
      const V3 w = z * f.n + (r * std::cos(phi)) * f.t + (r * std::sin(phi)) * f.b;
      visit((zi / sub) * kPhiBins + pi / sub, w, dz * dphi);
    }
  }
}

// Probability of each bin: the density integrated by the midpoint rule on 24 x 24 points per bin.
template <class Density>
std::vector<double> bin_probabilities(const Frame& f, const Density& density) {
  std::vector<double> p(kZBins * kPhiBins, 0.0);
  for_each_bin_point(f, 24, [&](int bin, V3 w, double d_omega) { p[bin] += density(w) * d_omega; });
  return p;
}

// The chance of a chi-square statistic at least `chi2` with `dof` degrees of freedom, by the
// Wilson-Hilferty approximation (ample for the hundreds of degrees of freedom here).
inline double chi2_p_value(double chi2, double dof) {
  const double z = (std::cbrt(chi2 / dof) - (1 - 2 / (9 * dof))) / std::sqrt(2 / (9 * dof));
  return 0.5 * std::erfc(z / std::sqrt(2.0));
}

// Observed against expected counts, bins expecting fewer than 5 pooled into one.
inline void chi2_test(const std::vector<double>& observed, const std::vector<double>& expected) {
  double chi2 = 0, pooled_observed = 0, pooled_expected = 0;
  int bins = 0;
  for (std::size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] < 5) {
      pooled_observed += observed[i];
      pooled_expected += expected[i];
      continue;
    }
    chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++bins;
  }
  if (pooled_expected >= 5) {
    chi2 += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
    ++bins;
  } else {
    CHECK(pooled_observed <= 5 + 5 * pooled_expected);  // nothing where nothing is expected
  }
  INFO("chi2 " << chi2 << " over " << bins - 1 << " degrees of freedom");
  const double p = chi2_p_value(chi2, bins - 1);
  INFO("p-value " << p);
  CHECK(p > 1e-3);
}

}  // namespace clrt::test
