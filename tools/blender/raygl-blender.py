# raygl-blender.py: renders one .glb frame raygl2pov wrote with Blender's
# Cycles on the CPU, the way raygl-render --engine blender runs it:
#
#   blender -b -noaudio --factory-startup --python-exit-code 1 \
#       -P raygl-blender.py -- --input F.glb --output F.png [--temp T.png] \
#       [--samples N] [--threads N] [--lighting SPEC|COMPAT|RAW]
#
# What it sets, and why (docs/mapping-gltf.md "Blender"):
# - numpy's np.bool (removed in numpy 1.24) is put back before the glTF
#   add-on runs: Blender 3.4's importer still uses it;
# - the importer's light units default to COMPAT: raygl2pov writes GL's
#   diffuse colour x pi as the intensity (a viewer's Lambert term divides by
#   pi), and COMPAT gives Cycles that number as watts per square metre
#   (sun) or over 4 pi sr (point, spot) (measured against SPEC and RAW);
# - the camera is the .glb's, the image size its extras.imageSize (glTF
#   cameras have no pixel size), the background extras.background, seen by
#   camera rays only (GL's clear colour lights nothing);
# - colour management "Standard", look None, no dither: GL has no tone
#   curve and no noise; GL lights cast no shadows and light directly (no
#   bounces); pixels sampled at their centre (filter width 0.01) as GL's
#   aliased rasteriser does;
# - what the look step asked for (raygl2pov --area-lights, --light area,
#   --radiosity): a light's extras.rayglShadowRadius (point, spot) or
#   rayglShadowAngle (sun) make it cast soft shadows of that size;
#   extras.radiosity: two diffuse bounces;
# - no denoising (Debian's Blender has no OpenImageDenoise), a fixed seed,
#   N samples;
# - the PNG is written under a temporary name and renamed into place, so
#   nobody sees half a file.
#
# Errors: one line "raygl-blender: FILE: reason" on stderr, exit status 1.
# What the render cannot show (GL lines and points) is one line
# "raygl-blender: FILE: note: ..." on stderr, which raygl-render repeats.
import json
import math
import os
import struct
import sys

PROG = "raygl-blender"


class Failure(Exception):
    pass


def parse_args(argv):
    args = argv[argv.index("--") + 1:] if "--" in argv else []
    opts = {"input": None, "output": None, "samples": 16, "threads": 0,
            "lighting": "COMPAT", "temp": None}
    i = 0
    while i < len(args):
        key = args[i][2:] if args[i].startswith("--") else None
        if key not in opts or i + 1 >= len(args):
            raise Failure("usage: blender -b -P raygl-blender.py -- --input F.glb "
                          "--output F.png [--temp T.png] [--samples N] [--threads N] "
                          "[--lighting SPEC|COMPAT|RAW] (bad argument %r)" % args[i])
        opts[key] = args[i + 1]
        i += 2
    if not opts["input"] or not opts["output"]:
        raise Failure("--input and --output are needed")
    try:
        opts["samples"] = int(opts["samples"])
        opts["threads"] = int(opts["threads"])
    except ValueError:
        raise Failure("--samples and --threads take whole numbers")
    if opts["samples"] < 1 or opts["threads"] < 0:
        raise Failure("--samples from 1, --threads from 0 (0: every core)")
    if opts["lighting"] not in ("SPEC", "COMPAT", "RAW"):
        raise Failure("--lighting: SPEC, COMPAT or RAW")
    return opts


def glb_json(path):
    """The JSON chunk of a binary glTF, checked as far as this script needs."""
    try:
        with open(path, "rb") as f:
            head = f.read(20)
            if len(head) < 20 or head[:4] != b"glTF":
                raise Failure("not a binary glTF file (no glTF magic)")
            version, total, jlen, jtype = struct.unpack("<IIII", head[4:20])
            if version != 2 or jtype != 0x4E4F534A:
                raise Failure("not a glTF 2.0 binary with a JSON chunk")
            text = f.read(jlen)
            if len(text) != jlen:
                raise Failure("truncated (JSON chunk of %d bytes, %d present)" % (jlen, len(text)))
    except OSError as e:
        raise Failure(e.strerror or str(e))
    try:
        return json.loads(text.decode("utf-8"))
    except (ValueError, UnicodeDecodeError) as e:
        raise Failure("damaged JSON chunk: %s" % e)


def note_undrawn(path, meta):
    """Lines and points: Blender imports them as loose edges and vertices,
    which Cycles does not draw (and their colours, which Blender keeps per
    face corner, are lost): said as a note, which raygl-render repeats."""
    lines = points = 0
    for mesh in meta.get("meshes") or []:
        for prim in (mesh.get("primitives") or []) if isinstance(mesh, dict) else []:
            mode = prim.get("mode", 4) if isinstance(prim, dict) else 4
            lines += mode in (1, 2, 3)
            points += mode == 0
    if lines or points:
        sys.stderr.write("%s: %s: note: %d line and %d point primitive(s) not drawn "
                         "(Cycles renders no loose edges or vertices)\n"
                         % (PROG, path, lines, points))


def shim_numpy():
    # Blender 3.4's glTF importer calls np.bool, gone since numpy 1.24.
    try:
        import numpy as np
    except ImportError:
        raise Failure("Blender's Python has no numpy, which its glTF importer needs "
                      "(apt-get install python3-numpy)")
    if "bool" not in np.__dict__:
        np.bool = bool


def srgb_to_linear(v):
    return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4


