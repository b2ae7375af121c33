#!/usr/bin/env python3
"""ray_to_mitsuba.py SCENE [--clrt CLRT] [--spp N] [--resolution WxH] [--seed S] [--time T]

Builds the Mitsuba 3 scene that renders the same image as `clrt --mode path` from the scene as
clrt itself reads it (`clrt --dump-scene`, docs/scene-json.md), following docs/path-tracing.md
(units, the four material lobes and their weights) and docs/scene-format.md (camera,
transforms). What Mitsuba cannot render as clrt does is refused with FILE:LINE:COLUMN: error,
so that a scene is never compared against a Mitsuba scene that quietly differs from it. Run
with the Mitsuba venv's python (tools/mitsuba/install.sh); it prints the scene dictionary it
built, for a look at the mapping.

Mitsuba's scene is static: a scene with moving objects (`endpose`) is built for one time of the
shutter, each moving object at its pose then (pose_at). clrt's motion blur is the average of
such static images over the shutter, which render_reference.py estimates by rendering each
sub-render at its own time.
"""
import argparse
import functools
import json
import os
import pathlib
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

# The clrt the README's quick start builds.
DEFAULT_CLRT = pathlib.Path(__file__).resolve().parents[2] / "build" / "clrt"

# The version of clrt's scene dump this converter reads.
SCENE_JSON_VERSION = 2

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

# The (u, v) of a triangle's corners where the scene gives none (docs/scene-format.md).
DEFAULT_UV = ((0.0, 0.0), (1.0, 0.0), (0.0, 1.0))


class SceneError(Exception):
    pass


class Material:
    """A `.ray` material as the lobe weights of docs/path-tracing.md."""

    def __init__(self, color, kd, ks, n, kr, kt, ior, emission=(0, 0, 0), textures=None):
        self.emission = np.asarray(emission, dtype=float)
        # Per textured term ("color", "ks", "kr", "kt"): the dumped texture that multiplies it.
        self.textures = textures or {}
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


def rgb(values):
    return {"type": "rgb", "value": [float(v) for v in values]}


def one_sided(bsdf):
    """clrt's surfaces reflect on both sides; Mitsuba's reflecting BSDFs only on the front."""
    return {"type": "twosided", "bsdf": bsdf}


def bitmap(texture):
    """Mitsuba's `bitmap` for a clrt image texture: the same file, decoded by Mitsuba (sRGB to
    linear for an 8-bit image, raw=False) into single precision ("variant"; its default keeps
    8-bit images in half precision), interpolated bilinearly without mip levels, wrapped alike.
    clrt's (s, t) = (u su + ou, v sv + ov) has t = 0 at the image's bottom row, Mitsuba's v = 0
    its top row (measured), so to_uv also turns t into 1 - t."""
    import mitsuba as mi
    (su, sv), (ou, ov) = texture["scale"], texture["offset"]
    to_uv = mi.ScalarTransform3f([[su, 0.0, ou], [0.0, -sv, 1.0 - ov], [0.0, 0.0, 1.0]])
    return {"type": "bitmap", "filename": texture["file"], "filter_type": "bilinear",
            "wrap_mode": texture["wrap"], "raw": False, "format": "variant", "to_uv": to_uv}


def reflectance(material):
    """The Lambertian lobe's reflectance: check_texture lets a textured colour through only
    where the lobe's weight is 1, the texel itself."""
    texture = material.textures.get("color")
    return bitmap(texture) if texture else rgb(material.diffuse)


def mitsuba_bsdf(material):
    """The sum of the material's lobes, each with its own weight (lobes.py's clrt_lobes)."""
    lobes = []
    if material.diffuse.max() > 0:
        lobes.append((material.diffuse.mean(),
                      one_sided({"type": "diffuse", "reflectance": reflectance(material)})))
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


def glowing(shape, material):
    """`shape` with an area emitter of the material's emission: both clrt's glow and Mitsuba's
    `area` emitter leave the front only."""
    if material.emission.max() > 0:
        shape["emitter"] = {"type": "area", "radiance": rgb(material.emission)}
    return shape


