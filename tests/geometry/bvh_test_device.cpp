#include "bvh_test_device.hpp"

#include "cl_fixture.hpp"
#include "geometry/device_geometry.hpp"

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

template <class Result>
std::vector<Result> run_queries(const char* kernel_name, const GeometryData& geometry,
                                const std::vector<TestRay>& rays) {
  const DeviceGeometry device_geometry(test::device(), geometry);
  compute::kernel kernel(test::test_program(kSource), kernel_name);
  const unsigned first = device_geometry.bind(kernel, 0);
  const compute::buffer ray_buffer = test::upload(pack(rays), "rays");
  const compute::buffer results = test::device().allocate(sizeof(Result) * rays.size(), "results");
  kernel.set_arg(first + 0, ray_buffer);
  kernel.set_arg(first + 1, static_cast<cl_uint>(rays.size()));
  kernel.set_arg(first + 2, results);
  test::run(kernel, rays.size());
  return test::download<Result>(results, rays.size());
}

}  // namespace

std::vector<dev::Hit> device_closest_hits(const GeometryData& geometry, const std::vector<TestRay>& rays) {
  return run_queries<dev::Hit>("bvh_closest_hits", geometry, rays);
}

std::vector<int> device_any_hits(const GeometryData& geometry, const std::vector<TestRay>& rays) {
  return run_queries<int>("bvh_any_hits", geometry, rays);
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
