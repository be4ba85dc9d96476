# SPDX-License-Identifier: Apache-2.0
"""Blender script of the peer benchmark (bench/peer/README.md): builds the scene that
make_scene.py wrote for glint — the terrain OBJ, a grey Lambertian (Diffuse BSDF) of the same
reflectance, a sun lamp of the same direction, disk and irradiance, a uniform world of the
same radiance, a nadir pinhole camera with the same field of view — and renders it with
Cycles on the CPU at a fixed sample count, writing an OpenEXR image and a JSON file of
timings and settings.

Run headless:
    blender -b --factory-startup -noaudio -t 2 -P cycles_render.py -- \
        --work WORK --px 1024 --spp 4 --threads 2 --max-bounces 8 --min-bounces 2 \
        --sun-dir=X,Y,Z --exr out.exr --json out.json

Fairness settings (what glint does, docs in bench/peer/README.md): path tracing, no
denoising, no adaptive sampling, a fixed sample count, a 1-pixel box filter, no clamping,
the same maximum bounces, Russian roulette held off for the first bounces as glint holds it
off (min light bounces), the world not importance-sampled (glint has no sky next-event
estimation), the sun sampled by next-event estimation only (lamp MIS off: glint never adds
the sun on a continuation ray), no light tree, no light threshold, an Embree BVH of build
quality HIGH as glint's (spatial splits on), CPU, N threads.
"""
import argparse
import array
import json
import math
import os
import sys
import time

import bpy

T_START = time.monotonic()


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    ap = argparse.ArgumentParser(prog="cycles_render.py")
    ap.add_argument("--work", required=True)
    ap.add_argument("--px", type=int, required=True)
    ap.add_argument("--spp", type=int, required=True)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--max-bounces", type=int, default=8)
    ap.add_argument("--min-bounces", type=int, default=2)
    ap.add_argument("--sun-dir", required=True, help="unit vector towards the sun, ENU")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--exr", required=True)
    ap.add_argument("--json", required=True)
    return ap.parse_args(argv)


def set_if(obj, name, value, record):
    """Sets obj.name when this Blender has it; records what was set (or that it is absent)."""
    if hasattr(obj, name):
        setattr(obj, name, value)
        record[name] = value
    else:
        record[name] = "absent in this Blender"


def main():
    args = parse_args()
    with open(os.path.join(args.work, "peer.json")) as f:
        peer = json.load(f)
    settings = {}
    times = {"script_start": T_START}

    # An empty scene.
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene

    if peer.get("canopy"):
        t0 = time.monotonic()
        triangles = build_canopy(peer, args.work, scene)
        times["obj_import_s"] = time.monotonic() - t0
    else:
        triangles = build_terrain(peer, args.work, scene, times)
    rest_of_scene(args, peer, scene, settings, times, triangles)


