// gather_shadows, accumulate_samples and resolve (kernels/accumulate.cl): per-owner sums in
// queue order, compared bit for bit with the same float sums done on the host, and the same
// bits wherever a run of the queue sits (so work-group boundaries cannot change an image).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "cl_fixture.hpp"
#include "render/stage_args.hpp"
#include "shared/ray.h"
#include "test_vectors.hpp"

using namespace clrt;

namespace {

// Values spread over six decades, so that summing in another order changes the low bits.
dev::f4 random_colour(std::mt19937& rng) {
  std::uniform_real_distribution<float> exponent(-3, 3);
  const auto v = [&] { return std::pow(10.0f, exponent(rng)); };
  return {v(), v(), v(), 0};
}

dev::f4 operator+(const dev::f4& a, const dev::f4& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w};
}

bool same_rgb(const dev::f4& a, const dev::f4& b) {
  return test::same_bits(a.x, b.x) && test::same_bits(a.y, b.y) && test::same_bits(a.z, b.z);
}

// Run lengths of one owner each; owners 1, 3, 4, 6, ... (some owners have nothing queued).
// Lengths around the local size (64) make runs cross work-group boundaries.
const std::vector<std::uint32_t> kRuns = {1, 3, 63, 64, 65, 1, 130, 2, 7, 200, 1, 64};

std::vector<std::uint32_t> run_owners() {
  std::vector<std::uint32_t> owners;
  std::uint32_t owner = 1;
  for (std::size_t r = 0; r < kRuns.size(); ++r) {
    owners.insert(owners.end(), kRuns[r], owner);
    owner += r % 3 == 1 ? 2 : 1;
  }
  return owners;
}

// A queue of `owners` preceded by `shift` entries owned by 0.
std::vector<std::uint32_t> shifted(const std::vector<std::uint32_t>& owners, std::uint32_t shift) {
  std::vector<std::uint32_t> out(shift, 0u);
  out.insert(out.end(), owners.begin(), owners.end());
  return out;
}

struct Sums {
  std::vector<dev::f4> values;  // per queue entry
  std::vector<dev::f4> start;   // per owner, before the launch
};

Sums random_sums(std::size_t entries, std::size_t owners, std::mt19937& rng) {
  Sums s;
  for (std::size_t i = 0; i < entries; ++i) s.values.push_back(random_colour(rng));
  for (std::size_t i = 0; i < owners; ++i) s.start.push_back(random_colour(rng));
  return s;
}

// Both kernels take (queue, a value per queue entry, entry count, a sum per owner) and add the
// values into the sums; these return the sums after the launch. gather_shadows reads its count
// from a device buffer (where compaction leaves it) and is launched, as in the renderer, over
// more work-items than that.
std::vector<dev::f4> gather_on_device(const std::vector<std::uint32_t>& owners, const Sums& s) {
  std::vector<dev::ShadowRay> shadows(owners.size());
  for (std::size_t i = 0; i < owners.size(); ++i) shadows[i].owner = owners[i];
  const auto count = static_cast<cl_uint>(owners.size());
  GatherShadowsArgs args;
  args.shadows = test::upload(shadows);
  args.visible = test::upload(s.values);
  args.count = test::upload(std::vector<cl_uint>{count});
  args.colour = test::upload(s.start);
  test::run(test::renderer_program(), args, count + 100);
  return test::download(args.colour, s.start.size());
}

std::vector<dev::f4> accumulate_on_device(const std::vector<std::uint32_t>& samples, const Sums& s) {
  std::vector<dev::Ray> rays(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) rays[i].sample = samples[i];
  AccumulateSamplesArgs args;
  args.rays = test::upload(rays);
  args.colour = test::upload(s.values);
  args.count = static_cast<cl_uint>(samples.size());
  args.sample_colour = test::upload(s.start);
  test::run(test::renderer_program(), args, samples.size());
  return test::download(args.sample_colour, s.start.size());
}

// gather_shadows: a ray's colour plus its shadow rays' contributions, one at a time in order.
std::vector<dev::f4> gather_on_host(const std::vector<std::uint32_t>& owners, const Sums& s) {
  std::vector<dev::f4> out = s.start;
  for (std::size_t i = 0; i < owners.size(); ++i) out[owners[i]] = out[owners[i]] + s.values[i];
  return out;
}

