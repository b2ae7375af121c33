#include "bvh_test_device.hpp"

#include <memory>

#include "cl_fixture.hpp"
#include "geometry/bvh_query_args.hpp"

namespace clrt::bvhtest {
namespace {

const char* const kSource = "#include \"geometry/bvh_query_kernels.h\"\n";

// Origin with w = tmin, then direction with w = tmax, per ray.
std::vector<dev::f4> pack(const std::vector<TestRay>& rays) {
  std::vector<dev::f4> out;
  for (const TestRay& r : rays) {
    out.push_back({static_cast<float>(r.o.x), static_cast<float>(r.o.y), static_cast<float>(r.o.z),
                   static_cast<float>(r.tmin)});
    out.push_back({static_cast<float>(r.d.x), static_cast<float>(r.d.y), static_cast<float>(r.d.z),
                   static_cast<float>(r.tmax)});
  }
  return out;
}

template <class Args, class Result>
std::vector<Result> run_queries(const GeometryData& geometry, const std::vector<TestRay>& rays,
                                Global<Result> Args::*results) {
  const DeviceGeometry device_geometry(test::device(), std::make_shared<const GeometryData>(geometry));
  Args args;
  args.scene = device_geometry.args();
  args.rays = test::upload(pack(rays), "rays");
  args.count = static_cast<cl_uint>(rays.size());
  args.*results = test::allocate<Result>(rays.size(), "results");
  test::run(test::test_program(kSource), args, rays.size());
  return test::download(args.*results, rays.size());
}

}  // namespace

std::vector<dev::Hit> device_closest_hits(const GeometryData& geometry, const std::vector<TestRay>& rays) {
  return run_queries(geometry, rays, &BvhClosestHitsArgs::hits);
}

std::vector<int> device_any_hits(const GeometryData& geometry, const std::vector<TestRay>& rays) {
  return run_queries(geometry, rays, &BvhAnyHitsArgs::results);
}

ObjectId hit_object(const GeometryData& geometry, const dev::Hit& hit) {
  const dev::Instance& inst = geometry.instances.at(hit.instance);
  ObjectId id;
  id.instance = geometry.instance_source.at(hit.instance);
  if (inst.shape == CLRT_SHAPE_MESH) {
    const dev::Mesh& mesh = geometry.meshes.at(inst.mesh);
    id.triangle = static_cast<int>(geometry.triangle_source.at(mesh.first_triangle + hit.primitive));
  }
  return id;
}

}  // namespace clrt::bvhtest
