// classify_hits (kernels/sort_hits.cl) against the host's reading of the shading classes: one
// launch writes every class's flag set, stride apart, with exactly one class flagged per ray
// (a miss, local shading only, or a mirror or glass surface), and leaves the slots between the
// sets alone.
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include "cl_fixture.hpp"
#include "render/stage_args.hpp"
#include "shared/ray.h"

using namespace clrt;

namespace {

constexpr std::uint32_t kStale = 0xabu;  // what the flag buffer holds before the launch

dev::Material material(float kr, float kt) {
  dev::Material m{};
  m.color = {1, 1, 1, 0};
  m.kd = 0.8f;
  m.kr = kr;
  m.kt = kt;
  m.ior = 1.5f;
  return m;
}

// 0 miss, 1 local, 2 mirror or glass, as the host reads the material table.
std::uint32_t host_class(const dev::Hit& hit, const std::vector<dev::Material>& materials) {
  if (hit.instance == CLRT_NO_HIT) return 0;
  const dev::Material& m = materials[hit.material];
  return m.kr > 0 || m.kt > 0 ? 2 : 1;
}

}  // namespace

TEST_CASE("classify_hits flags every class of a chunk in one launch") {
  // Local, mirror, glass, both, and a negative kr (read as no mirror).
  const std::vector<dev::Material> materials = {material(0, 0), material(0.5f, 0),
                                                material(0, 0.9f), material(0.3f, 0.3f),
                                                material(-0.2f, 0)};
  constexpr std::uint32_t kRays = 1000, kFirst = 123, kCount = 700, kStride = 1024;
  std::vector<dev::Hit> hits(kRays);
  for (std::uint32_t i = 0; i < kRays; ++i) {
    hits[i].instance = i % 7 == 3 ? CLRT_NO_HIT : i;
    hits[i].material = (i * 2654435761u >> 7) % materials.size();
  }
  const auto indices = test::allocate<cl_uint4>(kCount);
  const auto flags = test::upload(std::vector<cl_uint>(CLRT_SHADE_CLASSES * kStride, kStale));
  ClassifyHitsArgs args;
  args.materials = test::upload(materials);
  args.hits = test::upload(hits);
  args.first = kFirst;
  args.count = kCount;
  args.stride = kStride;
  args.indices = indices;
  args.flags = flags;
  test::run(test::renderer_program(), args, kCount);

  const std::vector<cl_uint4> got_indices = test::download(indices, kCount);
  const std::vector<cl_uint> got = test::download(flags, CLRT_SHADE_CLASSES * kStride);
  std::uint32_t per_class[CLRT_SHADE_CLASSES] = {};
  for (std::uint32_t j = 0; j < kCount; ++j) {
    INFO("ray " << kFirst + j);
    CHECK(got_indices[j].s[0] == kFirst + j);
    const std::uint32_t wanted = host_class(hits[kFirst + j], materials);
    ++per_class[wanted];
    for (std::uint32_t k = 0; k < CLRT_SHADE_CLASSES; ++k)
      CHECK(got[k * kStride + j] == (k == wanted ? 1u : 0u));
  }
  for (std::uint32_t k = 0; k < CLRT_SHADE_CLASSES; ++k) {
    CHECK(per_class[k] > 0);  // every class is exercised
    for (std::uint32_t j = kCount; j < kStride; ++j) CHECK(got[k * kStride + j] == kStale);
  }
}