// accumulate_samples: the pass's colours of one sample summed in order, then added to what the
// sample gathered in earlier passes.
std::vector<dev::f4> accumulate_on_host(const std::vector<std::uint32_t>& samples, const Sums& s) {
  std::vector<dev::f4> out = s.start;
  for (std::size_t i = 0; i < samples.size();) {
    dev::f4 run = s.values[i];
    std::size_t j = i + 1;
    for (; j < samples.size() && samples[j] == samples[i]; ++j) run = run + s.values[j];
    out[samples[i]] = out[samples[i]] + run;
    i = j;
  }
  return out;
}

// The sums of owners 1.. are the same bits for the unshifted queue and shifted ones.
template <class Device>
void check_placement_independence(const std::vector<std::uint32_t>& owners, Device on_device,
                                  std::mt19937& rng) {
  const std::size_t owner_count = owners.back() + 1;
  const Sums base = random_sums(owners.size(), owner_count, rng);
  const std::vector<dev::f4> reference = on_device(owners, base);
  for (std::uint32_t shift : {1u, 17u, 64u, 100u}) {
    INFO("shifted by " << shift);
    Sums moved = random_sums(shift, 0, rng);
    moved.values.insert(moved.values.end(), base.values.begin(), base.values.end());
    moved.start = base.start;
    const std::vector<dev::f4> result = on_device(shifted(owners, shift), moved);
    for (std::size_t o = 1; o < owner_count; ++o) CHECK(same_rgb(result[o], reference[o]));
  }
}

}  // namespace

TEST_CASE("gather_shadows adds each owner's contributions in queue order", "[accumulate]") {
  std::mt19937 rng(3);
  const std::vector<std::uint32_t> owners = run_owners();
  const Sums s = random_sums(owners.size(), owners.back() + 1, rng);
  const std::vector<dev::f4> device = gather_on_device(owners, s);
  const std::vector<dev::f4> host = gather_on_host(owners, s);
  for (std::size_t o = 0; o < host.size(); ++o) {
    INFO("owner " << o);
    CHECK(same_rgb(device[o], host[o]));
  }

  SECTION("the check would see another order") {
    std::vector<std::uint32_t> reversed_owners(owners.rbegin(), owners.rend());
    Sums reversed = s;
    reversed.values.assign(s.values.rbegin(), s.values.rend());
    const std::vector<dev::f4> other = gather_on_host(reversed_owners, reversed);
    std::size_t differ = 0;
    for (std::size_t o = 0; o < host.size(); ++o) differ += !same_rgb(other[o], host[o]);
    CHECK(differ > 0);
  }
}

TEST_CASE("gather_shadows gives the same bits wherever a run sits in the queue", "[accumulate]") {
  std::mt19937 rng(4);
  check_placement_independence(run_owners(), gather_on_device, rng);
}

TEST_CASE("accumulate_samples adds each sample's rays in queue order", "[accumulate]") {
  std::mt19937 rng(5);
  const std::vector<std::uint32_t> samples = run_owners();
  const Sums s = random_sums(samples.size(), samples.back() + 1, rng);
  const std::vector<dev::f4> device = accumulate_on_device(samples, s);
  const std::vector<dev::f4> host = accumulate_on_host(samples, s);
  for (std::size_t o = 0; o < host.size(); ++o) {
    INFO("sample " << o);
    CHECK(same_rgb(device[o], host[o]));
  }
}

TEST_CASE("accumulate_samples gives the same bits wherever a run sits in the queue",
          "[accumulate]") {
  std::mt19937 rng(6);
  check_placement_independence(run_owners(), accumulate_on_device, rng);
}

TEST_CASE("resolve is the sum of each pixel's samples, left for the host to divide", "[accumulate]") {
  std::mt19937 rng(7);
  for (std::uint32_t samples : {1u, 4u, 6u}) {
    const std::uint32_t pixels = 70;
    std::vector<dev::f4> sample_colour;
    for (std::uint32_t i = 0; i < pixels * samples; ++i) sample_colour.push_back(random_colour(rng));
    ResolveArgs args;
    args.sample_colour = test::upload(sample_colour);
    args.samples = samples;
    args.pixel_count = pixels;
    args.pixels = test::allocate<dev::f4>(pixels);
    test::run(test::renderer_program(), args, pixels);
    const std::vector<dev::f4> result = test::download(args.pixels, pixels);
    for (std::uint32_t p = 0; p < pixels; ++p) {
      INFO("samples " << samples << ", pixel " << p);
      Vec3 sum;
      for (std::uint32_t k = 0; k < samples; ++k) sum = sum + test::vec_of(sample_colour[p * samples + k]);
      CHECK(result[p].x == Approx(sum.x).epsilon(1e-6));
      CHECK(result[p].y == Approx(sum.y).epsilon(1e-6));
      CHECK(result[p].z == Approx(sum.z).epsilon(1e-6));
      if (samples == 1) CHECK(same_rgb(result[p], sample_colour[p]));
    }
  }
}

