// clrt-bench bvh: builds the two-level BVH of procedural or .ray scenes and measures
// scene_closest_hit and scene_any_hit on the device with camera rays and random rays. Prints a
// Markdown table: build time, the tree's SAH cost, BVH size, Mrays/s.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/whole_number.hpp"
#include "bench_scenes.hpp"
#include "bench_trace.hpp"
#include "commands.hpp"
#include "tree_cost.hpp"
#include "device/device_select.hpp"

namespace clrt::bench {
namespace {

struct Case {
  std::string name;
  std::function<Scene()> make;
  bool own_camera = false;  // a .ray file's camera, else one that frames the scene
};

std::vector<Case> suite() {
  std::vector<Case> cases;
  for (int n : {1000, 10000, 100000, 1000000, 4000000})
    cases.push_back({"mesh " + std::to_string(n / 1000) + "k tris", [n] { return mesh_scene(n); }});
  for (int n : {10, 100, 1000, 10000, 100000})
    cases.push_back({std::to_string(n) + " shapes", [n] { return shapes_scene(n); }});
  for (int n : {10, 100, 1000, 10000})
    cases.push_back({std::to_string(n) + " x 1k-tri mesh", [n] { return mesh_instances_scene(n); }});
  return cases;
}

double mib(std::size_t bytes) { return static_cast<double>(bytes) / (1024.0 * 1024.0); }

void run_case(DeviceContext& device, const Case& c, int ray_count, int runs) {
  const Scene scene = c.make();
  const auto tables = std::make_shared<const GeometryData>(build_geometry(scene));
  const GeometryData& geometry = *tables;
  const Box bounds = scene_bounds(geometry);
  const RaySet camera = camera_rays(c.own_camera ? scene.camera : camera_for(bounds), ray_count);
  const RaySet random = random_rays(bounds, ray_count);
  Tracer tracer(device, tables);
  const std::size_t triangles = geometry.triangle_count();
  // A build rate only where the triangles are the build's work: one mesh, placed once.
  const bool one_mesh = triangles > 0 && geometry.instances.size() == 1;
  char rate[32] = "-";
  if (one_mesh) std::snprintf(rate, sizeof rate, "%.2f", static_cast<double>(triangles) / geometry.build_seconds / 1e6);
  std::printf("| %s | %zu | %zu | %.1f | %s | %.1f | %zu | %.2f | %.2f |", c.name.c_str(), geometry.instances.size(),
              triangles, geometry.build_seconds * 1e3, rate, sah_cost(geometry.nodes), geometry.nodes.size(),
              mib(geometry.nodes.size() * sizeof(dev::BvhNode)), mib(geometry.device_bytes()));
  for (const Throughput& t : {tracer.closest_hit_mrays(camera, runs), tracer.closest_hit_mrays(random, runs),
                              tracer.any_hit_mrays(camera, runs), tracer.any_hit_mrays(random, runs)})
    std::printf(" %.1f (%.1f) |", t.wall, t.per_core);
  std::printf("\n");
  std::fflush(stdout);
}

struct BvhOptions {
  std::vector<std::string> files;
  int ray_count = 1 << 20;
  int runs = 3;
  std::string device_spec = "cpu";
  bool with_suite = false;
  std::string only;
};

int measure_bvh(const BvhOptions& o) {
  std::vector<Case> cases;
  if (o.with_suite || o.files.empty()) cases = suite();
  for (const std::string& f : o.files) cases.push_back({f, [f] { return load_scene(f); }, true});
  DeviceContext device(select_devices(o.device_spec).front());
  std::printf("%d rays per measurement on %s; Mrays/s elapsed (per CPU-second), best of %d\n\n", o.ray_count,
              device.name().c_str(), o.runs);
  std::printf("| scene | instances | triangles | build ms | build Mtris/s | SAH cost | nodes | BVH MiB | all MiB | "
              "closest camera | closest random | any camera | any random |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Case& c : cases)
    if (c.name.find(o.only) != std::string::npos) run_case(device, c, o.ray_count, o.runs);
  return 0;
}

}  // namespace

void add_bvh(CLI::App& app, Command& run) {
  // Shared, because CLI11 keeps references to the fields until the command runs.
  const auto o = std::make_shared<BvhOptions>();
  CLI::App* bvh = app.add_subcommand("bvh", "BVH build time, size and ray throughput");
  bvh->add_option("scenes", o->files, ".ray files to measure (their own cameras are used)");
  bvh->add_flag("--suite", o->with_suite,
                "procedural meshes of 1k-1M triangles and 10-100k instances (default without scenes)");
  bvh->add_option("--rays", o->ray_count, "rays per measurement")
      ->transform(whole_number(1, 1 << 30))
      ->capture_default_str();
  bvh->add_option("--runs", o->runs, "timed launches per measurement; the best counts")
      ->transform(whole_number(1, 1000))
      ->capture_default_str();
  bvh->add_option("--only", o->only, "run only the cases whose name contains this");
  bvh->add_option("--device", o->device_spec, "OpenCL device (cpu, gpu, P:D or a name)")->capture_default_str();
  bvh->callback([o, &run] { run = [o] { return measure_bvh(*o); }; });
}

}  // namespace clrt::bench