def diffuse_material(name, rho):
    """Diffuse BSDF (Lambert: roughness 0) of grey reflectance rho."""
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes = mat.node_tree.nodes
    nodes.clear()
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (rho, rho, rho, 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0
    out = nodes.new("ShaderNodeOutputMaterial")
    mat.node_tree.links.new(diffuse.outputs["BSDF"], out.inputs["Surface"])
    return mat


def leaf_material(rt):
    """A thin leaf: Mix(0.5) of Diffuse BSDF and Translucent BSDF of colour 2 rt, so that it
    reflects rt and transmits rt, both Lambertian (glint: reflectance rt, transmittance rt)."""
    mat = bpy.data.materials.new("leaf")
    mat.use_nodes = True
    nodes = mat.node_tree.nodes
    nodes.clear()
    c = 2.0 * rt
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (c, c, c, 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0
    translucent = nodes.new("ShaderNodeBsdfTranslucent")
    translucent.inputs["Color"].default_value = (c, c, c, 1.0)
    mix = nodes.new("ShaderNodeMixShader")
    mix.inputs["Fac"].default_value = 0.5
    links = mat.node_tree.links
    links.new(diffuse.outputs["BSDF"], mix.inputs[1])
    links.new(translucent.outputs["BSDF"], mix.inputs[2])
    out = nodes.new("ShaderNodeOutputMaterial")
    links.new(mix.outputs["Shader"], out.inputs["Surface"])
    return mat


def build_canopy(peer, work, scene):
    """The tree OBJ once, its mesh shared by one object per instance (Cycles instances
    objects that share mesh data), over a flat soil square; returns the triangle count."""
    canopy = peer["canopy"]
    bpy.ops.wm.obj_import(filepath=os.path.join(work, canopy["tree_obj"]),
                          forward_axis="Y", up_axis="Z")
    tree = [o for o in scene.objects if o.type == "MESH"][0]
    tree.data.polygons.foreach_set("use_smooth", [False] * len(tree.data.polygons))
    leaf = leaf_material(canopy["leaf_rt"])
    bark = diffuse_material("bark", canopy["bark_reflectance"])
    for slot in tree.material_slots:
        slot.material = leaf if "leaf" in (slot.name or "") else bark
    for x, y, rot_deg, scale in canopy["instances"]:
        o = tree.copy()  # shares tree.data
        o.location = (x, y, 0.0)
        o.rotation_euler = (0.0, 0.0, math.radians(rot_deg))
        o.scale = (scale, scale, scale)
        scene.collection.objects.link(o)
    tree.hide_render = True
    half = canopy["ground_size_m"] / 2.0
    mesh = bpy.data.meshes.new("ground")
    mesh.from_pydata([(-half, -half, 0), (half, -half, 0), (half, half, 0), (-half, half, 0)], [],
                     [(0, 1, 2, 3)])
    ground = bpy.data.objects.new("ground", mesh)
    ground.data.materials.append(diffuse_material("soil", peer["reflectance"]))
    scene.collection.objects.link(ground)
    return canopy["triangles"]


def build_terrain(peer, work, scene, times):
    # Geometry: the same OBJ glint reads (z up, as glint's scene frame).
    t0 = time.monotonic()
    bpy.ops.wm.obj_import(filepath=os.path.join(work, peer["terrain_obj"]),
                          forward_axis="Y", up_axis="Z")
    times["obj_import_s"] = time.monotonic() - t0
    terrain = [o for o in scene.objects if o.type == "MESH"]
    assert len(terrain) == 1, "expected one mesh from the OBJ"
    terrain = terrain[0]
    polygons = terrain.data.polygons
    sides = array.array("i", [0]) * len(polygons)
    polygons.foreach_get("loop_total", sides)
    triangles = sum(sides) - 2 * len(polygons)
    # Flat shading: glint shades with the geometric normal (the OBJ has no normals).
    polygons.foreach_set("use_smooth", [False] * len(polygons))

    # Material: Diffuse BSDF (Lambert: roughness 0), grey reflectance.
    terrain.data.materials.clear()
    terrain.data.materials.append(diffuse_material("soil", peer["reflectance"]))
    return triangles


def rest_of_scene(args, peer, scene, settings, times, triangles):

    # World: uniform radiance, not importance-sampled (glint: sky only on continuation rays).
    world = bpy.data.worlds.new("sky")
    scene.world = world
    world.use_nodes = True
    bg = world.node_tree.nodes["Background"]
    L = peer["sky_radiance"]
    bg.inputs["Color"].default_value = (L, L, L, 1.0)
    bg.inputs["Strength"].default_value = 1.0
    world_settings = {}
    set_if(world.cycles, "sampling_method", "NONE", world_settings)
    settings["world"] = world_settings

    # Sun: irradiance per channel = glint's sun at 0.45, 0.55, 0.65 um (W/(cm2 um): the
    # image's numbers are then glint's radiance units), disk of glint's angular size.
    e = peer["sun_irradiance_rgb"]
    emax = max(e)
    sun_data = bpy.data.lights.new("sun", type="SUN")
    sun_data.energy = emax
    sun_data.color = tuple(v / emax for v in e)
    sun_data.angle = math.radians(peer["sun_angle_deg"])
    sun_settings = {}
    set_if(sun_data.cycles, "use_multiple_importance_sampling", False, sun_settings)
    set_if(sun_data.cycles, "cast_shadow", True, sun_settings)
    settings["sun"] = sun_settings
    sun = bpy.data.objects.new("sun", sun_data)
    scene.collection.objects.link(sun)
    sx, sy, sz = (float(v) for v in args.sun_dir.split(","))
    # The lamp shines along its local -z: rotate local +z onto the direction towards the sun.
    sun.rotation_mode = "XYZ"
    sun.rotation_euler = (math.acos(max(-1.0, min(1.0, sz))), 0.0, math.atan2(sx, -sy))

    # Camera: nadir pinhole at the glint camera's position and field of view.
    cam_data = bpy.data.cameras.new("camera")
    cam_data.type = "PERSP"
    cam_data.lens = peer["focal_length_mm"]
    cam_data.sensor_fit = "HORIZONTAL"
    cam_data.sensor_width = peer["sensor_width_mm"]
    cam_data.clip_start = 1.0
    cam_data.clip_end = 1.0e6
    cam = bpy.data.objects.new("camera", cam_data)
    cam.location = (0.0, peer.get("camera_y_m", 0.0), peer["camera_height_m"])
    # Looks down -z, north up; a rotation about x tilts the view towards +y (north), as
    # glint's pitch does.
    cam.rotation_euler = (math.radians(peer.get("view_zenith_deg", 0.0)), 0.0, 0.0)
    scene.collection.objects.link(cam)
    scene.camera = cam

    # Render settings.
    r = scene.render
    r.engine = "CYCLES"
    r.resolution_x = r.resolution_y = args.px
    r.resolution_percentage = 100
    r.pixel_aspect_x = r.pixel_aspect_y = 1.0
    r.threads_mode = "FIXED"
    r.threads = args.threads
    r.use_motion_blur = False
    r.use_persistent_data = False
    r.film_transparent = False
    r.image_settings.file_format = "OPEN_EXR"
    r.image_settings.color_mode = "RGB"
    r.image_settings.color_depth = "32"
    r.image_settings.exr_codec = "NONE"
    r.filepath = args.exr
    r.use_file_extension = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    vl = scene.view_layers[0]
    vl.use_pass_combined = True
    vl.use_pass_z = False

    c = scene.cycles
    cs = {}
    for name, value in [
        ("device", "CPU"),
        ("feature_set", "SUPPORTED"),
        ("samples", args.spp),
        ("use_adaptive_sampling", False),
        ("use_denoising", False),
        ("use_preview_denoising", False),
        ("time_limit", 0.0),
        ("seed", args.seed),
        ("use_animated_seed", False),
        ("pixel_filter_type", "BOX"),
        ("filter_width", 1.0),
        ("max_bounces", args.max_bounces),
        ("diffuse_bounces", args.max_bounces),
        ("glossy_bounces", args.max_bounces),
        ("transmission_bounces", args.max_bounces),
        ("volume_bounces", 0),
        ("transparent_max_bounces", args.max_bounces),
        ("min_light_bounces", args.min_bounces),
        ("min_transparent_bounces", 0),
        ("sample_clamp_direct", 0.0),
        ("sample_clamp_indirect", 0.0),
        ("light_sampling_threshold", 0.0),
        ("use_light_tree", False),
        ("caustics_reflective", True),
        ("caustics_refractive", True),
        ("blur_glossy", 0.0),
        ("use_fast_gi", False),
        ("ao_bounces", 0),
        ("ao_bounces_render", 0),
        ("use_guiding", False),
        ("use_auto_tile", False),
        ("auto_scrambling_distance", False),
        ("scrambling_distance", 1.0),
        ("use_layer_samples", "USE"),
        ("film_exposure", 1.0),
        # Embree build quality HIGH, as glint's (Cycles' default for a static scene: MEDIUM;
        # spatial splits select HIGH in Cycles' Embree BVH).
        ("debug_use_spatial_splits", True),
        ("debug_use_compact_bvh", False),
    ]:
        set_if(c, name, value, cs)
    settings["cycles"] = cs
    settings["blender_version"] = bpy.app.version_string
    settings["build_options"] = {k: getattr(bpy.app.build_options, k)
                                 for k in dir(bpy.app.build_options)
                                 if not k.startswith("_") and k in ("cycles", "cycles_osl", "openimagedenoise", "embree")}

    # Timestamps (time.monotonic: the runner's clock too) of the render's handlers: pre
    # (before Cycles syncs the scene), post (after the last sample), and the return of the
    # render operator (after the EXR is written). The runner times the path tracing phase
    # from Cycles' own status lines ("Sample 0/N" .. "Finished"), which it stamps as they come.
    def on_pre(*_):
        times["render_pre"] = time.monotonic()

    def on_post(*_):
        times["render_post"] = time.monotonic()

    bpy.app.handlers.render_pre.append(on_pre)
    bpy.app.handlers.render_post.append(on_post)

    times["setup_done"] = time.monotonic()
    bpy.ops.render.render(write_still=True)
    times["render_returned"] = time.monotonic()

    result = {
        "engine": "cycles",
        "px": args.px,
        "spp": args.spp,
        "threads": args.threads,
        "triangles": triangles,
        "settings": settings,
        "obj_import_s": times["obj_import_s"],
        "setup_s": times["setup_done"] - T_START,
        "render_pre_to_post_s": times["render_post"] - times["render_pre"],
        "write_s": times["render_returned"] - times["render_post"],
        "monotonic": {k: v for k, v in times.items() if not k.endswith("_s")},
    }
    with open(args.json, "w") as f:
        json.dump(result, f, indent=1)
    sys.stdout.flush()


main()
