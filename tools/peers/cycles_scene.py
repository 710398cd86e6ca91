# Renders one frame of a lacrima shot in Blender's Cycles, the peer renderer (issue 16), from the
# frame's geometry as `lacrima export` writes it. Run by tools/peers/compare_with_cycles.sh:
#
#   blender -b --factory-startup --python-exit-code 2 -P tools/peers/cycles_scene.py -- \
#       --shot SHOT.json --glb FRAME.glb --out cycles.exr [--spp N] [--width W --height H] [--threads T]
#
# What is matched to lacrima (docs/peers.md says why each choice makes the two estimate the same
# image):
#  - axes: lacrima and glTF are +Y up, Blender +Z up; Blender's glTF importer turns the meshes
#    (x, y, z) -> (x, -z, y), and this script does the same to the camera and the lights;
#  - camera: a pinhole with the shot's focal length and sensor height (vertical sensor fit);
#  - pixel filter: Blackman-Harris 1.5 px, lacrima's default (Cycles' default too);
#  - colours: lacrima renders RGB channel by channel in ACEScg; Cycles does the same arithmetic in
#    its own working space, so every colour (albedos, radiances, environment texels) is passed
#    unchanged and the environment image is read as non-colour data: no conversion on either side;
#  - lights: lacrima's area lights are uniform Lambertian emitters, radiance = power / (pi A) per
#    emitting side; a one-sided rectangle becomes a Cycles area light of that radiance (see
#    add_area_light for Cycles' unit); spheres and two-sided rectangles become emissive meshes of
#    that radiance (Cycles' mesh emission strength is radiance);
#  - materials: "diffuse" -> Diffuse BSDF; "water" -> a sharp Glass BSDF (Fresnel-weighted
#    reflection and refraction at the index, tint on transmission); "skin" -> an approximation
#    (Principled BSDF: Lambertian base, GGX specular of the same roughness and index, no pores,
#    no wet film, no subsurface), reported as approximate; glTF materials the shot does not map
#    -> Diffuse BSDF of their base colour, as lacrima does;
#  - no clamping, no glossy filter, no denoising, no adaptive sampling, and no shadow caustics
#    unless --mnee: an unbiased estimate, the reference to judge lacrima's caustics by.
import argparse
import math
import os
import re
import sys

import bpy
import numpy
from mathutils import Matrix, Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shot_json  # noqa: E402  (next to this script; Blender does not put it on the path)

numpy.bool = bool  # Blender 3.4's glTF importer still uses the alias numpy 1.24 removed


def fail(message):
    print(f"cycles_scene.py: {message}", file=sys.stderr)
    sys.exit(2)


def load_shot(path):
    try:
        return shot_json.load_shot(path)
    except (OSError, ValueError) as error:
        fail(f"{path}: cannot read the shot: {error}")


def to_blender(p):
    """lacrima/glTF (+Y up) to Blender (+Z up), the glTF importer's own conversion."""
    return (p[0], -p[2], p[1])


def place(obj, origin, x_axis, y_axis, z_axis):
    """Puts obj at origin with its local axes along the given lacrima directions (orthonormal)."""
    columns = [to_blender(x_axis), to_blender(y_axis), to_blender(z_axis)]
    rotation = Matrix([[columns[c][r] for c in range(3)] for r in range(3)])
    obj.matrix_world = Matrix.Translation(Vector(to_blender(origin))) @ rotation.to_4x4()


def static_vector(shot_path, where, value):
    """Numbers or [x, y, z]; keyed (animated) values are outside what the peer reproduces."""
    if isinstance(value, list) and value and isinstance(value[0], dict):
        fail(f"{shot_path}: {where} is keyed; the peer renders static cameras and lights only")
    return value


def colour(value, default):
    if value is None:
        return list(default)
    return [float(value)] * 3 if isinstance(value, (int, float)) else [float(c) for c in value]