def needs_plugins(material):
    return material.glossy > 0 or sum(w > 0 for w in (material.diffuse.max(), material.mirror, material.glass)) > 1


class DumpedScene:
    """The scene as clrt read it (`clrt --dump-scene`, docs/scene-json.md), in the form the
    Mitsuba scene is built from: spheres, planes, cubes and cylinders with their placements,
    triangles in world space with their corners' (u, v), lights. What the comparison cannot
    match is refused with the object's FILE:LINE:COLUMN. Moving objects stand at their poses at
    `time` (by default the middle of the shutter: one instant, not the blurred image)."""

    def __init__(self, dump, time=None):
        if dump.get("format") != "clrt-scene" or dump.get("version") != SCENE_JSON_VERSION:
            raise SceneError(f"not a clrt scene dump of version {SCENE_JSON_VERSION}")
        self.path = dump["scene"]
        camera = dump["camera"]
        self.eye, self.lookat, self.up = (np.array(camera[k], dtype=float) for k in ("eye", "lookat", "up"))
        self.fov, self.background = camera["fov_degrees"], np.array(dump["background"], dtype=float)
        self.lens_radius, self.focus_distance = camera["lens_radius"], camera["focus_distance"]
        self.shutter = tuple(float(v) for v in camera.get("shutter", (0.0, 1.0)))
        self.moving = any("end_transform" in placed for placed in dump["objects"])
        self.time = sum(self.shutter) / 2 if time is None else float(time)
        self.resolution, self.samples, self.maxdepth = tuple(dump["resolution"]), dump["samples"], dump["maxdepth"]
        self.environment = dump.get("environment")
        # One object per material, so that triangles group by the material they were given.
        self.all_materials = [Material(m["color"], m["kd"], m["ks"], m["shininess"], m["kr"], m["kt"], m["ior"],
                                       m["emission"], {slot: dump["textures"][i] for slot, i in m["textures"].items()})
                              for m in dump["materials"]]
        self.spheres, self.triangles, self.lights, self.planes, self.cubes = [], [], [], [], []
        # The (u, v) of each triangle's corners, in step with `triangles`, whose (material, corners)
        # pairs the Cycles converter reads too.
        self.triangle_uvs = []
        self.cylinders = []
        self.meshes = dump["meshes"]
        for placed in dump["objects"]:
            try:
                placement = np.array(placed["transform"], dtype=float)
                if "end_transform" in placed:
                    placement = pose_at(placement, np.array(placed["end_transform"], dtype=float), self.time)
                self.add_object(placed, self.all_materials[placed["material"]], placement)
            except SceneError as e:
                raise SceneError(f"{self.path}:{placed['line']}:{placed['column']}: error: {e}") from None
        # Loose triangles and lights have no place in the dump: their errors name the file.
        try:
            for triangle in dump["triangles"]:
                self.place_triangle(self.all_materials[triangle["material"]],
                                    np.array(triangle["corners"], dtype=float),
                                    np.array(triangle.get("uv", DEFAULT_UV), dtype=float))
            for light in dump["lights"]:
                self.add_light(light)
        except SceneError as e:
            raise SceneError(f"{self.path}: error: {e}") from None

    def add_object(self, placed, material, placement):
        shape = placed["shape"]
        if shape != "mesh" and material.textures:
            raise SceneError(f"a textured `{shape}`: its (u, v) are not Mitsuba's, so the comparison textures "
                             "triangles and meshes only")
        if shape == "sphere":
            self.add_sphere(material, placement)
        elif shape == "plane":
            self.planes.append((material, placement))
        elif shape == "cube":
            check_front(material, placement)
            self.cubes.append((material, placement))
        elif shape == "cylinder":
            self.cylinders.append((material, cylinder_placement(placement)))
        elif shape == "mesh":
            mesh = self.meshes[placed["mesh"]]
            if mesh["normals"]:
                raise SceneError(f"{mesh['path']}: every corner has a normal, so clrt shades it smoothly, "
                                 "which the comparison does not read")
            # An MTL material where the triangle's `usemtl` names one and the object keeps them.
            own = mesh.get("triangle_materials", []) if placed.get("mtl", False) else []
            materials = [self.all_materials[m] if m >= 0 else material for m in own] or [material] * len(mesh["triangles"])
            for m in {id(m): m for m in materials}.values():
                check_front(m, placement)
            corners = np.array(mesh["positions"], dtype=float)[np.array(mesh["triangles"])]
            world = corners @ placement[:3, :3].T + placement[:3, 3]
            for triangle_material, triangle, uv in zip(materials, world, mesh_uvs(mesh)):
                self.place_triangle(triangle_material, triangle, uv)
        else:
            raise SceneError(f"`{shape}` has no Mitsuba shape, so the Mitsuba comparison does not read it")

    def place_triangle(self, material, corners, uv):
        """A triangle and its corners' (u, v); add_triangle is the step subclasses refine."""
        check_texture(material)
        self.add_triangle(material, corners)
        self.triangle_uvs.append(uv)

    def add_triangle(self, material, corners):
        self.triangles.append((material, corners))

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

    def anything_in_front(self, origin, normal):
        """Whether the eye or any object reaches strictly into the half-space in front of the
        plane through `origin` facing `normal` (unit)."""
        margin = 1e-6 * max(1.0, float(np.abs(origin).max()))

        def ahead(points, reach=0.0):
            points = np.asarray(points, dtype=float).reshape(-1, 3)
            return points.size > 0 and float(((points - origin) @ normal + reach).max()) > margin

        def plane_ahead(placement):
            # An endless plane reaches every side but the one it is parallel to.
            plane_normal = np.linalg.inv(placement[:3, :3]).T @ [0.0, 1.0, 0.0]
            plane_normal /= np.linalg.norm(plane_normal)
            return abs(float(plane_normal @ normal)) < 1 - 1e-9 or ahead(placement[:3, 3])

        cube_corners = np.array([[x, y, z, 1.0] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)])
        return (any(plane_ahead(t) for _, t in self.planes) or ahead(self.eye)
                or any(ahead(c, r) for _, c, r in self.spheres)
                or ahead([t for _, t in self.triangles])
                or any(ahead((cube_corners @ t.T)[:, :3]) for _, t in self.cubes)
                or any(ahead(c[:2], c[2]) for _, c in self.cylinders))

    def add_sphere(self, material, placement):
        """clrt's unit sphere placed by `placement`, which a Mitsuba sphere follows only under a
        uniform scale."""
        linear = placement[:3, :3]
        scale = abs(np.linalg.det(linear)) ** (1.0 / 3.0)
        if not np.allclose(linear.T @ linear, scale * scale * np.eye(3), rtol=1e-6, atol=1e-9):
            raise SceneError("a sphere under a non-uniform scale is an ellipsoid, which the comparison does not read")
        self.spheres.append((material, placement[:3, 3], scale))

    def add_light(self, light):
        kind, color = light["kind"], np.array(light["color"], dtype=float)
        if kind == "ambient":
            print(f"{self.path}: note: ambient lights are not used in path mode", file=sys.stderr)
        elif kind == "point":
            self.lights.append((kind, color, np.array(light["position"], dtype=float)))
        elif kind == "directional":
            self.lights.append((kind, color, np.array(light["direction"], dtype=float)))
        elif kind == "area":
            self.lights.append((kind, color, np.concatenate([light[k] for k in ("corner", "edge_u", "edge_v")])))
        else:
            raise SceneError(f"`{kind}` lights are not supported by the Mitsuba comparison")


