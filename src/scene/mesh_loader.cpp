#include "scene/mesh_loader.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <optional>
#include <unordered_map>
#include <vector>

#include "math/parallel_for.hpp"
#include "image/input_file_checks.hpp"
#include "scene/limits.hpp"
#include "scene/obj_chunk.hpp"
#include "scene/obj_index_check.hpp"
#include "scene/obj_polygons.hpp"
#include "scene/polygon_triangulation.hpp"

namespace clrt {
namespace {

// Below this a slice is not worth a thread of its own.
constexpr std::size_t kMinSliceBytes = std::size_t{1} << 20;

// Whole lines, about equal in size: a few per core, so that a core that drew the quick lines
// (faces parse faster than vertices) takes another slice.
std::vector<std::string_view> split_into_slices(std::string_view text) {
  const std::size_t target = std::max(kMinSliceBytes, text.size() / (4 * parallel_threads()) + 1);
  std::vector<std::string_view> slices;
  while (!text.empty()) {
    std::size_t end = text.size();
    if (target < text.size()) {
      const auto* newline = static_cast<const char*>(std::memchr(text.data() + target, '\n', text.size() - target));
      if (newline) end = static_cast<std::size_t>(newline - text.data()) + 1;
    }
    slices.push_back(text.substr(0, end));
    text.remove_prefix(end);
  }
  return slices;
}

// What the slices before each one held, and the whole file's counts.
struct SliceStarts {
  std::vector<ObjCounts> elements;
  std::vector<std::size_t> corners, lines;
  ObjCounts total_elements;
  std::size_t total_corners = 0;
};

SliceStarts slice_starts(const std::vector<ObjChunk>& chunks) {
  SliceStarts s;
  std::size_t lines = 0;
  for (const ObjChunk& c : chunks) {
    s.elements.push_back(s.total_elements);
    s.corners.push_back(s.total_corners);
    s.lines.push_back(lines);
    s.total_elements.positions += c.positions.size();
    s.total_elements.texcoords += c.texcoords.size();
    s.total_elements.normals += c.normals.size();
    s.total_corners += c.corners.index.size();
    lines += c.lines;
  }
  return s;
}

SourceLocation location(const std::string& path, std::size_t lines_before, const ObjPlace& place) {
  return {path, static_cast<int>(lines_before + place.line + 1), static_cast<int>(place.column)};
}

[[noreturn]] void fail_at_first_problem(const std::string& path, const std::vector<ObjChunk>& chunks) {
  std::size_t lines = 0;
  for (const ObjChunk& c : chunks) {
    if (c.problem) throw MeshError(location(path, lines, c.problem->where), c.problem->message);
    lines += c.lines;
  }
  throw std::logic_error("fail_at_first_problem: no problem");
}

// A corner's index into one table: what messages call it, as written, and the file's count.
struct CornerIndex {
  std::string what;
  std::int64_t written;
  std::size_t count;
};

CornerIndex corner_index(ObjTable table, const ObjCornerSource& source, const ObjCounts& total) {
  switch (table) {
    case ObjTable::Position: return {"vertex", source.position, total.positions};
    case ObjTable::Texcoord: return {"texture coordinate", source.texcoord, total.texcoords};
    case ObjTable::Normal: return {"normal", source.normal, total.normals};
  }
  throw std::logic_error("corner_index: no such table");
}

[[noreturn]] void fail_at_corner(const std::string& path, std::string_view slice, std::size_t lines_before,
                                 const ObjBadCorner& bad, const ObjCounts& total) {
  const ObjCornerSource source = find_obj_corner(slice, bad.corner);
  const auto [what, written, count] = corner_index(bad.table, source, total);
  throw MeshError(location(path, lines_before, source.where),
                  written > 0 ? what + " index " + std::to_string(written) + " is out of range (the file has " +
                                    std::to_string(count) + ")"
                              : "relative " + what + " index " + std::to_string(written) +
                                    " reaches before the first one");
}

template <class T>
void release(std::vector<T>& v) {
  std::vector<T>().swap(v);
}

void copy_indices(std::vector<std::int32_t>& from, std::uint32_t* to) {
  std::transform(from.begin(), from.end(), to, [](std::int32_t i) { return static_cast<std::uint32_t>(i); });
  release(from);
}

// kNoMeshTexcoord for a corner that names none, as for every corner of a slice none of whose
// corners names one (it holds no indices: ObjChunk::corner_texcoords).
void copy_texcoord_indices(std::vector<std::int32_t>& from, std::size_t corners, std::uint32_t* to) {
  if (from.empty()) std::fill_n(to, corners, kNoMeshTexcoord);
  std::transform(from.begin(), from.end(), to, [](std::int32_t i) {
    return i == kObjNoIndex ? kNoMeshTexcoord : static_cast<std::uint32_t>(i);
  });
  release(from);
}

// Which optional tables the mesh keeps.
struct MeshTables {
  bool normals = false, texcoords = false, names = false;
};

// Moves every slice's elements into `mesh`, each slice's memory freed as soon as it is copied.
// Texture coordinate indices are copied per corner: a triangle with a corner naming none loses
// them only once its polygon is cut (keep_whole_triangle_texcoords).
void gather(std::vector<ObjChunk>& chunks, const SliceStarts& starts, const MeshTables& with, MeshData& mesh) {
  mesh.positions.resize(starts.total_elements.positions);
  mesh.corners.resize(starts.total_corners);
  if (with.normals) {
    mesh.normals.resize(starts.total_elements.normals);
    mesh.corner_normals.resize(starts.total_corners);
  }
  if (with.texcoords) {
    mesh.texcoords.resize(starts.total_elements.texcoords);
    mesh.corner_texcoords.resize(starts.total_corners);
  }
  parallel_for(chunks.size(), 1, [&](std::size_t i) {
    ObjChunk& c = chunks[i];
    const std::size_t corners = c.corners.index.size();
    std::copy(c.positions.begin(), c.positions.end(), mesh.positions.begin() + starts.elements[i].positions);
    release(c.positions);
    copy_indices(c.corners.index, mesh.corners.data() + starts.corners[i]);
    if (with.normals) {
      std::copy(c.normals.begin(), c.normals.end(), mesh.normals.begin() + starts.elements[i].normals);
      copy_indices(c.corner_normals.index, mesh.corner_normals.data() + starts.corners[i]);
    }
    release(c.normals);
    release(c.corner_normals.index);
    if (with.texcoords) {
      std::copy(c.texcoords.begin(), c.texcoords.end(), mesh.texcoords.begin() + starts.elements[i].texcoords);
      copy_texcoord_indices(c.corner_texcoords.index, corners, mesh.corner_texcoords.data() + starts.corners[i]);
    }
    release(c.texcoords);
    release(c.corner_texcoords.index);
  });
}

// Each triangle's `usemtl` name, the name in force carried from slice to slice.
void gather_material_names(const std::string& path, const std::vector<ObjChunk>& chunks,
                           const SliceStarts& starts, MeshData& mesh) {
  for (std::size_t i = 0; i < chunks.size(); ++i)
    for (const ObjLibraryRef& library : chunks[i].libraries)
      mesh.libraries.push_back({library.path, location(path, starts.lines[i], library.where)});
  if (std::all_of(chunks.begin(), chunks.end(), [](const ObjChunk& c) { return c.material_runs.empty(); }))
    return;
  std::unordered_map<std::string, std::uint32_t> index_of;
  mesh.triangle_names.assign(starts.total_corners / 3, kNoMeshMaterial);
  std::uint32_t current = kNoMeshMaterial;
  for (std::size_t i = 0; i < chunks.size(); ++i) {
    const ObjChunk& c = chunks[i];
    const std::size_t end = i + 1 < chunks.size() ? starts.corners[i + 1] : starts.total_corners;
    const std::size_t first = starts.corners[i] / 3, count = end / 3 - first;
    std::size_t from = 0;
    for (const ObjMaterialRun& run : c.material_runs) {
      std::fill(mesh.triangle_names.begin() + first + from, mesh.triangle_names.begin() + first + run.first_triangle,
                current);
      const auto known = index_of.emplace(run.name, static_cast<std::uint32_t>(mesh.material_names.size()));
      if (known.second) mesh.material_names.push_back({run.name, location(path, starts.lines[i], run.where)});
      current = known.first->second;
      from = run.first_triangle;
    }
    std::fill(mesh.triangle_names.begin() + first + from, mesh.triangle_names.begin() + first + count, current);
  }
}

// The mesh's tables once gathered.
std::uint64_t mesh_bytes(const SliceStarts& starts, const MeshTables& with) {
  const std::uint64_t per_corner = (std::uint64_t{1} + with.normals + with.texcoords) * sizeof(std::uint32_t);
  return (starts.total_elements.positions + (with.normals ? starts.total_elements.normals : 0)) * sizeof(Vec3) +
         (with.texcoords ? starts.total_elements.texcoords * sizeof(std::array<float, 2>) : 0) +
         starts.total_corners * per_corner + (with.names ? starts.total_corners / 3 * sizeof(std::uint32_t) : 0);
}

// A triangle keeps its texture coordinates only when all three corners name one, and the mesh
// keeps them only when a triangle does.
void keep_whole_triangle_texcoords(MeshData& mesh) {
  std::vector<std::uint32_t>& c = mesh.corner_texcoords;
  bool any = false;
  for (std::size_t t = 0; t < c.size(); t += 3) {
    if (c[t] == kNoMeshTexcoord || c[t + 1] == kNoMeshTexcoord || c[t + 2] == kNoMeshTexcoord)
      c[t] = c[t + 1] = c[t + 2] = kNoMeshTexcoord;
    else
      any = true;
  }
  if (!any) {
    release(mesh.texcoords);
    release(c);
  }
}

void check_gather_memory(const std::string& path, const std::vector<ObjChunk>& chunks, std::uint64_t mesh,
                         const MemoryLimit& memory) {
  std::uint64_t needed = mesh;
  for (const ObjChunk& c : chunks) needed += c.bytes();
  if (needed > memory.bytes)
    throw MeshError(path, "the mesh needs " + mebibytes(needed) + " to gather its tables, " +
                              mebibytes(memory.bytes) + " available (" + memory.source + ")");
}

}  // namespace

MeshError::MeshError(const std::string& path, const std::string& message)
    : std::runtime_error(path + ": " + message) {}

MeshError::MeshError(const SourceLocation& where, const std::string& message)
    : std::runtime_error(where.file + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) +
                         ": " + message) {}