def normalized(v):
    length = math.sqrt(sum(c * c for c in v))
    return [c / length for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


# ---- render settings -------------------------------------------------------------------------

def set_up_render(shot, args):
    scene = bpy.context.scene
    render = shot.get("render", {})
    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.samples = args.spp or int(render.get("spp", 16))
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.seed = int(render.get("seed", 0))
    depth = int(render.get("maxDepth", 12))
    cycles.max_bounces = depth
    cycles.diffuse_bounces = depth
    cycles.glossy_bounces = depth
    cycles.transmission_bounces = depth
    cycles.transparent_max_bounces = depth
    cycles.volume_bounces = 0
    cycles.caustics_reflective = True
    cycles.caustics_refractive = True
    cycles.blur_glossy = 0.0
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.pixel_filter_type = "BLACKMAN_HARRIS"
    cycles.filter_width = 1.5
    scene.render.resolution_x = args.width or int(render.get("width", 640))
    scene.render.resolution_y = args.height or int(render.get("height", 360))
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.render.threads_mode = "FIXED"
    scene.render.threads = args.threads
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    settings = scene.render.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_depth = "32"
    settings.exr_codec = "ZIP"
    settings.color_mode = "RGBA"


# ---- camera ----------------------------------------------------------------------------------

def set_up_camera(shot, shot_path):
    camera = shot.get("camera")
    if camera is None:
        fail(f"{shot_path}: camera: missing")
    for key in ("gltf", "fStop", "shutter"):
        if key in camera:
            fail(f"{shot_path}: camera.{key}: the peer renders a pinhole camera given by position and lookAt")
    position = static_vector(shot_path, "camera.position", camera["position"])
    look_at = static_vector(shot_path, "camera.lookAt", camera["lookAt"])
    up = static_vector(shot_path, "camera.up", camera.get("up", [0, 1, 0]))
    data = bpy.data.cameras.new("lacrima camera")
    data.lens = float(camera.get("focalLength", 50))
    data.sensor_fit = "VERTICAL"
    data.sensor_height = float(camera.get("sensorHeight", 24))
    data.clip_start = 1e-4
    data.clip_end = 1e4
    obj = bpy.data.objects.new("lacrima camera", data)
    bpy.context.scene.collection.objects.link(obj)
    # Blender's camera looks down its local -Z with +Y up, as lacrima's does.
    forward = normalized([a - b for a, b in zip(look_at, position)])
    right = normalized(cross(forward, up))
    place(obj, position, right, cross(right, forward), [-c for c in forward])
    bpy.context.scene.camera = obj


# ---- environment -----------------------------------------------------------------------------

def set_up_world(shot, shot_path):
    world = bpy.data.worlds.new("lacrima world")
    bpy.context.scene.world = world
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    background = nodes["Background"]
    environment = shot.get("environment")
    if environment is None:
        background.inputs["Color"].default_value = (*colour(shot.get("background"), [0, 0, 0]), 1.0)
        background.inputs["Strength"].default_value = 1.0
        return
    path = os.path.join(os.path.dirname(os.path.abspath(shot_path)), environment["file"])
    try:
        image = bpy.data.images.load(path)
    except RuntimeError as error:
        fail(f"{shot_path}: environment.file: {error}")
    image.colorspace_settings.name = "Non-Color"  # the texels as they are: lacrima converts nothing
    texture = nodes.new("ShaderNodeTexEnvironment")
    texture.image = image
    texture.interpolation = "Linear"  # lacrima's bilinear lookup
    # lacrima maps direction d (+Y up) to u = (atan2(-d.x, d.z) + r) / 2 pi; Cycles' equirect
    # gives u = 1/2 - atan2(d_b.y, d_b.x) / 2 pi for the converted d_b = (x, -z, y), which is
    # lacrima's unrotated u plus 3/4, and rotating d_b by a about +Z lowers u by a / 2 pi, so
    # a = -(pi/2 + r) lines the maps up (both put the map's top row at +up, u growing rightwards
    # as seen from inside).
    rotation = math.radians(float(environment.get("rotation", 0.0)))
    coordinates = nodes.new("ShaderNodeTexCoord")
    mapping = nodes.new("ShaderNodeMapping")
    mapping.vector_type = "POINT"
    mapping.inputs["Rotation"].default_value = (0.0, 0.0, -(math.pi / 2 + rotation))
    links.new(coordinates.outputs["Generated"], mapping.inputs["Vector"])
    links.new(mapping.outputs["Vector"], texture.inputs["Vector"])
    links.new(texture.outputs["Color"], background.inputs["Color"])
    background.inputs["Strength"].default_value = float(environment.get("intensity", 1.0))


# ---- lights ----------------------------------------------------------------------------------

def emission_material(name, radiance, two_sided):
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    front = nodes.new("ShaderNodeEmission")
    front.inputs["Color"].default_value = (*radiance, 1.0)
    front.inputs["Strength"].default_value = 1.0  # mesh emission strength is radiance
    if two_sided:
        links.new(front.outputs["Emission"], output.inputs["Surface"])
        return material
    back = nodes.new("ShaderNodeEmission")
    back.inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
    geometry = nodes.new("ShaderNodeNewGeometry")
    mix = nodes.new("ShaderNodeMixShader")
    links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
    links.new(front.outputs["Emission"], mix.inputs[1])
    links.new(back.outputs["Emission"], mix.inputs[2])
    links.new(mix.outputs["Shader"], output.inputs["Surface"])
    return material


def rectangle_edges(light, shot_path, where):
    """Edges u, v and the emitting normal, as docs/shot-format.md's "rectangles" defines them."""
    center = light["center"]
    if "u" in light:
        u, v = light["u"], light["v"]
        return u, v, normalized(cross(u, v))
    width, height = light["size"]
    if "lookAt" in light:
        normal = normalized([a - b for a, b in zip(light["lookAt"], center)])
    else:
        normal = normalized(light["normal"])
    up = light.get("up", [0, 1, 0])
    if abs(dot(normalized(up), normal)) > 1 - 1e-6:
        if "up" in light:
            fail(f"{shot_path}: {where}.up: parallel to the normal")
        up = [0, 0, -1]
    width_axis = normalized(cross(normal, up))
    height_axis = normalized([a - normal[i] * dot(up, normal) for i, a in enumerate(up)])
    return [c * width for c in width_axis], [c * height for c in height_axis], normal


def add_rectangle_light(index, light, shot_path):
    where = f"lights[{index}]"
    center = static_vector(shot_path, f"{where}.center", light["center"])
    u, v, normal = rectangle_edges(light, shot_path, where)
    area = math.sqrt(sum(c * c for c in cross(u, v)))
    two_sided = bool(light.get("twoSided", False))
    radiance = light_radiance(light, area, two_sided, shot_path, where)
    is_rectangle = abs(dot(u, v)) <= 1e-6 * math.sqrt(dot(u, u) * dot(v, v))
    if is_rectangle and not two_sided:
        add_area_light(index, center, u, v, normal, area, radiance)
        return
    # A parallelogram (edges u, v not at right angles) or a two-sided light: an emissive quad.
    corners = [[center[i] + su * u[i] / 2 + sv * v[i] / 2 for i in range(3)]
               for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    if dot(cross(u, v), normal) < 0:  # wind the quad so its face normal is the emitting side
        corners.reverse()
    add_emitter(f"light {index}", [to_blender(c) for c in corners], [(0, 1, 2, 3)], radiance, two_sided)


def add_area_light(index, center, u, v, normal, area, radiance):
    """A one-sided rectangle as a Cycles area light, which Cycles 3.4 samples in proportion to the
    light count (an emissive mesh's triangles are picked by area, so a small bright catchlight
    beside a big key is hardly ever sampled and paints fireflies). Cycles 3.4 gives an area light of
    "power" P the radiance P / (4 A), not P / (pi A): measured here against an emissive mesh of known
    radiance (mesh emission strength is radiance), the area light of power pi A L was pi / 4 of it
    (0.7853, on the lit sphere and the floor of shots/sphere_in_studio.json). So P = 4 A L."""
    data = bpy.data.lights.new(f"light {index}", "AREA")
    data.shape = "RECTANGLE"
    data.size = math.sqrt(dot(u, u))
    data.size_y = math.sqrt(dot(v, v))
    brightest = max(radiance)
    data.energy = brightest * 4.0 * area if brightest > 0 else 0.0
    data.color = [c / brightest for c in radiance] if brightest > 0 else (1.0, 1.0, 1.0)
    data.cycles.max_bounces = 1024
    obj = bpy.data.objects.new(f"light {index}", data)
    bpy.context.scene.collection.objects.link(obj)
    x_axis = normalized(u)
    z_axis = [-c for c in normal]  # the light shines down its local -Z
    place(obj, center, x_axis, cross(z_axis, x_axis), z_axis)


def add_sphere_light(index, light, shot_path):
    where = f"lights[{index}]"
    center = static_vector(shot_path, f"{where}.center", light["center"])
    radius = float(light["radius"])
    radiance = light_radiance(light, 4 * math.pi * radius * radius, False, shot_path, where)
    bpy.ops.mesh.primitive_uv_sphere_add(segments=96, ring_count=48, radius=radius,
                                         location=to_blender(center))
    obj = bpy.context.active_object
    obj.name = f"light {index}"
    bpy.ops.object.shade_smooth()
    obj.data.materials.append(emission_material(f"light {index}", radiance, False))


def light_radiance(light, area, two_sided, shot_path, where):
    intensity = static_vector(shot_path, f"{where}.intensity", light.get("intensity", 1.0))
    if "radiance" in light:
        radiance = colour(light["radiance"], [0, 0, 0])
    else:
        sides = 2 if two_sided else 1
        radiance = [p / (sides * math.pi * area) for p in colour(light["power"], [0, 0, 0])]
    return [c * float(intensity) for c in radiance]


def add_emitter(name, vertices, faces, radiance, two_sided):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(vertices, [], faces)
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    mesh.materials.append(emission_material(name, radiance, two_sided))


def set_up_lights(shot, shot_path):
    for index, light in enumerate(shot.get("lights", [])):
        kind = light.get("type")
        if kind == "rectangle":
            add_rectangle_light(index, light, shot_path)
        elif kind == "sphere":
            add_sphere_light(index, light, shot_path)
        else:
            fail(f"{shot_path}: lights[{index}].type: '{kind}' is not a light the peer knows")


# ---- materials -------------------------------------------------------------------------------

def shader_material(name, spec, base_colour):
    """A Cycles material for one of the shot's materials (or an unmapped glTF one, spec None)."""
    material = bpy.data.materials.new(f"peer {name}")
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    kind = spec.get("type") if spec else "diffuse"
    if kind == "diffuse":
        albedo = colour(spec.get("albedo") if spec else None, base_colour)
        shader = nodes.new("ShaderNodeBsdfDiffuse")
        shader.inputs["Color"].default_value = (*albedo, 1.0)
        shader.inputs["Roughness"].default_value = 0.0
    elif kind == "water":
        shader = nodes.new("ShaderNodeBsdfGlass")
        shader.distribution = "SHARP"
        shader.inputs["IOR"].default_value = float(spec.get("ior", 1.337))
        shader.inputs["Color"].default_value = (*colour(spec.get("tint"), [1, 1, 1]), 1.0)
    elif kind == "skin":
        print(f"cycles_scene.py: material '{name}': skin is approximated (Principled BSDF; no pores, "
              "wet film, second lobe or subsurface)", file=sys.stderr)
        shader = nodes.new("ShaderNodeBsdfPrincipled")
        ior = float(spec.get("ior", 1.4))
        shader.inputs["Base Color"].default_value = (*colour(spec.get("albedo"), [0.62, 0.43, 0.35]), 1.0)
        shader.inputs["Roughness"].default_value = float(spec.get("roughness", 0.35))
        shader.inputs["Specular"].default_value = ((ior - 1) / (ior + 1)) ** 2 / 0.08
        shader.inputs["Subsurface"].default_value = 0.0
    else:
        fail(f"material '{name}': type '{kind}' is not one the peer reproduces")
    emission = colour(spec.get("emission") if spec else None, [0, 0, 0])
    if any(c > 0 for c in emission):
        glow = nodes.new("ShaderNodeEmission")
        glow.inputs["Color"].default_value = (*emission, 1.0)
        add = nodes.new("ShaderNodeAddShader")
        links.new(shader.outputs[0], add.inputs[0])
        links.new(glow.outputs[0], add.inputs[1])
        shader = add
    links.new(shader.outputs[0], output.inputs["Surface"])
    return material


def glb_base_colour(material):
    if material.use_nodes:
        for node in material.node_tree.nodes:
            if node.type == "BSDF_PRINCIPLED":
                return [min(max(c, 0.0), 1.0) for c in node.inputs["Base Color"].default_value[:3]]
    return [min(max(c, 0.0), 1.0) for c in material.diffuse_color[:3]]


def import_frame(glb_path, shot):
    try:
        bpy.ops.import_scene.gltf(filepath=glb_path, merge_vertices=False)
    except RuntimeError as error:
        fail(f"{glb_path}: the glTF importer failed: {error}")
    materials = shot.get("materials", {})
    replaced = {}
    for obj in list(bpy.context.scene.objects):
        if obj.type != "MESH" or obj.name.startswith("light "):
            continue
        for slot in obj.material_slots:
            if slot.material is None:
                continue
            name = re.sub(r"\.\d{3}$", "", slot.material.name)
            if name not in replaced:
                replaced[name] = shader_material(name, materials.get(name), glb_base_colour(slot.material))
            slot.material = replaced[name]
    return sorted(replaced)


def enable_shadow_caustics(shot):
    """Cycles' own manifold next-event estimation (Cycles 3.2+): water casts, everything else
    receives, every area light is a caustic light. Without it Cycles finds the light under a tear
    only by paths that happen to refract out of the bead into a light (unbiased, but it takes
    thousands of samples); with it, Cycles 3.4 is faster but approximate ("approximate caustics"
    in its own words): under the cheek bead of shots/tear_on_cheek.json it found 0.059 where its
    path tracing converges to 0.145."""
    water = {name for name, spec in shot.get("materials", {}).items()
             if spec.get("type") in ("water", "rough_dielectric")}
    for obj in bpy.context.scene.objects:
        if obj.type == "LIGHT":
            obj.data.cycles.is_caustics_light = True
        elif obj.type == "MESH" and not obj.name.startswith("light "):
            casts = any(slot.material and slot.material.name.removeprefix("peer ") in water
                        for slot in obj.material_slots)
            obj.cycles.is_caustics_caster = casts
            obj.cycles.is_caustics_receiver = not casts


def set_render_region(x, y, w, h):
    """Blender's render border, in fractions of the frame with y up (lacrima's pixels run down)."""
    render = bpy.context.scene.render
    width, height = render.resolution_x, render.resolution_y
    render.use_border = True
    render.use_crop_to_border = False
    render.border_min_x, render.border_max_x = x / width, (x + w) / width
    render.border_min_y, render.border_max_y = 1 - (y + h) / height, 1 - y / height


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="cycles_scene.py", description=__doc__)
    parser.add_argument("--shot", required=True)
    parser.add_argument("--glb", required=True, help="the frame's geometry from `lacrima export`")
    parser.add_argument("--out", required=True, help="the EXR to write (linear RGBA, 32-bit float)")
    parser.add_argument("--spp", type=int, default=0, help="samples per pixel (default: the shot's)")
    parser.add_argument("--width", type=int, default=0)
    parser.add_argument("--height", type=int, default=0)
    parser.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--region", type=int, nargs=4, metavar=("X", "Y", "W", "H"),
                        help="render only this pixel rectangle (top-left X, Y), the rest black: "
                        "a region converged with many more samples at a fraction of the cost")
    parser.add_argument("--mnee", action="store_true",
                        help="turn on Cycles' shadow caustics (its MNEE); off by default: it is approximate, and "
                        "under a bead lying on skin it lost 60 %% of the light (docs/peers.md)")
    args = parser.parse_args(argv)

    shot = load_shot(args.shot)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    set_up_render(shot, args)
    set_up_camera(shot, args.shot)
    set_up_world(shot, args.shot)
    materials = import_frame(args.glb, shot)
    set_up_lights(shot, args.shot)
    if args.mnee:
        enable_shadow_caustics(shot)
    if args.region:
        set_render_region(*args.region)
    print(f"cycles_scene.py: materials {', '.join(materials)}; {bpy.context.scene.cycles.samples} spp")
    bpy.context.scene.render.filepath = args.out
    bpy.ops.render.render(write_still=True)


main()
