#!/usr/bin/env python3
"""ray_to_cycles.py SCENE -o OUT.exr [--clrt CLRT] [--spp N] [--resolution WxH] [--seed S] [--threads T]

Builds, in Blender's Python module (PyPI `bpy` 4.5, installed by install.sh into
BUILD/cycles-venv), the Cycles scene that estimates the same image as `clrt --mode path`, and
renders it to a linear 32-bit float EXR comparable with clrt's `--exr-pixel float` EXR. The
scene is the one clrt itself reads (`clrt --dump-scene`, docs/scene-json.md), taken apart by
tools/mitsuba/ray_to_mitsuba.py's DumpedScene as for the Mitsuba comparison; README.md beside
this file says how each item maps and how the units were checked. What Cycles cannot be made
to render identically (Phong, mirror and glass lobes, cylinders, cones, spot lights) is
refused with FILE:LINE:COLUMN: error, never approximated.

Run with the venv's python. Prints one JSON line on standard output: the render call's time
(`render_s`: bpy.ops.render.render, which syncs the scene, builds the BVH, renders and writes
the EXR), the time spent building the scene in bpy (`build_s`), and the settings used.
"""
import argparse
import json
import math
import os
import pathlib
import sys
import time

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "mitsuba"))
import ray_to_mitsuba as rtm  # noqa: E402  (DumpedScene, SceneError, the plane's stand-in)

SceneError = rtm.SceneError

# A point light of Blender power P (W) has, in Cycles, the radiant intensity P / (4 pi) W/sr:
# Cycles' point light evaluates strength * 1/(4 pi) / d^2. clrt's `light r g b point` is a
# radiant intensity (r, g, b), so P = 4 pi I. Checked numerically: scenes/units_point.ray
# (a floor under a point light, nothing else) has the same image mean in both renderers to
# within the noise (README.md, "Units").
POINT_POWER_PER_INTENSITY = 4.0 * math.pi

# Cycles' max_bounces counts bounces after the camera ray, and its last vertex still takes
# light samples and sends a BSDF ray that only gathers emission (MIS), exactly clrt's maxdepth
# (docs/path-tracing.md, "The depth cap"): max_bounces = maxdepth. The per-kind limits are set
# to the same value so that no kind stops earlier. Passing through an area light (a
# transparent surface) is a transparent bounce, counted apart; its limit is set high enough
# that no path is cut by passing through lights.
TRANSPARENT_BOUNCES = 256


class CyclesScene(rtm.DumpedScene):
    """DumpedScene that refuses, with the object's place, what Cycles cannot render as clrt does."""

    def __init__(self, dump):
        super().__init__(dump)
        if self.lens_radius > 0:
            raise SceneError("the thin lens (`lens`) is not mapped to Cycles (its aperture is set "
                             "by an f-number of the focal length in millimetres)")
        if self.environment:
            raise SceneError("an `environment` image is not mapped to Cycles yet")

    def add_object(self, placed, material, placement):
        if "end_transform" in placed:
            raise SceneError("moving objects (`endpose`) are not mapped to Cycles yet")
        if placed["shape"] == "cylinder":
            raise SceneError("`cylinder` is not mapped to Cycles (no capped-cylinder primitive; "
                             "a tessellation would differ at the silhouette)")
        if placed["shape"] == "cone":
            raise SceneError("`cone` is not mapped to Cycles (no cone primitive)")
        check_material(material)
        super().add_object(placed, material, placement)

    def add_triangle(self, material, corners):
        check_material(material)
        super().add_triangle(material, corners)

    def add_light(self, light):
        if light["kind"] == "spot":
            raise SceneError("spot lights are not mapped to Cycles (its spot fades by a blend "
                             "between two angles, clrt's by (S.D)^exp)")
        super().add_light(light)


