#!/usr/bin/env python3
"""ray_to_mitsuba.py SCENE.ray [--spp N] [--resolution WxH] [--seed S]

Reads a clrt `.ray` scene and builds the Mitsuba 3 scene that renders the same image as
`clrt --mode path`, following docs/path-tracing.md (units, the four material lobes and their
weights) and docs/scene-format.md (camera, transforms). Only the subset the comparison scenes
need is read; anything else is refused with FILE:LINE: error, so that a scene is never compared
against a Mitsuba scene that quietly differs from it. Run with the Mitsuba venv's python
(tools/mitsuba/install.sh); it prints the scene dictionary it built, for a look at the mapping.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import obj_mesh  # noqa: E402

# clrt's `maxdepth` counts bounces after the camera ray and still takes next-event estimation
# at the last vertex, so a path of D bounces carries light over D + 2 segments (camera to the
# first hit, D bounces, the shadow ray). Mitsuba's max_depth counts those segments: 1 shows
# only emitters seen directly, 2 is direct lighting. docs/path-tracing.md says how this was
# checked.
DEPTH_OFFSET = 2

# Mitsuba has no endless plane: a `plane` becomes a square this many times wider than the
# scene's extent (its objects, lights and eye), centred under the eye. From inside the scene,
# the strip of sky it leaves below the horizon is under 1e-3 radians high. Wider squares meet
# Mitsuba's single precision: at 1e4 a tilted floor shadowed itself.
PLANE_EXTENT = 1e3

# The two faces of an area light are separate one-sided rectangles; each is pushed this far
# (relative to the light's size) along its own normal, so that a ray from either side meets
# the face turned towards it first and a shadow ray to one face is never blocked by the other.
AREA_FACE_GAP = 1e-5


class SceneError(Exception):
    pass


class Material:
    """A `.ray` material as the lobe weights of docs/path-tracing.md."""

    def __init__(self, color, kd, ks, n, kr, kt, ior):
        local = max(0.0, 1.0 - kr - kt)
        diffuse = local * kd * np.asarray(color, dtype=float)
        glossy, mirror, glass = local * ks, kr, kt
        if min(diffuse.min(), glossy) < 0:
            raise SceneError("negative kd, ks or colour: no physical BSDF to compare with")
        largest = (diffuse + glossy + mirror + glass).max()
        s = 1.0 / largest if largest > 1.0 else 1.0
        self.diffuse, self.glossy, self.mirror, self.glass = s * diffuse, s * glossy, s * mirror, s * glass
        self.exponent = n
        self.ior = ior if ior > 0 else 1.0


DEFAULT_MATERIAL = Material((1, 1, 1), 0.8, 0.0, 1.0, 0.0, 0.0, 1.0)


def rgb(values):
    return {"type": "rgb", "value": [float(v) for v in values]}


def one_sided(bsdf):
    """clrt's surfaces reflect on both sides; Mitsuba's reflecting BSDFs only on the front."""
    return {"type": "twosided", "bsdf": bsdf}


def mitsuba_bsdf(material):
    """The sum of the material's lobes, each with its own weight (lobes.py's clrt_lobes)."""
    lobes = []
    if material.diffuse.max() > 0:
        lobes.append((material.diffuse.mean(),
                      one_sided({"type": "diffuse", "reflectance": rgb(material.diffuse)})))
    if material.glossy > 0:
        lobes.append((material.glossy,
                      one_sided({"type": "clrt_phong", "weight": material.glossy,
                                 "exponent": float(material.exponent)})))
    if material.mirror > 0:
        lobes.append((material.mirror,
                      one_sided({"type": "conductor", "material": "none",
                                 "specular_reflectance": rgb([material.mirror] * 3)})))
    if material.glass > 0:
        lobes.append((material.glass,
                      {"type": "dielectric", "int_ior": material.ior, "ext_ior": 1.0,
                       "specular_reflectance": rgb([material.glass] * 3),
                       "specular_transmittance": rgb([material.glass] * 3)}))
    if not lobes:
        return one_sided({"type": "diffuse", "reflectance": rgb([0, 0, 0])})
    if len(lobes) == 1:
        return lobes[0][1]
    # Lobes are drawn as clrt draws them, in proportion to their weights averaged over the
    # channels; any choice would do, as each sample is divided by its chance.
    total = sum(p for p, _ in lobes)
    d = {"type": "clrt_lobes"}
    for i, (p, lobe) in enumerate(lobes):
        d[f"lobe_{i}"], d[f"chance_{i}"] = lobe, float(p / total)
    return d


def needs_plugins(material):
    return material.glossy > 0 or sum(w > 0 for w in (material.diffuse.max(), material.mirror, material.glass)) > 1


class RayScene:
    """The subset of the `.ray` format the Mitsuba comparison reads (docs/scene-format.md)."""

    def __init__(self, path):
        self.path = path
        self.eye, self.lookat, self.up = np.array([0.0, 0, 5]), np.zeros(3), np.array([0.0, 1, 0])
        self.fov, self.background = 60.0, np.zeros(3)
        self.resolution, self.samples, self.maxdepth = (500, 300), 1, 5
        self.material, self.transform = DEFAULT_MATERIAL, np.eye(4)
        self.spheres, self.triangles, self.lights, self.planes, self.cubes = [], [], [], [], []
        self.cylinders = []
        with open(path, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                words = line.split("#", 1)[0].split()
                if words:
                    try:
                        self.command(words[0].lower(), words[1:])
                    except (SceneError, ValueError) as e:
                        raise SceneError(f"{path}:{number}: error: {e}") from None

    def command(self, name, args):
        def numbers(*counts):
            if len(args) not in counts:
                raise SceneError(f"`{name}` takes {' or '.join(map(str, counts))} numbers, found {len(args)}")
            return [float(a) for a in args]

        def whole(value):
            if value != int(value) or value < 0:
                raise SceneError(f"`{name}` needs a whole number, found {value}")
            return int(value)

        if name in ("eye", "lookat", "up"):
            setattr(self, name, np.array(numbers(3)))
        elif name == "fov":
            self.fov = numbers(1)[0]
        elif name == "background":
            self.background = np.array(numbers(3))
        elif name == "resolution":
            self.resolution = tuple(whole(v) for v in numbers(2))
        elif name == "samples":
            self.samples = whole(numbers(1)[0])
        elif name == "maxdepth":
            self.maxdepth = whole(numbers(1)[0])
        elif name in ("material", "surface"):
            v = numbers(9, 10, 11)
            if len(v) == 11:
                del v[3]
            color, (_ka, kd, ks, n, kr, kt), ior = v[0:3], v[3:9], v[9] if len(v) == 10 else 1.0
            self.material = Material(color, kd, ks, n, kr, kt, ior)
        elif name == "reset":
            numbers(0)
            self.transform = np.eye(4)
        elif name == "translate":
            m = np.eye(4)
            m[:3, 3] = numbers(3)
            self.transform = m @ self.transform
        elif name == "scale":
            m = np.diag(numbers(3) + [1.0])
            self.transform = m @ self.transform
        elif name == "rotate":
            v = numbers(4)
            self.transform = rotation(v[0], np.array(v[1:])) @ self.transform
        elif name in ("rotatex", "rotatey", "rotatez"):
            self.transform = rotation(numbers(1)[0], np.eye(3)["xyz".index(name[-1])]) @ self.transform
        elif name == "plane":
            numbers(0)
            self.planes.append((self.material, self.transform))
        elif name == "cube":
            numbers(0)
            self.check_front()
            self.cubes.append((self.material, self.transform))
        elif name == "mesh":
            if len(args) != 1:
                raise SceneError("`mesh` takes one path")
            self.check_front()
            obj = os.path.join(os.path.dirname(self.path), args[0].strip('"'))
            try:
                triangles = obj_mesh.read_triangles(obj)
            except obj_mesh.MeshError as e:
                raise SceneError(f"bad mesh file {e}") from None
            for corners in triangles:
                world = (self.transform @ np.c_[corners, np.ones(3)].T).T[:, :3]
                self.triangles.append((self.material, world))
        elif name == "sphere":
            v = numbers(0, 4) or [0.0, 0.0, 0.0, 1.0]
            self.add_sphere(np.array(v[:3]), v[3])
        elif name == "triangle":
            corners = np.array(numbers(9)).reshape(3, 3)
            world = (self.transform @ np.c_[corners, np.ones(3)].T).T[:, :3]
            self.triangles.append((self.material, world))
        elif name == "light":
            self.add_light(args)
        elif name == "cylinder":
            numbers(0)
            self.cylinders.append((self.material, cylinder_placement(self.transform)))
        elif name == "cone":
            raise SceneError("`cone` has no Mitsuba shape, so the Mitsuba comparison does not read it")
        else:
            raise SceneError(f"`{name}` is not supported by the Mitsuba comparison")

    def check_front(self):
        # clrt maps a mirrored object's normals by (M^-1)^T, keeping its front; Mitsuba takes a
        # mesh's front from its winding in world space, which the mirror turns inside out.
        if self.material.glass > 0 and np.linalg.det(self.transform[:3, :3]) < 0:
            raise SceneError("a glass cube or mesh under a mirroring transform is inside out in Mitsuba")

    def materials(self):
        return [m for m, *_ in self.spheres] + [m for m, _ in self.triangles + self.planes + self.cubes + self.cylinders]

    def extent(self):
        """The radius, about the eye, of a ball holding the scene's objects and lights."""
        points = [self.eye] + [c for _, c, _ in self.spheres] + [p for _, t in self.triangles for p in t]
        points += [t[:3, 3] for _, t in self.planes + self.cubes] + [v[:3] for k, _, v in self.lights if k != "directional"]
        reach = [np.linalg.norm(p - self.eye) for p in points] + [r for *_, r in self.spheres]
        reach += [np.linalg.norm(t[:3, :3], 2) * np.sqrt(3) for _, t in self.cubes]
        reach += [np.linalg.norm(c[0] - self.eye) + np.linalg.norm(c[1] - c[0]) + c[2] for _, c in self.cylinders]
        return max(reach) or 1.0

    def add_sphere(self, centre, radius):
        linear = self.transform[:3, :3]
        scale = abs(np.linalg.det(linear)) ** (1.0 / 3.0)
        if not np.allclose(linear.T @ linear, scale * scale * np.eye(3), rtol=1e-6, atol=1e-9):
            raise SceneError("a sphere under a non-uniform scale is an ellipsoid, which the comparison does not read")
        self.spheres.append((self.material, (self.transform @ np.r_[centre, 1.0])[:3], radius * scale))

    def add_light(self, args):
        if len(args) < 4:
            raise SceneError("`light` needs a colour and a kind")
        color, kind, v = np.array([float(a) for a in args[:3]]), args[3].lower(), [float(a) for a in args[4:]]
        counts = {"point": (3,), "directional": (3,), "area": (9, 10), "ambient": (0,)}
        if kind not in counts:
            raise SceneError(f"`{kind}` lights are not supported by the Mitsuba comparison")
        if len(v) not in counts[kind]:
            raise SceneError(f"a {kind} light takes {' or '.join(map(str, counts[kind]))} numbers after its kind")
        if kind == "ambient":
            print(f"{self.path}: note: ambient lights are not used in path mode", file=sys.stderr)
            return
        self.lights.append((kind, color, np.array(v[:9])))


