"""Render a Glint glTF scene with Blender Cycles (CPU) at increasing sample counts, timed.

Usage (Blender 3.4 and python3-numpy from Debian, headless):
  blender -b --factory-startup --python app/bench/cycles/cornell_cycles.py -- \
      --scene resources/scenes/cornell_box/cornell_box.gltf --out OUT_DIR \
      [--size 512x512] [--bounces 4] [--samples 1,2,4,8,16,32,64] [--reference-samples 1024] \
      [--threads 2] [--seed 0] [--materials imported|diffuse] [--emission-sides gltf|both] \
      [--reference-exr EXR] [--adaptive-threshold T] [--env MAP.hdr]

The scene comes in through Blender's own glTF importer with its default options (the light-unit
convention Glint follows, docs/LIGHTS.md), so this also checks that Blender opens Glint's files.
Settings match `glint render`: the same bounce limit for every kind of bounce, a 1-pixel box pixel
filter, no denoiser, no adaptive sampling (unless asked for), no clamping, no light threshold, the 'Standard' view
transform (the EXR holds linear scene radiance either way), black world (a glTF carries none), or
with `--env MAP` the equirectangular map at strength 1 (Blender's mapping, u = 0.5 - atan2(y, x) / 2pi
in its Z-up axes, is Glint's u = 0.5 + atan2(z, x) / 2pi in glTF's once the importer turns Y up to Z).
Emission follows Glint's sides (docs/LIGHTS.md): a single-sided glTF material (Blender's importer
turns on backface culling for it, which Cycles ignores) emits from its front face only, a
double-sided one from both; `--emission-sides both` keeps Cycles' two-sided mesh emission.

Writes OUT_DIR/cycles_<N>spp.exr per sample count, OUT_DIR/cycles_reference.exr, and
OUT_DIR/cycles_convergence.csv with columns samples,seconds,relmse,cpu_seconds,worst_share: seconds is the wall time of
bpy.ops.render.render (scene sync included; with persistent data that is a few ms), relmse against
the reference (rendered with seed + 1) as docs/CLI.md defines it (mean over pixels and RGB of
(x - r)^2 / (r^2 + 0.01)); cpu_seconds the process CPU time of all threads (the steadier figure on a
shared machine); worst_share the share of the relMSE held by the worst 0.1 % of pixels (fireflies
put it there); the last row is the reference itself. `--reference-exr` judges against an existing
reference (another seed's run of this script) instead of rendering one. `--adaptive-threshold T`
turns on Cycles' adaptive sampling with noise threshold T (automatic minimum samples): each
`--samples` count is then the cap, and the reference is still rendered without it.
"""
import numpy

numpy.bool = numpy.bool_  # Blender 3.4's glTF importer still uses the alias numpy 1.24 removed

import argparse
import os
import sys
import time

import bpy


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="cornell_cycles.py")
    p.add_argument("--scene", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--size", default="512x512")
    p.add_argument("--bounces", type=int, default=4)
    p.add_argument("--samples", default="1,2,4,8,16,32,64")
    p.add_argument("--reference-samples", type=int, default=1024)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--reference-exr", help="an existing reference (32-bit EXR of the same size) instead of rendering one")
    p.add_argument("--adaptive-threshold", type=float, default=0.0,
                   help="Cycles' adaptive sampling with this noise threshold (0: off); --samples are then caps")
    p.add_argument("--env", help="an equirectangular environment map lighting the scene (default: black)")
    p.add_argument("--emission-sides", choices=["gltf", "both"], default="gltf",
                   help="gltf: single-sided materials emit from their front face only, as in Glint")
    p.add_argument("--materials", choices=["imported", "diffuse"], default="imported",
                   help="diffuse: replace each Principled BSDF by a Diffuse BSDF of its base colour "
                        "(emission kept), to separate the material model from light units")
    return p.parse_args(argv)


def import_scene(path):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=os.path.abspath(path))
    scene = bpy.context.scene
    cameras = [o for o in scene.objects if o.type == "CAMERA"]
    if not cameras:
        raise SystemExit("cornell_cycles.py: the scene has no camera")
    scene.camera = cameras[0]
    return scene


def use_diffuse_materials():
    for material in bpy.data.materials:
        if not material.use_nodes:
            continue
        nodes, links = material.node_tree.nodes, material.node_tree.links
        for principled in [n for n in nodes if n.type == "BSDF_PRINCIPLED"]:
            diffuse = nodes.new("ShaderNodeBsdfDiffuse")
            diffuse.inputs["Color"].default_value = principled.inputs["Base Color"].default_value
            emission = nodes.new("ShaderNodeEmission")
            emission.inputs["Color"].default_value = principled.inputs["Emission"].default_value
            emission.inputs["Strength"].default_value = principled.inputs["Emission Strength"].default_value
            add = nodes.new("ShaderNodeAddShader")
            links.new(diffuse.outputs[0], add.inputs[0])
            links.new(emission.outputs[0], add.inputs[1])
            for link in list(principled.outputs[0].links):
                links.new(add.outputs[0], link.to_socket)


