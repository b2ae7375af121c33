"""The triangles clrt makes of a Wavefront OBJ file (docs/scene-format.md, "Meshes"), for the
Mitsuba comparison: `v` and `f` lines (corners `v`, `v/vt`, `v//vn`, `v/vt/vn`, indices from 1
or counting back when negative), triangles and quads cut as clrt cuts them. Meshes that clrt
shades smoothly (a normal at every corner) and polygons of more than four corners (cut by ear
clipping) are refused, so that no mesh is compared in a form that quietly differs."""
import numpy as np


class MeshError(Exception):
    pass


def corner_index(word, so_far, count, number):
    """A positive index may name a vertex defined later; a negative one counts back from the
    vertices defined before its line."""
    index = int(word)
    if index < 0:
        index += so_far + 1
    if not 1 <= index <= count:
        raise MeshError(f"line {number}: index {word} names no element")
    return index - 1


def cut_quad(p):
    """clrt's cut: along 0-2 only when that diagonal is strictly shorter in single precision."""
    def squared(a, b):
        d = np.float32(a) - np.float32(b)
        return np.float32(d @ d)
    if squared(p[0], p[2]) < squared(p[1], p[3]):
        return [(0, 1, 2), (0, 2, 3)]
    return [(0, 1, 3), (1, 2, 3)]


def read_triangles(path):
    """The object-space corners of every triangle, a list of 3x3 arrays."""
    vertices, faces, normals, smooth = [], [], 0, True
    try:
        with open(path, encoding="utf-8") as f:
            lines = f.read().splitlines()
    except OSError as e:
        raise MeshError(f"{path}: {e.strerror}") from None
    for number, line in enumerate(lines, 1):
        words = line.split()
        if not words:
            continue
        if words[0] == "v":
            vertices.append([float(w) for w in words[1:4]])
        elif words[0] == "vn":
            normals += 1
        elif words[0] == "f":
            corners = [w.split("/") for w in words[1:]]
            smooth &= all(len(c) == 3 and c[2] != "" for c in corners)
            faces.append((number, [c[0] for c in corners], len(vertices)))
    if normals and smooth and faces:
        raise MeshError(f"{path}: every corner has a normal, so clrt shades it smoothly, "
                        "which the comparison does not read")
    triangles = []
    for number, words, so_far in faces:
        p = [np.array(vertices[corner_index(w, so_far, len(vertices), number)]) for w in words]
        if len(p) == 3:
            cuts = [(0, 1, 2)]
        elif len(p) == 4:
            cuts = cut_quad(p)
        else:
            raise MeshError(f"{path}:{number}: a face of {len(p)} corners (clrt cuts it by ear clipping, "
                            "which the comparison does not read)")
        triangles += [np.array([p[i] for i in cut]) for cut in cuts]
    if not triangles:
        raise MeshError(f"{path}: no triangles")
    return triangles