def rotation(degrees, axis):
    """The 4x4 matrix turning by `degrees` about `axis`, counter-clockwise (right-hand rule)."""
    if not np.any(axis):
        raise SceneError("the rotation axis must not be zero")
    x, y, z = axis / np.linalg.norm(axis)
    c, s = np.cos(np.radians(degrees)), np.sin(np.radians(degrees))
    cross = np.array([[0, -z, y], [z, 0, -x], [-y, x, 0]])
    m = np.eye(4)
    m[:3, :3] = c * np.eye(3) + s * cross + (1 - c) * np.outer([x, y, z], [x, y, z])
    return m


def cylinder_placement(placement):
    """The ends and radius of clrt's cylinder (radius 1 about y, y in [-1, 1]) placed by
    `placement`, which Mitsuba's cylinder can follow only without shear and with one radius."""
    radial_x, axis, radial_z = (placement[:3, i] for i in range(3))
    radius = np.linalg.norm(radial_x)
    for u, v in ((radial_x, axis), (radial_z, axis), (radial_x, radial_z)):
        if abs(u @ v) > 1e-9 * np.linalg.norm(u) * np.linalg.norm(v):
            raise SceneError("a cylinder under a shear is not round, which the comparison does not read")
    if not np.isclose(np.linalg.norm(radial_z), radius, rtol=1e-9):
        raise SceneError("a cylinder scaled differently across its axis is elliptic, which the comparison does not read")
    return placement[:3, 3] - axis, placement[:3, 3] + axis, radius