def polar(linear):
    """(R, S) with linear = R S, R a rotation and S symmetric: the polar decomposition, from
    the SVD U diag(sigma) V^T as U V^T and V diag(sigma) V^T. A mirroring matrix gives U V^T of
    determinant -1; its negative is a rotation, and the stretch takes the sign, as clrt splits
    it, so that two mirrored poses interpolate through mirrored poses."""
    u, sigma, vt = np.linalg.svd(linear)
    rotation, stretch = u @ vt, vt.T @ np.diag(sigma) @ vt
    if np.linalg.det(rotation) < 0:
        rotation, stretch = -rotation, -stretch
    return rotation, stretch


def quaternion(rotation):
    """The unit quaternion (w, x, y, z) of a rotation matrix. The component of largest
    magnitude is found first from the diagonal and the others divided by it, so that none is
    taken from the square root of a difference near zero."""
    r = rotation
    diagonal = [np.trace(r), r[0, 0], r[1, 1], r[2, 2]]
    i = int(np.argmax(diagonal))
    if i == 0:
        w = np.sqrt(max(0.0, 1.0 + diagonal[0])) / 2
        q = [w, (r[2, 1] - r[1, 2]) / (4 * w), (r[0, 2] - r[2, 0]) / (4 * w), (r[1, 0] - r[0, 1]) / (4 * w)]
    elif i == 1:
        x = np.sqrt(max(0.0, 1.0 + r[0, 0] - r[1, 1] - r[2, 2])) / 2
        q = [(r[2, 1] - r[1, 2]) / (4 * x), x, (r[0, 1] + r[1, 0]) / (4 * x), (r[0, 2] + r[2, 0]) / (4 * x)]
    elif i == 2:
        y = np.sqrt(max(0.0, 1.0 - r[0, 0] + r[1, 1] - r[2, 2])) / 2
        q = [(r[0, 2] - r[2, 0]) / (4 * y), (r[0, 1] + r[1, 0]) / (4 * y), y, (r[1, 2] + r[2, 1]) / (4 * y)]
    else:
        z = np.sqrt(max(0.0, 1.0 - r[0, 0] - r[1, 1] + r[2, 2])) / 2
        q = [(r[1, 0] - r[0, 1]) / (4 * z), (r[0, 2] + r[2, 0]) / (4 * z), (r[1, 2] + r[2, 1]) / (4 * z), z]
    q = np.array(q)
    return q / np.linalg.norm(q)