MeshData load_obj_mesh(const std::string& path, const FileSource& files, const MemoryLimit& memory) {
  std::unique_ptr<FileBytes> file;
  try {
    file = files.open(path, limits::kMaxMeshFileBytes);
  } catch (const FileChangedError& e) {
    throw MeshError(path, e.what());
  } catch (const InputFileError& e) {
    throw MeshError(path, std::string("cannot be read (") + e.what() + ")");
  }
  const std::vector<std::string_view> slices = split_into_slices(without_byte_order_mark(file->text()));
  std::vector<ObjChunk> chunks(slices.size());
  ObjMemoryMeter meter;
  meter.available = memory.bytes;
  meter.source = memory.source;
  meter.used = file->text().size();
  parallel_for(slices.size(), 1, [&](std::size_t i) { chunks[i] = parse_obj_chunk(slices[i], meter); });
  if (std::any_of(chunks.begin(), chunks.end(), [](const ObjChunk& c) { return c.problem.has_value(); }))
    fail_at_first_problem(path, chunks);

  const SliceStarts starts = slice_starts(chunks);
  std::vector<std::optional<ObjBadCorner>> bad(chunks.size());
  parallel_for(chunks.size(), 1, [&](std::size_t i) {
    bad[i] = resolve_obj_indices(chunks[i], starts.elements[i], starts.total_elements);
  });
  for (std::size_t i = 0; i < chunks.size(); ++i)
    if (bad[i]) fail_at_corner(path, slices[i], starts.lines[i], *bad[i], starts.total_elements);
  if (starts.total_corners == 0) throw MeshError(path, "the mesh has no triangles");
  // Everything is parsed and checked: the file's pages go before gather holds the slices' tables
  // and the mesh's side by side (the peak of loading a large mesh).
  file.reset();

  MeshTables with;
  with.normals =
      std::all_of(chunks.begin(), chunks.end(), [](const ObjChunk& c) { return c.every_corner_has_normal; });
  with.texcoords =
      std::any_of(chunks.begin(), chunks.end(), [](const ObjChunk& c) { return !c.corner_texcoords.index.empty(); });
  with.names =
      std::any_of(chunks.begin(), chunks.end(), [](const ObjChunk& c) { return !c.material_runs.empty(); });
  check_gather_memory(path, chunks, mesh_bytes(starts, with), memory);
  MeshData mesh;
  mesh.path = path;
  gather_material_names(path, chunks, starts, mesh);
  gather(chunks, starts, with, mesh);
  // Per slice, its first polygon refused.
  std::vector<const ObjPolygon*> refused(chunks.size(), nullptr);
  parallel_for(chunks.size(), 1, [&](std::size_t i) {
    for (const ObjPolygon& p : chunks[i].polygons)
      if (!triangulate_polygon(mesh, starts.corners[i] + p.first_corner, p.corners)) {
        refused[i] = &p;
        return;
      }
  });
  for (std::size_t i = 0; i < chunks.size(); ++i)
    if (refused[i])
      throw MeshError(location(path, starts.lines[i], {refused[i]->line, 1}),
                      ConcavePolygonTooLarge(refused[i]->corners).what());
  keep_whole_triangle_texcoords(mesh);
  return mesh;
}

}  // namespace clrt