def cylinder_shapes(material, ends):
    """Mitsuba's `cylinder`, which has no caps, closed by two `disk`s facing outwards."""
    bottom, top, radius = ends
    axis = (top - bottom) / np.linalg.norm(top - bottom)
    shapes = [{"type": "cylinder", "p0": bottom.tolist(), "p1": top.tolist(), "radius": radius,
               "bsdf": mitsuba_bsdf(material)}]
    for centre, normal in ((bottom, -axis), (top, axis)):
        shapes.append({"type": "disk", "to_world": facing(normal, centre, radius), "bsdf": mitsuba_bsdf(material)})
    return shapes


def facing(normal, centre, size):
    """The to_world taking Mitsuba's flat shapes (the unit disk or the square [-1, 1]^2 in z = 0,
    facing +z) to `centre`, facing `normal` (unit), `size` times larger: a rotation and a
    uniform scale, which Mitsuba inverts accurately in single precision."""
    helper = np.eye(3)[np.argmin(np.abs(normal))]
    u = np.cross(helper, normal)
    u /= np.linalg.norm(u)
    m = np.eye(4)
    m[:3, 0], m[:3, 1], m[:3, 2], m[:3, 3] = size * u, size * np.cross(normal, u), size * normal, centre
    return transform(m)


def plane_rectangle(material, placement, eye, extent):
    """clrt's endless plane y = 0 (front +y) placed by `placement` as a wide square."""
    # The placed plane is the world plane through M 0 with normal (M^-1)^T (0, 1, 0). The square
    # is built from that plane alone: the placement times a huge scale along two axes only is
    # too ill-conditioned for Mitsuba's single precision (a tilted plane came out displaced,
    # shadowing itself).
    normal = np.linalg.inv(placement[:3, :3]).T @ [0.0, 1.0, 0.0]
    normal /= np.linalg.norm(normal)
    origin = placement[:3, 3]
    # Centred on the point of the plane nearest to the eye.
    foot = eye - ((eye - origin) @ normal) * normal
    return {"type": "rectangle", "bsdf": mitsuba_bsdf(material),
            "to_world": facing(normal, foot, extent * PLANE_EXTENT)}