def front_face_emission_only():
    """Emission x (1 - Backfacing) for single-sided materials (glTF doubleSided false, which the
    importer marks with use_backface_culling): the front face emits, the back face does not."""
    for material in bpy.data.materials:
        if not material.use_nodes or not material.use_backface_culling:
            continue
        nodes, links = material.node_tree.nodes, material.node_tree.links
        for node in list(nodes):
            if node.type == "BSDF_PRINCIPLED":
                socket = node.inputs["Emission Strength"]
            elif node.type == "EMISSION":
                socket = node.inputs["Strength"]
            else:
                continue
            geometry = nodes.new("ShaderNodeNewGeometry")
            front = nodes.new("ShaderNodeMath")
            front.operation = "SUBTRACT"
            front.inputs[0].default_value = 1.0
            links.new(geometry.outputs["Backfacing"], front.inputs[1])
            strength = nodes.new("ShaderNodeMath")
            strength.operation = "MULTIPLY"
            if socket.is_linked:
                links.new(socket.links[0].from_socket, strength.inputs[0])
            else:
                strength.inputs[0].default_value = socket.default_value
            links.new(front.outputs[0], strength.inputs[1])
            links.new(strength.outputs[0], socket)


def use_environment(scene, path):
    world = bpy.data.worlds.new("Environment")
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    texture = nodes.new("ShaderNodeTexEnvironment")
    texture.image = bpy.data.images.load(os.path.abspath(path))
    texture.interpolation = "Linear"
    background = nodes["Background"]
    background.inputs["Strength"].default_value = 1.0
    links.new(texture.outputs["Color"], background.inputs["Color"])
    scene.world = world


def configure(scene, args):
    width, height = (int(v) for v in args.size.lower().split("x"))
    r = scene.render
    r.engine = "CYCLES"
    r.resolution_x, r.resolution_y, r.resolution_percentage = width, height, 100
    r.threads_mode, r.threads = "FIXED", args.threads
    r.use_persistent_data = True  # later renders reuse the synced scene and BVH
    r.film_transparent = False
    c = scene.cycles
    c.device = "CPU"
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    c.max_bounces = args.bounces
    c.diffuse_bounces = args.bounces
    c.glossy_bounces = args.bounces
    c.transmission_bounces = args.bounces
    c.volume_bounces = args.bounces
    c.transparent_max_bounces = args.bounces
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.light_sampling_threshold = 0.0
    c.caustics_reflective = True
    c.caustics_refractive = True
    c.blur_glossy = 0.0
    c.seed = args.seed
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    settings = r.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_mode = "RGBA"
    settings.color_depth = "32"
    settings.exr_codec = "ZIP"


def render(scene, samples, path):
    scene.cycles.samples = samples
    scene.render.filepath = path
    start, cpu_start = time.perf_counter(), time.process_time()
    bpy.ops.render.render(write_still=True)
    return time.perf_counter() - start, time.process_time() - cpu_start


def read_rgb(path):
    image = bpy.data.images.load(path, check_existing=False)
    image.colorspace_settings.name = "Non-Color"
    pixels = numpy.empty(image.size[0] * image.size[1] * 4, dtype=numpy.float32)
    image.pixels.foreach_get(pixels)
    bpy.data.images.remove(image)
    return pixels.reshape(-1, 4)[:, :3].astype(numpy.float64)


def rel_mse(image, reference):
    return float(numpy.mean((image - reference) ** 2 / (reference ** 2 + 0.01)))


def worst_share(image, reference, fraction=0.001):
    """Share of the relMSE sum held by the worst `fraction` of pixels (per pixel: mean over RGB)."""
    per_pixel = numpy.sort(((image - reference) ** 2 / (reference ** 2 + 0.01)).mean(axis=1))[::-1]
    count = max(1, int(fraction * per_pixel.size))
    total = per_pixel.sum()
    return float(per_pixel[:count].sum() / total) if total > 0 else 0.0


def main():
    args = parse_args()
    os.makedirs(args.out, exist_ok=True)
    scene = import_scene(args.scene)
    if args.materials == "diffuse":
        use_diffuse_materials()
    if args.emission_sides == "gltf":
        front_face_emission_only()
    configure(scene, args)
    if args.env:
        use_environment(scene, args.env)
    out = os.path.abspath(args.out)
    if args.adaptive_threshold > 0.0:
        scene.cycles.use_adaptive_sampling = True
        scene.cycles.adaptive_threshold = args.adaptive_threshold
        scene.cycles.adaptive_min_samples = 0  # automatic
    render(scene, 1, os.path.join(out, "cycles_warmup.exr"))  # first sync and BVH build: not timed
    counts = [int(s) for s in args.samples.split(",")]
    times = {n: render(scene, n, os.path.join(out, "cycles_%dspp.exr" % n)) for n in counts}
    if args.reference_exr:
        reference_path, reference_seconds, reference_cpu = os.path.abspath(args.reference_exr), None, None
    else:
        reference_path = os.path.join(out, "cycles_reference.exr")
        scene.cycles.seed = args.seed + 1  # independent of the runs it judges
        scene.cycles.use_adaptive_sampling = False
        reference_seconds, reference_cpu = render(scene, args.reference_samples, reference_path)
    reference = read_rgb(reference_path)
    with open(os.path.join(out, "cycles_convergence.csv"), "w") as csv:
        csv.write("samples,seconds,relmse,cpu_seconds,worst_share\n")
        for n in counts:
            image = read_rgb(os.path.join(out, "cycles_%dspp.exr" % n))
            error, share = rel_mse(image, reference), worst_share(image, reference)
            csv.write("%d,%.6f,%.8g,%.6f,%.6f\n" % (n, times[n][0], error, times[n][1], share))
            print("cycles: %5d spp  %9.3f s  (CPU %.3f s)  relMSE %.6g  worst 0.1%% share %.3f" % (n, times[n][0], times[n][1], error, share))
        if reference_seconds is not None:
            csv.write("%d,%.6f,0,%.6f,0\n" % (args.reference_samples, reference_seconds, reference_cpu))
    if reference_seconds is not None:
        print("cycles: reference %d spp  %.3f s  (CPU %.3f s)" % (args.reference_samples, reference_seconds, reference_cpu))


main()