def check_material(material):
    if material.textures:
        raise SceneError("textured materials (`texture`, MTL maps) are not mapped to Cycles yet")
    if material.emission.max() > 0:
        raise SceneError("glowing materials (`emission`) are not mapped to Cycles yet")
    lobes = [("a Phong lobe (ks)", material.glossy), ("a mirror lobe (kr)", material.mirror),
             ("a glass lobe (kt)", material.glass)]
    found = [what for what, weight in lobes if weight > 0]
    if found:
        raise SceneError(f"a material with {' and '.join(found)} is not mapped to Cycles: only "
                         "Lambertian materials are (Cycles' Glossy BSDF is not the normalised "
                         "Phong lobe, and its sharp glass does not scale radiance by "
                         "(n_i/n_t)^2 as clrt does); make kd the only lobe")


def parse_resolution(text):
    if text is None:
        return None
    w, _, h = text.lower().partition("x")
    return int(w), int(h)


# ---------------------------------------------------------------------------------------------
# bpy scene construction


def reset():
    import bpy
    bpy.ops.wm.read_factory_settings(use_empty=True)
    return bpy.context.scene


def node_material(name):
    """A new material with an empty node tree: the tree, and its output node."""
    import bpy
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    m.node_tree.nodes.clear()
    return m, m.node_tree.nodes, m.node_tree.nodes.new("ShaderNodeOutputMaterial")


def diffuse_material(name, colour):
    m, nodes, out = node_material(name)
    bsdf = nodes.new("ShaderNodeBsdfDiffuse")
    bsdf.inputs["Color"].default_value = (*[float(c) for c in colour], 1.0)
    bsdf.inputs["Roughness"].default_value = 0.0  # 0: Lambertian (above 0: Oren-Nayar)
    m.node_tree.links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    return m


def area_light_material(name, radiance):
    """Emits `radiance` from both sides and is otherwise invisible: Emission + Transparent BSDF
    (white) through an Add Shader, so that paths and shadow rays pass through, as clrt's area
    lights do not block."""
    m, nodes, out = node_material(name)
    emission = nodes.new("ShaderNodeEmission")
    emission.inputs["Color"].default_value = (*[float(c) for c in radiance], 1.0)
    emission.inputs["Strength"].default_value = 1.0
    clear = nodes.new("ShaderNodeBsdfTransparent")
    clear.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    add = nodes.new("ShaderNodeAddShader")
    m.node_tree.links.new(emission.outputs["Emission"], add.inputs[0])
    m.node_tree.links.new(clear.outputs["BSDF"], add.inputs[1])
    m.node_tree.links.new(add.outputs["Shader"], out.inputs["Surface"])
    # Importance-sample both faces: clrt's area lights are two-sided.
    m.cycles.emission_sampling = "FRONT_BACK"
    return m


def add_object(name, data, collection):
    import bpy
    obj = bpy.data.objects.new(name, data)
    collection.objects.link(obj)
    return obj


def triangle_object(name, corners, material, collection):
    """One flat-shaded mesh object of the triangles `corners` (N x 3 x 3, world space); no
    vertex is shared, so no normal is interpolated."""
    import bpy
    corners = np.asarray(corners, dtype=np.float64).reshape(-1, 3, 3)
    n = len(corners)
    mesh = bpy.data.meshes.new(name)
    mesh.vertices.add(3 * n)
    mesh.vertices.foreach_set("co", corners.astype(np.float32).ravel())
    mesh.loops.add(3 * n)
    mesh.loops.foreach_set("vertex_index", np.arange(3 * n, dtype=np.int32))
    mesh.polygons.add(n)
    mesh.polygons.foreach_set("loop_start", np.arange(0, 3 * n, 3, dtype=np.int32))
    mesh.polygons.foreach_set("use_smooth", np.zeros(n, dtype=bool))
    mesh.update()
    if mesh.validate():
        raise SceneError(f"{name}: Blender changed the mesh while validating it")
    mesh.materials.append(material)
    return add_object(name, mesh, collection)