def transform(matrix):
    import mitsuba as mi
    return mi.ScalarTransform4f(np.asarray(matrix, dtype=float).tolist())


def area_light_faces(color, geometry):
    """Two one-sided emitting rectangles, back to back, for clrt's two-sided area light."""
    corner, u, v = geometry[0:3], geometry[3:6], geometry[6:9]
    normal = np.cross(u, v)
    if np.linalg.norm(normal) == 0:
        raise SceneError("an area light with parallel edges has no area")
    normal /= np.linalg.norm(normal)
    gap = AREA_FACE_GAP * max(np.linalg.norm(u), np.linalg.norm(v))
    faces = []
    for side in (1.0, -1.0):
        # Mitsuba's rectangle is [-1, 1]^2 in z = 0 facing +z; map it onto the parallelogram,
        # with z along the face's normal (a mirrored frame for the back face flips it).
        m = np.eye(4)
        m[:3, 0], m[:3, 1], m[:3, 2] = u / 2, side * v / 2, side * normal
        m[:3, 3] = corner + (u + v) / 2 + side * gap * normal
        faces.append({"type": "rectangle", "to_world": transform(m),
                      # What lies behind an area light is hidden in Mitsuba (it is a surface)
                      # but seen in clrt; a black surface gives both the same image when
                      # nothing but black lies behind it, as in the comparison scenes.
                      "bsdf": one_sided({"type": "diffuse", "reflectance": rgb([0, 0, 0])}),
                      "emitter": {"type": "area", "radiance": rgb(color)}})
    return faces


