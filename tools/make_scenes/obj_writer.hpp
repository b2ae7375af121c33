// Wavefront OBJ output of a TriangleMesh: positions, vertex normals and `f a//a b//b c//c`.
#pragma once

#include <string>

#include "torus_knot.hpp"

namespace clrt::scenes {

void write_obj(const std::string& path, const TriangleMesh& mesh);

}  // namespace clrt::scenes