def sphere_object(name, centre, radius, material, collection):
    """An exact sphere: Cycles renders a point cloud's points as true spheres. bpy cannot add
    points to a point cloud directly, so a one-vertex mesh becomes one point of the radius
    through a geometry-nodes modifier (Mesh to Points, Set Material)."""
    import bpy
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([[0.0, 0.0, 0.0]], [], [])
    obj = add_object(name, mesh, collection)
    obj.location = [float(c) for c in centre]
    tree = bpy.data.node_groups.new(name, "GeometryNodeTree")
    tree.interface.new_socket("Geometry", in_out="INPUT", socket_type="NodeSocketGeometry")
    tree.interface.new_socket("Geometry", in_out="OUTPUT", socket_type="NodeSocketGeometry")
    given, result = tree.nodes.new("NodeGroupInput"), tree.nodes.new("NodeGroupOutput")
    points = tree.nodes.new("GeometryNodeMeshToPoints")
    points.mode = "VERTICES"
    points.inputs["Radius"].default_value = float(radius)
    paint = tree.nodes.new("GeometryNodeSetMaterial")
    paint.inputs["Material"].default_value = material
    tree.links.new(given.outputs[0], points.inputs["Mesh"])
    tree.links.new(points.outputs["Points"], paint.inputs["Geometry"])
    tree.links.new(paint.outputs["Geometry"], result.inputs[0])
    obj.modifiers.new("sphere", "NODES").node_group = tree
    return obj


def cube_corners(placement):
    """The 12 triangles of the box [-1, 1]^3 placed by `placement` (4x4)."""
    quads = []
    for axis in range(3):
        for side in (-1.0, 1.0):
            u, v = [a for a in range(3) if a != axis]
            quad = []
            for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = np.zeros(3)
                p[axis], p[u], p[v] = side, su, sv
                quad.append(p)
            quads.append(quad)
    triangles = []
    for q in quads:
        world = [(placement @ np.r_[p, 1.0])[:3] for p in q]
        triangles += [[world[0], world[1], world[2]], [world[0], world[2], world[3]]]
    return np.array(triangles)