def triangle_mesh(material, corners):
    import mitsuba as mi
    mesh = mi.Mesh("triangles", 3 * len(corners), len(corners),
                   has_vertex_normals=False, has_vertex_texcoords=False)
    params = mi.traverse(mesh)
    params["vertex_positions"] = np.concatenate(corners).ravel().tolist()
    params["faces"] = list(range(3 * len(corners)))
    params.update()
    mesh.set_bsdf(mi.load_dict(mitsuba_bsdf(material)))
    return mesh


def to_mitsuba(scene, spp=None, resolution=None, seed=0):
    """The mi.load_dict dictionary of `scene`; needs mitsuba imported with a variant set."""
    width, height = resolution or scene.resolution
    spp = spp or scene.samples
    max_depth = scene.maxdepth + DEPTH_OFFSET
    import mitsuba as mi
    if any(needs_plugins(m) for m in scene.materials()):
        if not mi.variant().startswith("scalar"):
            raise SceneError("the Phong lobe and mixed materials (lobes.py) run in Mitsuba's scalar variants only")
        import lobes
        lobes.register()
    d = {
        "type": "scene",
        # Russian roulette would only add noise: the expectation is the same, so it starts
        # past the deepest path.
        "integrator": {"type": "path", "max_depth": max_depth, "rr_depth": max_depth + 1},
        "sensor": {
            "type": "perspective", "fov": scene.fov, "fov_axis": "x",
            # clrt's camera rays ignore hits closer than epsilon, 1e-4.
            "near_clip": 1e-4, "far_clip": 1e7,
            "to_world": mi.ScalarTransform4f().look_at(origin=scene.eye.tolist(), target=scene.lookat.tolist(),
                                                       up=scene.up.tolist()),
            "sampler": {"type": "independent", "sample_count": spp, "seed": seed},
            # clrt averages samples drawn uniformly over each pixel's square: a box filter.
            "film": {"type": "hdrfilm", "width": width, "height": height, "rfilter": {"type": "box"},
                     "pixel_format": "rgb", "component_format": "float32"},
        },
    }
    if scene.background.max() > 0:
        d["background"] = {"type": "constant", "radiance": rgb(scene.background)}
    for i, (material, centre, radius) in enumerate(scene.spheres):
        d[f"sphere_{i}"] = {"type": "sphere", "center": centre.tolist(), "radius": radius,
                            "bsdf": mitsuba_bsdf(material)}
    for i, (material, placement) in enumerate(scene.planes):
        d[f"plane_{i}"] = plane_rectangle(material, placement, scene.eye, scene.extent())
    for i, (material, placement) in enumerate(scene.cubes):
        # Both are the box [-1, 1]^3, its faces flat, with the outside as the front.
        d[f"cube_{i}"] = {"type": "cube", "to_world": transform(placement), "bsdf": mitsuba_bsdf(material)}
    for i, (material, ends) in enumerate(scene.cylinders):
        for j, shape in enumerate(cylinder_shapes(material, ends)):
            d[f"cylinder_{i}_{j}"] = shape
    groups = {}
    for material, corners in scene.triangles:
        groups.setdefault(id(material), (material, []))[1].append(corners)
    for i, (material, corners) in enumerate(groups.values()):
        d[f"triangles_{i}"] = triangle_mesh(material, corners)
    for i, (kind, color, v) in enumerate(scene.lights):
        if kind == "point":
            d[f"light_{i}"] = {"type": "point", "position": v[:3].tolist(), "intensity": rgb(color)}
        elif kind == "directional":
            d[f"light_{i}"] = {"type": "directional", "direction": v[:3].tolist(), "irradiance": rgb(color)}
        else:
            for j, face in enumerate(area_light_faces(color, v)):
                d[f"light_{i}_{j}"] = face
    return d


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene")
    parser.add_argument("--spp", type=int)
    parser.add_argument("--resolution", help="WxH")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    import mitsuba as mi
    mi.set_variant("scalar_rgb")
    try:
        scene = RayScene(args.scene)
        d = to_mitsuba(scene, args.spp, parse_resolution(args.resolution), args.seed)
    except SceneError as e:
        sys.exit(str(e))
    for key, value in d.items():
        print(f"{key}: {value}")


def parse_resolution(text):
    if text is None:
        return None
    w, _, h = text.lower().partition("x")
    return int(w), int(h)


if __name__ == "__main__":
    main()
