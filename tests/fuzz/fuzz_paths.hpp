// The paths each fuzz target drives an input through, shared by the libFuzzer targets and by
// test_fuzz_regressions, which replays every input they found.
#pragma once

#include <string>

namespace clrt::fuzz {

enum class Outcome { Rejected, Accepted };

// Each reads the file at `path` the way clrt does. The reader's own error (SceneError, MeshError,
// ImageError) is Rejected. An accepted input that breaks what its reader promises throws
// std::logic_error; any other exception escapes. Both are findings.

// A .ray scene through the loader, the BVH build and the frame set-up.
Outcome ray_scene(const std::string& path);
// A .ray scene rendered in path mode at a few pixels, with both integrators, on the test
// device (CLRT_TEST_DEVICE, else the first CPU device): every value must be finite.
Outcome path_render(const std::string& path);
// An OBJ mesh through load_obj_mesh().
Outcome obj_mesh(const std::string& path);
// An image through read_image(), which picks the reader by the path's extension.
Outcome image(const std::string& path);
// The next three write their files in input_dir().
// A program cache entry: the file read through ProgramCache::load(), then the file's bytes
// stored as a payload and loaded back whole, and not at all once cut short by a byte.
Outcome program_cache_entry(const std::string& path);
// Tiles for `clrt-img stitch`: each line of the file is a placement text ("X,Y WxH of FWxFH");
// each tile is written as a PNG, its header read back, the frame checked from the headers, and
// the tiles read and stitched; every pixel of the frame must be its tile's.
Outcome stitch_tiles(const std::string& path);
// A polygon for the NFF and OBJ triangulator: after a first byte that picks flat (even) or not,
// every 2 bytes of the file a corner in the plane z = 0, or every 3 one anywhere. Accepted triangles index corners, have area and
// face the polygon's way; for a simple planar polygon their areas add up to its own.
Outcome polygon(const std::string& path);

}  // namespace clrt::fuzz