def rotation_matrix(q):
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def slerp(q0, q1, t):
    """The rotation a fraction t of the way from q0 to q1 at constant angular speed, the
    shorter way round: q and -q are one rotation, and the pair at an obtuse angle would go
    the long way."""
    cos = float(q0 @ q1)
    if cos < 0:
        q1, cos = -q1, -cos
    angle = np.arccos(min(1.0, cos))
    if angle < 1e-9:
        # sin(angle) vanishes; the arc is a straight segment to within rounding.
        q = (1 - t) * q0 + t * q1
    else:
        q = (np.sin((1 - t) * angle) * q0 + np.sin(t * angle) * q1) / np.sin(angle)
    return q / np.linalg.norm(q)


def pose_at(start, end, time):
    """A moving object's 4x4 placement at `time`, between its pose `start` at time 0 and `end`
    at time 1 (held outside [0, 1]), as docs/scene-format.md's Motion section moves it: each
    pose split into M = T R S, T and S interpolated linearly, R by slerp."""
    t = min(max(time, 0.0), 1.0)
    if t == 0.0:
        return start
    if t == 1.0:
        return end
    (r0, s0), (r1, s1) = polar(start[:3, :3]), polar(end[:3, :3])
    m = np.eye(4)
    m[:3, :3] = rotation_matrix(slerp(quaternion(r0), quaternion(r1), t)) @ ((1 - t) * s0 + t * s1)
    m[:3, 3] = (1 - t) * start[:3, 3] + t * end[:3, 3]
    return m


def check_front(material, placement):
    # clrt maps a mirrored object's normals by (M^-1)^T, keeping its front; Mitsuba takes a
    # mesh's front from its winding in world space, which the mirror turns inside out.
    if (material.glass > 0 or material.emission.max() > 0) and np.linalg.det(placement[:3, :3]) < 0:
        raise SceneError("a glass or glowing cube or mesh under a mirroring transform is inside out in Mitsuba")


def mesh_uvs(mesh):
    """Per triangle of a dumped mesh, the (u, v) of its corners: the file's `vt`, or clrt's
    default where a triangle names none."""
    texcoords = np.array(mesh["texcoords"], dtype=float).reshape(-1, 2)
    named = mesh["triangle_texcoords"] or [None] * len(mesh["triangles"])
    return [np.array(DEFAULT_UV) if corners is None else texcoords[corners] for corners in named]