def set_background(bpy, scene, rgb):
    # The clear colour for camera rays, black for lighting: GL's clear
    # colour lights nothing. World colours are linear; GL's are display
    # values, which Standard view encodes back exactly.
    world = bpy.data.worlds.new("raygl-background")
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    for n in list(nodes):
        nodes.remove(n)
    out = nodes.new("ShaderNodeOutputWorld")
    bg = nodes.new("ShaderNodeBackground")
    bg.inputs["Color"].default_value = [srgb_to_linear(c) for c in rgb[:3]] + [1.0]
    bg.inputs["Strength"].default_value = 1.0
    dark = nodes.new("ShaderNodeBackground")
    dark.inputs["Strength"].default_value = 0.0
    path = nodes.new("ShaderNodeLightPath")
    mix = nodes.new("ShaderNodeMixShader")
    links.new(path.outputs["Is Camera Ray"], mix.inputs["Fac"])
    links.new(dark.outputs["Background"], mix.inputs[1])
    links.new(bg.outputs["Background"], mix.inputs[2])
    links.new(mix.outputs["Shader"], out.inputs["Surface"])
    scene.world = world


def light_size(light, key):
    # A size raygl2pov wrote into the light's extras, or 0.
    v = light.get(key)
    return float(v) if isinstance(v, (int, float)) and 0 < v < 1e6 else 0.0


def render(opts):
    meta = glb_json(opts["input"])
    extras = meta.get("extras") if isinstance(meta.get("extras"), dict) else {}
    size = extras.get("imageSize")
    if not (isinstance(size, list) and len(size) == 2 and
            all(isinstance(v, int) and 0 < v <= 65536 for v in size)):
        raise Failure("no extras.imageSize: not written by raygl2pov --format gltf?")

    note_undrawn(opts["input"], meta)
    import bpy
    shim_numpy()
    # --factory-startup's cube, light and camera go first.
    bpy.ops.wm.read_factory_settings(use_empty=True)
    try:
        result = bpy.ops.import_scene.gltf(filepath=opts["input"], import_shading="NORMALS",
                                           convert_lighting_mode=opts["lighting"])
    except RuntimeError as e:
        raise Failure("the glTF importer failed: %s" % str(e).strip().splitlines()[-1])
    if "FINISHED" not in result:
        raise Failure("the glTF importer failed (%s)" % ", ".join(sorted(result)))

    scene = bpy.context.scene
    cams = [o for o in scene.objects if o.type == "CAMERA"]
    if not cams:
        raise Failure("no camera in the file")
    scene.camera = cams[0]
    for o in scene.objects:
        if o.type == "LIGHT":
            # GL lights are points that cast no shadow; a light raygl2pov
            # gave a size (--area-lights, --light area: the importer keeps
            # the light's extras as custom properties) casts soft shadows.
            radius = light_size(o.data, "rayglShadowRadius")
            angle = light_size(o.data, "rayglShadowAngle")
            o.data.shadow_soft_size = radius
            if o.data.type == "SUN":
                o.data.angle = angle
            o.data.cycles.cast_shadow = radius > 0 or angle > 0

    bg = extras.get("background")
    if not (isinstance(bg, list) and len(bg) >= 3):
        bg = [0.0, 0.0, 0.0]
    set_background(bpy, scene, [float(c) for c in bg])

    r = scene.render
    r.engine = "CYCLES"
    r.resolution_x, r.resolution_y = size
    r.resolution_percentage = 100
    r.pixel_aspect_x = r.pixel_aspect_y = 1.0
    r.film_transparent = False
    r.dither_intensity = 0.0
    if opts["threads"] > 0:
        r.threads_mode = "FIXED"
        r.threads = opts["threads"]
    c = scene.cycles
    c.device = "CPU"
    c.samples = opts["samples"]
    c.use_adaptive_sampling = False
    c.seed = 0
    c.use_animated_seed = False
    c.use_denoising = False
    c.use_preview_denoising = False
    c.filter_width = 0.01
    c.max_bounces = 0
    if extras.get("radiosity") is True:
        # --radiosity: light bounces off diffuse surfaces, as POV-Ray's
        # radiosity{} (its recursion_limit 2).
        c.max_bounces = c.diffuse_bounces = 2
        c.glossy_bounces = c.transmission_bounces = c.volume_bounces = 0
    c.caustics_reflective = c.caustics_refractive = False
    v = scene.view_settings
    scene.display_settings.display_device = "sRGB"
    v.view_transform = "Standard"
    v.look = "None"
    v.exposure = 0.0
    v.gamma = 1.0
    im = r.image_settings
    im.file_format = "PNG"
    im.color_mode = "RGB"
    im.color_depth = "8"
    im.compression = 15

    bpy.ops.render.render()
    out = opts["output"]
    folder, name = os.path.split(out)
    # raygl-render names the temporary itself (--temp), so that a stop
    # while Blender writes it removes it too.
    tmp = opts["temp"] or os.path.join(folder, ".%s.%d.tmp.png" % (name, os.getpid()))
    try:
        bpy.data.images["Render Result"].save_render(filepath=tmp, scene=scene)
        if not os.path.isfile(tmp) or os.path.getsize(tmp) == 0:
            raise Failure("%s: Blender wrote no image" % out)
        os.replace(tmp, out)
    except (OSError, RuntimeError) as e:
        raise Failure("%s: cannot write: %s" % (out, e))
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def main():
    where = "raygl-blender.py"
    try:
        opts = parse_args(sys.argv)
        where = opts["input"]
        render(opts)
    except Failure as e:
        sys.stderr.write("%s: %s: %s\n" % (PROG, where, e))
        sys.stderr.flush()
        sys.exit(1)
    except Exception as e:
        # A failure nobody foresaw: the traceback for the log, then the
        # one line raygl-render repeats.
        import traceback
        traceback.print_exc()
        sys.stderr.write("%s: %s: %s: %s\n" % (PROG, where, type(e).__name__, e))
        sys.stderr.flush()
        sys.exit(1)


main()
