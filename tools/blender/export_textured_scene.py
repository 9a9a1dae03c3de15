# Measurement only: a scene as a Blender user makes one, exported by Blender's glTF exporter:
# a checker base colour texture on the ground, a normal-mapped cube, an emissive sphere
# (KHR_materials_emissive_strength), a glass sphere (KHR_materials_transmission), a point and
# a spot lamp, a camera. docs/performance.md times wavepath and Cycles on it.
# blender -b --factory-startup -P tools/blender/export_textured_scene.py -- OUT.glb
import bpy, math, os, shutil, sys, tempfile
out = sys.argv[sys.argv.index("--") + 1]
bpy.ops.wm.read_factory_settings(use_empty=True)
images = tempfile.mkdtemp()  # the PNGs, until the exporter has embedded them
def image(name, size, texel):  # an RGBA8 PNG of texel(x, y) -> (r, g, b, a), packed into the file
    img = bpy.data.images.new(name, size, size, alpha=False)
    img.pixels = [v for y in range(size) for x in range(size) for v in texel(x, y)]
    img.filepath_raw = os.path.join(images, name + ".png"); img.file_format = 'PNG'; img.save()
    return img
checker = image("checker", 64, lambda x, y: (0.9, 0.9, 0.9, 1) if (x // 8 + y // 8) % 2 == 0 else (0.1, 0.3, 0.1, 1))
def bump(x, y):  # tangent-space normals of cos bumps, four periods across the image
    nx = 0.5 * math.cos(x / 64 * 8 * math.pi); ny = 0.5 * math.cos(y / 64 * 8 * math.pi)
    l = math.sqrt(nx * nx + ny * ny + 1)
    return (nx / l * 0.5 + 0.5, ny / l * 0.5 + 0.5, 0.5 / l + 0.5, 1)
bumps = image("bumps", 64, bump)
def principled(name):
    m = bpy.data.materials.new(name); m.use_nodes = True
    return m, m.node_tree.nodes["Principled BSDF"], m.node_tree
ground, p, t = principled("ground")
tex = t.nodes.new("ShaderNodeTexImage"); tex.image = checker
t.links.new(tex.outputs["Color"], p.inputs["Base Color"]); p.inputs["Roughness"].default_value = 0.7
bumpy, p, t = principled("bumpy")
p.inputs["Base Color"].default_value = (0.8, 0.5, 0.2, 1); p.inputs["Roughness"].default_value = 0.35
ntex = t.nodes.new("ShaderNodeTexImage"); ntex.image = bumps; bumps.colorspace_settings.name = 'Non-Color'
nmap = t.nodes.new("ShaderNodeNormalMap")
t.links.new(ntex.outputs["Color"], nmap.inputs["Color"]); t.links.new(nmap.outputs["Normal"], p.inputs["Normal"])
emit, p, t = principled("emit")
p.inputs["Base Color"].default_value = (0.1, 0.1, 0.1, 1)
p.inputs["Emission"].default_value = (1.0, 0.6, 0.2, 1); p.inputs["Emission Strength"].default_value = 4.0
glass, p, t = principled("glass")
p.inputs["Base Color"].default_value = (0.95, 0.95, 1.0, 1); p.inputs["Transmission"].default_value = 1.0
p.inputs["Roughness"].default_value = 0.0; p.inputs["IOR"].default_value = 1.5
def placed(material):
    bpy.context.active_object.data.materials.append(material)
bpy.ops.mesh.primitive_plane_add(size=10); placed(ground)
bpy.ops.mesh.primitive_cube_add(size=1.0, location=(-1.3, 0.3, 0.5), rotation=(0, 0, math.radians(30))); placed(bumpy)
bpy.ops.mesh.primitive_uv_sphere_add(segments=48, ring_count=24, radius=0.35, location=(0.2, 0.8, 0.35))
bpy.ops.object.shade_smooth(); placed(emit)
bpy.ops.mesh.primitive_uv_sphere_add(segments=64, ring_count=32, radius=0.5, location=(1.3, -0.2, 0.5))
bpy.ops.object.shade_smooth(); placed(glass)
bpy.ops.object.light_add(type='POINT', location=(1.5, -2.0, 3.0))
bpy.context.active_object.data.energy = 300.0; bpy.context.active_object.data.shadow_soft_size = 0.0
bpy.ops.object.light_add(type='SPOT', location=(-2.5, -1.5, 3.0), rotation=(math.radians(40), 0, math.radians(-50)))
spot = bpy.context.active_object.data
spot.energy = 500.0; spot.spot_size = math.radians(50); spot.spot_blend = 0.3; spot.shadow_soft_size = 0.0
bpy.ops.object.camera_add(location=(0, -5.5, 2.4), rotation=(math.radians(70), 0, 0))
bpy.context.scene.camera = bpy.context.active_object
bpy.ops.export_scene.gltf(filepath=out, export_lights=True, export_cameras=True)
shutil.rmtree(images)