def check_texture(material):
    """Refuses the textures the comparison does not carry over: it needs one case, an image on
    the colour of a white Lambertian material (Mitsuba's bitmap cannot be scaled by a weight)."""
    if set(material.textures) - {"color"}:
        raise SceneError("textures of ks, kr or kt are not carried over to Mitsuba")
    texture = material.textures.get("color")
    if texture is None:
        return
    if texture["kind"] != "image":
        raise SceneError(f"`{texture['kind']}` textures have no Mitsuba counterpart; the comparison reads images")
    if material.diffuse.tolist() != [1.0, 1.0, 1.0] or max(material.glossy, material.mirror, material.glass) > 0:
        raise SceneError("a textured colour is compared on a white Lambertian material only (colour 1 1 1 and "
                         "kd 1, or an MTL's Kd 1 1 1, with no ks, kr or kt): Mitsuba's bitmap takes no weight")
    check_image(texture["file"], texture["linear"])


# Once per image, not per triangle.
@functools.lru_cache(maxsize=None)
def check_image(path, linear):
    """Refuses an image that Mitsuba would not read as clrt does: clrt reads PNG and PPM as 8-bit
    sRGB (a 16-bit one too, Mitsuba all 16 bits); a linear texel above 1 makes clrt scale the
    lobe down, as for any weight above 1, where Mitsuba's `diffuse` reflects more than it gets."""
    import mitsuba as mi
    image = mi.Bitmap(path)
    if linear:
        if np.array(image).max() > 1:
            raise SceneError(f"{path}: a texel above 1 (clrt scales such a lobe down, Mitsuba does not)")
    elif image.component_format() != mi.Struct.Type.UInt8 or not image.srgb_gamma():
        raise SceneError(f"{path}: not 8-bit sRGB to Mitsuba, which would decode it otherwise than clrt")