def plane_corners(placement, eye, extent):
    """clrt's endless plane as a square PLANE_EXTENT times the scene's extent, centred on the
    plane's point nearest the eye: the same stand-in as the Mitsuba converter's."""
    normal = np.linalg.inv(placement[:3, :3]).T @ [0.0, 1.0, 0.0]
    normal /= np.linalg.norm(normal)
    origin = placement[:3, 3]
    foot = eye - ((eye - origin) @ normal) * normal
    helper = np.eye(3)[np.argmin(np.abs(normal))]
    u = np.cross(helper, normal)
    u /= np.linalg.norm(u)
    v = np.cross(normal, u)
    size = extent * rtm.PLANE_EXTENT
    c = [foot + size * (su * u + sv * v) for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    return np.array([[c[0], c[1], c[2]], [c[0], c[2], c[3]]])


def camera_matrix(eye, lookat, up):
    """Blender's camera looks along its local -z with +y up."""
    import mathutils
    f = lookat - eye
    f = f / np.linalg.norm(f)
    r = np.cross(f, up)
    r = r / np.linalg.norm(r)
    u = np.cross(r, f)
    m = np.eye(4)
    m[:3, 0], m[:3, 1], m[:3, 2], m[:3, 3] = r, u, -f, eye
    return mathutils.Matrix(m.tolist())


def build(scene, spp, resolution, seed, threads):
    """Makes bpy's current scene the Cycles version of `scene` (a CyclesScene)."""
    import bpy
    bs = reset()
    collection = bs.collection
    width, height = resolution or scene.resolution

    # --- render settings
    bs.render.engine = "CYCLES"
    cy = bs.cycles
    cy.device = "CPU"
    cy.samples = int(spp)
    cy.use_adaptive_sampling = False
    cy.use_denoising = False
    cy.seed = int(seed)
    cy.use_animated_seed = False
    # clrt averages samples drawn uniformly over each pixel's square: a box filter one pixel wide.
    cy.pixel_filter_type = "BOX"
    cy.filter_width = 1.0
    depth = int(scene.maxdepth)
    cy.max_bounces = depth
    cy.diffuse_bounces = depth
    cy.glossy_bounces = depth
    cy.transmission_bounces = depth
    cy.volume_bounces = depth
    cy.transparent_max_bounces = TRANSPARENT_BOUNCES
    # Cycles clamps indirect samples at 10 by default: a bias clrt does not have.
    cy.sample_clamp_direct = 0.0
    cy.sample_clamp_indirect = 0.0
    cy.blur_glossy = 0.0
    cy.film_exposure = 1.0
    # Light tree, light threshold, sampling pattern, caustics, guiding: Cycles' defaults.
    bs.render.film_transparent = False
    bs.render.threads_mode = "FIXED"
    bs.render.threads = int(threads)
    bs.render.resolution_x, bs.render.resolution_y = int(width), int(height)
    bs.render.resolution_percentage = 100
    bs.render.pixel_aspect_x = bs.render.pixel_aspect_y = 1.0
    bs.render.use_border = False
    bs.render.use_compositing = False
    bs.render.use_sequencer = False
    bs.view_settings.view_transform = "Standard"
    bs.view_settings.look = "None"
    bs.view_settings.exposure = 0.0
    bs.view_settings.gamma = 1.0
    image = bs.render.image_settings
    image.file_format = "OPEN_EXR"
    image.color_mode = "RGB"
    image.color_depth = "32"
    image.exr_codec = "ZIP"

    # --- camera: fov is the angle across the image's width
    cam = bpy.data.cameras.new("camera")
    cam.type = "PERSP"
    cam.sensor_fit = "HORIZONTAL"
    cam.angle = math.radians(scene.fov)
    cam.clip_start = 1e-4  # clrt ignores hits closer than 1e-4
    cam.clip_end = 1e7
    cam.shift_x = cam.shift_y = 0.0
    cam_obj = add_object("camera", cam, collection)
    cam_obj.matrix_world = camera_matrix(scene.eye, scene.lookat, scene.up)
    bs.camera = cam_obj

    # --- background: a constant environment of radiance (r, g, b)
    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    nodes = world.node_tree.nodes
    nodes.clear()
    bg = nodes.new("ShaderNodeBackground")
    bg.inputs["Color"].default_value = (*[float(c) for c in scene.background], 1.0)
    bg.inputs["Strength"].default_value = 1.0
    wout = nodes.new("ShaderNodeOutputWorld")
    world.node_tree.links.new(bg.outputs["Background"], wout.inputs["Surface"])
    bs.world = world

    # --- surfaces: one Diffuse BSDF per .ray material, colour w_d
    materials = {}

    def material_of(m):
        if id(m) not in materials:
            materials[id(m)] = (m, diffuse_material(f"material_{len(materials)}", m.diffuse))
        return materials[id(m)][1]

    for i, (m, centre, radius) in enumerate(scene.spheres):
        sphere_object(f"sphere_{i}", centre, radius, material_of(m), collection)
    groups = {}
    for m, corners in scene.triangles:
        groups.setdefault(id(m), (m, []))[1].append(corners)
    for i, (m, placement) in enumerate(scene.cubes):
        groups.setdefault(id(m), (m, []))[1].extend(cube_corners(placement))
    for i, (m, placement) in enumerate(scene.planes):
        groups.setdefault(id(m), (m, []))[1].extend(plane_corners(placement, scene.eye, scene.extent()))
    for i, (m, corners) in enumerate(groups.values()):
        triangle_object(f"triangles_{i}", corners, material_of(m), collection)

    # --- lights
    for i, (kind, colour, v) in enumerate(scene.lights):
        colour = np.asarray(colour, dtype=float)
        if kind == "area":
            corner, u, w = v[0:3], v[3:6], v[6:9]
            if np.linalg.norm(np.cross(u, w)) == 0:
                raise SceneError("an area light with parallel edges has no area")
            quad = [corner, corner + u, corner + u + w, corner + w]
            triangle_object(f"area_light_{i}", [[quad[0], quad[1], quad[2]], [quad[0], quad[2], quad[3]]],
                            area_light_material(f"area_light_{i}", colour), collection)
            continue
        largest = float(colour.max())
        if kind == "point":
            light = bpy.data.lights.new(f"light_{i}", "POINT")
            light.shadow_soft_size = 0.0  # a true point
            light.use_soft_falloff = False
            light.energy = largest * POINT_POWER_PER_INTENSITY
        else:  # directional: a sun of irradiance (r, g, b) and no angular size
            light = bpy.data.lights.new(f"light_{i}", "SUN")
            light.angle = 0.0
            light.energy = largest
        light.color = (colour / largest).tolist() if largest > 0 else [0.0, 0.0, 0.0]
        light.use_temperature = False
        light.exposure = 0.0
        light.use_shadow = True
        obj = add_object(f"light_{i}", light, collection)
        if kind == "point":
            obj.location = [float(c) for c in v[:3]]
        else:
            # A sun shines along its local -z.
            d = np.asarray(v[:3], dtype=float)
            d /= np.linalg.norm(d)
            import mathutils
            obj.rotation_euler = mathutils.Vector((-d).tolist()).to_track_quat("Z", "Y").to_euler()
    return bs


def render(out):
    """Renders bpy's current scene to `out` (EXR); returns the render call's seconds."""
    import bpy
    bs = bpy.context.scene
    bs.render.filepath = str(pathlib.Path(out).resolve())
    bs.render.use_file_extension = False
    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    return time.perf_counter() - start


def read_exr(path):
    """The RGB planes of an EXR (H x W x 3 float64, top row first), through Blender's reader."""
    import bpy
    image = bpy.data.images.load(str(pathlib.Path(path).resolve()), check_existing=False)
    try:
        image.colorspace_settings.name = "Non-Color"  # the values as stored: no conversion
        w, h = image.size
        pixels = np.empty(w * h * image.channels, dtype=np.float32)
        image.pixels.foreach_get(pixels)
        rgba = pixels.reshape(h, w, image.channels)[::-1]  # Blender stores the bottom row first
        return rgba[..., :3].astype(np.float64)
    finally:
        bpy.data.images.remove(image)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene", help="a .ray or .nff file")
    parser.add_argument("-o", "--output", required=True, help="the EXR to write")
    parser.add_argument("--clrt", default=rtm.DEFAULT_CLRT, help="the clrt that reads the scene (default: build/clrt)")
    parser.add_argument("--spp", type=int, help="samples per pixel (default: the scene's `samples`)")
    parser.add_argument("--resolution", help="WxH (default: the scene's)")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    try:
        scene = rtm.read_scene(args.clrt, args.scene, CyclesScene)
        started = time.perf_counter()
        build(scene, args.spp or scene.samples, parse_resolution(args.resolution), args.seed, args.threads)
        built = time.perf_counter() - started
    except SceneError as e:
        print(f"ray_to_cycles: {e}", file=sys.stderr)
        sys.exit(2)
    seconds = render(args.output)
    import bpy
    cy = bpy.context.scene.cycles
    print(json.dumps({"render_s": seconds, "build_s": built, "bpy": bpy.app.version_string,
                      "spp": cy.samples, "seed": cy.seed, "max_bounces": cy.max_bounces,
                      "threads": bpy.context.scene.render.threads,
                      "resolution": [bpy.context.scene.render.resolution_x,
                                     bpy.context.scene.render.resolution_y]}))


if __name__ == "__main__":
    main()
