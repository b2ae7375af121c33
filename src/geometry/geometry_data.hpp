// The scene's geometry flattened into the tables the device reads (see kernels/shared/scene.h
// and kernels/shared/bvh.h): instances with planes first, meshes, per-triangle normals and
// materials, and the BVH table, whose leaf packets carry the triangles' vertices.
#pragma once

#include <cstddef>
#include <vector>

#include "geometry/device_tables.hpp"
#include "scene/scene.hpp"
#include "shared/bvh.h"
#include "shared/scene.h"

namespace clrt {

struct GeometryData {
  DeviceTable<dev::Instance> instances;  // planes are [0, plane_count): they stay outside the BVH
  dev::u32 plane_count = 0;
  DeviceTable<dev::InstanceMotion> motions;  // one per moving instance (Instance.motion)
  DeviceTable<dev::Mesh> meshes;  // the scene's mesh files, then one mesh of the loose triangles
  // Per triangle, each mesh's triangles in the order of its BVH leaves, which is the order
  // Hit.primitive counts in (triangle_source maps them back to the file's order):
  DeviceTable<dev::TriangleNormals> triangle_normals;  // rows of the meshes with vertex normals
                                                       // (Mesh.normals)
  DeviceTable<dev::u32> triangle_materials;  // rows of the meshes whose triangles have
                                             // materials of their own (Instance.material_rows)
  DeviceTable<dev::TriangleTexcoords> triangle_texcoords;  // rows of the meshes whose triangles
                                                           // have coordinates (Mesh.texcoords)
  BvhTable nodes;                     // the top level's root is node 0
  // The glowing surfaces path mode samples (geometry/emitter_table.hpp), which the frame's light
  // table carries after the glow light's record; their total power, luminance times area.
  std::vector<dev::Emitter> emitters;
  double emitter_power = 0;
  double build_seconds = 0;                            // BVH build time, for --stats

  // Host-only maps back to the scene (the BVH build reorders instances and triangles):
  std::vector<int> instance_source;        // per instance: index in Scene::instances, -1 for the
                                           // loose-triangle mesh's instance
  std::vector<dev::u32> triangle_source;   // per triangle: its index within its MeshData (in
                                           // Scene::triangles for the loose-triangle mesh)
  std::vector<dev::u32> mesh_material_rows;  // per mesh: where its triangle_materials rows
                                             // start, or CLRT_NO_MATERIAL_ROWS

  std::size_t triangle_count() const;
  std::size_t device_bytes() const;
};

GeometryData build_geometry(const Scene& scene);

// The same tables for a render, which needs nothing else: what the build has read of `scene` is
// freed as it goes (each mesh's normals once its per-triangle rows hold them, before the BVH
// table, the build's largest allocation, is written; Scene::instances, left empty, before the top
// level is built; the rest of the meshes at the end, by release_mesh_data), and the host-only
// maps back to the scene are left empty. For a 1M-triangle mesh with normals the build's peak is
// 24 MB lower and the render's 4 MB; for 3M spheres, the instances' 500 MB are gone first.
GeometryData build_geometry_for_render(Scene& scene);

// Frees the positions, normals, texture coordinates and corners of `scene`'s meshes (each keeps
// its path): once build_geometry has run, its BVH table and per-triangle tables hold all the
// device needs, and nothing reads the meshes again.
void release_mesh_data(Scene& scene);

}  // namespace clrt