def dump_scene(clrt, path):
    """`path` (.ray or .nff) as clrt reads it: the dictionary of `clrt --dump-scene`."""
    done = subprocess.run([str(clrt), "--dump-scene", "-", str(path)], stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        raise SceneError(done.stderr.strip() or f"{clrt} --dump-scene exited with {done.returncode}")
    return json.loads(done.stdout)


def read_scene(clrt, path, kind=DumpedScene, **options):
    return kind(dump_scene(clrt, path), **options)


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
    shapes = [glowing({"type": "cylinder", "p0": bottom.tolist(), "p1": top.tolist(), "radius": radius,
                       "bsdf": mitsuba_bsdf(material)}, material)]
    for centre, normal in ((bottom, -axis), (top, axis)):
        shapes.append(glowing({"type": "disk", "to_world": facing(normal, centre, radius),
                               "bsdf": mitsuba_bsdf(material)}, material))
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
    return glowing({"type": "rectangle", "bsdf": mitsuba_bsdf(material),
                    "to_world": facing(normal, foot, extent * PLANE_EXTENT)}, material)


def transform(matrix):
    import mitsuba as mi
    return mi.ScalarTransform4f(np.asarray(matrix, dtype=float).tolist())


def area_light_faces(color, geometry, seen=lambda origin, normal: True):
    """Two one-sided emitting rectangles, back to back, for clrt's two-sided area light; a face
    that `seen(centre, normal)` says nothing is in front of (no object it could light, not the
    eye) is left out: it adds nothing to the image, and Mitsuba, which picks one emitter per light
    sample, would spend samples on it."""
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
        if not seen(corner + (u + v) / 2, side * normal):
            continue
        faces.append({"type": "rectangle", "to_world": transform(m),
                      # What lies behind an area light is hidden in Mitsuba (it is a surface)
                      # but seen in clrt; a black surface gives both the same image when
                      # nothing but black lies behind it, as in the comparison scenes.
                      "bsdf": one_sided({"type": "diffuse", "reflectance": rgb([0, 0, 0])}),
                      "emitter": {"type": "area", "radiance": rgb(color)}})
    return faces


# Mitsuba's envmap interpolates between pixels; clrt's pixels are constant over their part of the
# sphere. The converter hands Mitsuba the clrt image this many times finer along each axis, which
# confines the difference to bands a 32nd of a pixel wide.
ENVIRONMENT_REFINEMENT = 32


def environment_emitter(env):
    """Mitsuba's `envmap` for clrt's `environment`: the same orientation (both map (x, y, z) to
    u = atan2(x, -z) / 2 pi, v = acos(y) / pi), the rotation as `to_world`, the scale, and the
    image refined so that Mitsuba's interpolation reproduces clrt's constant pixels."""
    import mitsuba as mi
    bitmap = mi.Bitmap(env["file"])
    srgb = env["file"].lower().endswith((".png", ".ppm"))
    bitmap = bitmap.convert(mi.Bitmap.PixelFormat.RGB, mi.Struct.Type.Float32, srgb_gamma=False) if srgb \
        else bitmap.convert(mi.Bitmap.PixelFormat.RGB, mi.Struct.Type.Float32)
    pixels = np.array(bitmap, dtype=np.float32)
    f = ENVIRONMENT_REFINEMENT
    # Across, Mitsuba puts fine column i at the centre of its cell, u = (i + 1/2) / width, as
    # clrt's pixels are laid out: each pixel becomes f columns. Down, it puts fine row k at
    # v = k / (height - 1) (measured: its rows are vertices, the first at the top, the last at the
    # bottom), so each holds clrt's mean over the span of v about it, mixing two rows where a clrt
    # pixel's edge crosses that span.
    fine_columns = pixels.repeat(f, axis=1)
    height = pixels.shape[0]
    rows = height * f
    half = 0.5 / (rows - 1)
    fine = np.zeros((rows, fine_columns.shape[1], 3), dtype=np.float64)
    for k in range(rows):
        lo, hi = max(0.0, k / (rows - 1) - half), min(1.0, k / (rows - 1) + half)
        for j in range(int(lo * height), min(height - 1, int(hi * height)) + 1):
            overlap = min(hi, (j + 1) / height) - max(lo, j / height)
            if overlap > 0:
                fine[k] += overlap / (hi - lo) * fine_columns[j]
    fine = fine.astype(np.float32)
    rotation = np.array(env["rotation"], dtype=float)
    rotation[:3, 3] = 0
    return {"type": "envmap", "bitmap": mi.Bitmap(np.ascontiguousarray(fine)), "scale": float(env["scale"]),
            "to_world": transform(rotation)}


def triangle_mesh(material, corners, uvs):
    import mitsuba as mi
    # A mesh made here takes its emitter from its properties (it has no set_emitter).
    props = mi.Properties()
    if material.emission.max() > 0:
        props["emitter"] = mi.load_dict(glowing({}, material)["emitter"])
    textured = bool(material.textures)
    mesh = mi.Mesh("triangles", 3 * len(corners), len(corners), props=props,
                   has_vertex_normals=False, has_vertex_texcoords=textured)
    params = mi.traverse(mesh)

    # Handed over as arrays of the parameters' own types: through Python lists, the 100k
    # triangles of the race's knot took 2 s.
    def array(key, values, dtype):
        return type(params[key])(np.ascontiguousarray(values, dtype=dtype).ravel())

    params["vertex_positions"] = array("vertex_positions", np.concatenate(corners), np.float32)
    if textured:
        params["vertex_texcoords"] = array("vertex_texcoords", np.concatenate(uvs), np.float32)
    params["faces"] = array("faces", np.arange(3 * len(corners)), np.uint32)
    params.update()
    mesh.set_bsdf(mi.load_dict(mitsuba_bsdf(material)))
    return mesh


def to_mitsuba(scene, spp=None, resolution=None, seed=0, russian_roulette=False, sampler="independent"):
    """The mi.load_dict dictionary of `scene`; needs mitsuba imported with a variant set.
    `russian_roulette` keeps the path integrator's own (from its fifth vertex on); `sampler` is
    the Mitsuba sampler plugin's name."""
    width, height = resolution or scene.resolution
    spp = spp or scene.samples
    max_depth = scene.maxdepth + DEPTH_OFFSET
    import mitsuba as mi
    if any(needs_plugins(m) for m in {id(m): m for m in scene.materials()}.values()):
        if not mi.variant().startswith("scalar"):
            raise SceneError("the Phong lobe and mixed materials (lobes.py) run in Mitsuba's scalar variants only")
        import lobes
        lobes.register()
    d = {
        "type": "scene",
        # For a reference, Russian roulette would only add noise: the expectation is the same,
        # so it starts past the deepest path.
        "integrator": {"type": "path", "max_depth": max_depth,
                       **({} if russian_roulette else {"rr_depth": max_depth + 1})},
        "sensor": {
            # Mitsuba's thin lens puts the plane in focus across the view axis, as clrt's does.
            **({"type": "thinlens", "aperture_radius": scene.lens_radius,
                "focus_distance": scene.focus_distance} if scene.lens_radius > 0 else {"type": "perspective"}),
            "fov": scene.fov, "fov_axis": "x",
            # clrt's camera rays ignore hits closer than epsilon, 1e-4.
            "near_clip": 1e-4, "far_clip": 1e7,
            "to_world": mi.ScalarTransform4f().look_at(origin=scene.eye.tolist(), target=scene.lookat.tolist(),
                                                       up=scene.up.tolist()),
            "sampler": {"type": sampler, "sample_count": spp, "seed": seed},
            # clrt averages samples drawn uniformly over each pixel's square: a box filter.
            "film": {"type": "hdrfilm", "width": width, "height": height, "rfilter": {"type": "box"},
                     "pixel_format": "rgb", "component_format": "float32"},
        },
    }
    if scene.environment:
        d["environment"] = environment_emitter(scene.environment)
    elif scene.background.max() > 0:
        d["background"] = {"type": "constant", "radiance": rgb(scene.background)}
    for i, (material, centre, radius) in enumerate(scene.spheres):
        d[f"sphere_{i}"] = glowing({"type": "sphere", "center": centre.tolist(), "radius": radius,
                                    "bsdf": mitsuba_bsdf(material)}, material)
    for i, (material, placement) in enumerate(scene.planes):
        d[f"plane_{i}"] = plane_rectangle(material, placement, scene.eye, scene.extent())
    for i, (material, placement) in enumerate(scene.cubes):
        # Both are the box [-1, 1]^3, its faces flat, with the outside as the front.
        d[f"cube_{i}"] = glowing({"type": "cube", "to_world": transform(placement), "bsdf": mitsuba_bsdf(material)},
                                 material)
    for i, (material, ends) in enumerate(scene.cylinders):
        for j, shape in enumerate(cylinder_shapes(material, ends)):
            d[f"cylinder_{i}_{j}"] = shape
    groups = {}
    for (material, corners), uv in zip(scene.triangles, scene.triangle_uvs):
        _, group_corners, group_uvs = groups.setdefault(id(material), (material, [], []))
        group_corners.append(corners)
        group_uvs.append(uv)
    for i, (material, corners, uvs) in enumerate(groups.values()):
        d[f"triangles_{i}"] = triangle_mesh(material, corners, uvs)
    for i, (kind, color, v) in enumerate(scene.lights):
        if kind == "point":
            d[f"light_{i}"] = {"type": "point", "position": v[:3].tolist(), "intensity": rgb(color)}
        elif kind == "directional":
            d[f"light_{i}"] = {"type": "directional", "direction": v[:3].tolist(), "irradiance": rgb(color)}
        else:
            for j, face in enumerate(area_light_faces(color, v, scene.anything_in_front)):
                d[f"light_{i}_{j}"] = face
    return d


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene", help="a .ray or .nff file")
    parser.add_argument("--clrt", default=DEFAULT_CLRT, help="the clrt that reads it (default: build/clrt)")
    parser.add_argument("--spp", type=int)
    parser.add_argument("--resolution", help="WxH")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--time", type=float, help="the time to pose moving objects at (default: mid-shutter)")
    args = parser.parse_args()
    import mitsuba as mi
    mi.set_variant("scalar_rgb")
    try:
        scene = read_scene(args.clrt, args.scene, time=args.time)
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