TEST_CASE("resolve scales a sample brighter than the largest value down to it, hue kept",
          "[accumulate]") {
  // pbrt-v4's maxcomponentvalue: a sample whose largest channel exceeds the limit is multiplied
  // by limit / largest; the others are left as they are.
  const std::vector<dev::f4> sample_colour = {{1, 2, 4, 0}, {0.5f, 0.25f, 0.125f, 0}, {8, 1, 0, 0},
                                              {3, 3, 3, 0}};
  ResolveArgs args;
  args.sample_colour = test::upload(sample_colour);
  args.samples = 4;
  args.pixel_count = 1;
  args.max_sample_value = 2;
  args.pixels = test::allocate<dev::f4>(1);
  test::run(test::renderer_program(), args, 1);
  const dev::f4 result = test::download(args.pixels, 1)[0];
  const Vec3 expected = (Vec3{0.5, 1, 2} + Vec3{0.5, 0.25, 0.125} + Vec3{2, 0.25, 0} + Vec3{2, 2, 2});
  CHECK(result.x == Approx(expected.x).epsilon(1e-6));
  CHECK(result.y == Approx(expected.y).epsilon(1e-6));
  CHECK(result.z == Approx(expected.z).epsilon(1e-6));
}

// A pixel's samples resolved in rounds (src/render/sample_rounds.hpp): each round adds its
// samples to the sums the previous one left, and the result has the bits of one resolve over
// all samples.
std::vector<dev::f4> resolve_in_rounds(const std::vector<dev::f4>& sample_colour,
                                       std::uint32_t pixels, std::uint32_t samples,
                                       const std::vector<std::uint32_t>& round_sizes) {
  std::vector<dev::f4> sums(pixels);
  std::uint32_t first = 0;
  for (std::uint32_t count : round_sizes) {
    std::vector<dev::f4> round_colour;  // the wave's layout: pixel by pixel, count samples each
    for (std::uint32_t p = 0; p < pixels; ++p)
      for (std::uint32_t k = 0; k < count; ++k) round_colour.push_back(sample_colour[p * samples + first + k]);
    ResolveArgs args;
    args.sample_colour = test::upload(round_colour);
    args.samples = count;
    args.first_sample = first;
    args.pixel_count = pixels;
    args.pixels = test::upload(sums);
    test::run(test::renderer_program(), args, pixels);
    sums = test::download(args.pixels, pixels);
    first += count;
  }
  return sums;
}

TEST_CASE("resolve in rounds of samples gives the bits of one resolve", "[accumulate]") {
  std::mt19937 rng(8);
  const std::uint32_t pixels = 70, samples = 7;
  std::vector<dev::f4> sample_colour;
  for (std::uint32_t i = 0; i < pixels * samples; ++i) sample_colour.push_back(random_colour(rng));
  const std::vector<dev::f4> whole = resolve_in_rounds(sample_colour, pixels, samples, {7});
  for (const std::vector<std::uint32_t>& rounds :
       {std::vector<std::uint32_t>{1, 1, 1, 1, 1, 1, 1}, {3, 4}, {2, 2, 2, 1}, {6, 1}}) {
    const std::vector<dev::f4> split = resolve_in_rounds(sample_colour, pixels, samples, rounds);
    for (std::uint32_t p = 0; p < pixels; ++p) {
      INFO("rounds of " << rounds.size() << ", pixel " << p);
      CHECK(same_rgb(split[p], whole[p]));
    }
  }
  SECTION("the sums between rounds are the samples' sums in order") {
    std::vector<dev::f4> half = resolve_in_rounds(sample_colour, pixels, samples, {3});
    for (std::uint32_t p = 0; p < pixels; ++p) {
      const dev::f4* s = &sample_colour[p * samples];
      CHECK(same_rgb(half[p], s[0] + s[1] + s[2]));
    }
  }
}
