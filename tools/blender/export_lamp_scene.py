# Measurement only: builds a lamp-lit scene in Blender, renders it with Cycles, exports it with
import numpy; numpy.bool = bool
# Blender's glTF exporter. blender -b --factory-startup -P roundtrip.py -- OUTDIR SPP
import bpy, math, os, sys
args = sys.argv[sys.argv.index("--") + 1:]
out, spp, lambert = args[0], int(args[1]), "lambert" in args[2:]
for ob in list(bpy.data.objects): bpy.data.objects.remove(ob, do_unlink=True)
def diffuse(name, rgb):
    m = bpy.data.materials.new(name); m.use_nodes = True; nt = m.node_tree
    nt.nodes.remove(nt.nodes["Principled BSDF"])
    d = nt.nodes.new("ShaderNodeBsdfDiffuse"); d.inputs["Color"].default_value = (*rgb, 1)
    d.inputs["Roughness"].default_value = 0
    nt.links.new(d.outputs[0], nt.nodes["Material Output"].inputs["Surface"])
    return m
def principled(name, rgb, metallic, roughness):
    if lambert: return diffuse(name, rgb)
    m = bpy.data.materials.new(name); m.use_nodes = True
    p = m.node_tree.nodes["Principled BSDF"]
    p.inputs["Base Color"].default_value = (*rgb, 1); p.inputs["Metallic"].default_value = metallic
    p.inputs["Roughness"].default_value = roughness
    return m
def add(op, mat, **kw):
    op(**kw); ob = bpy.context.active_object; ob.data.materials.append(mat); return ob
matte = principled("matte", (0.8, 0.8, 0.8), 0, 1.0)
add(bpy.ops.mesh.primitive_plane_add, matte, size=8, location=(0, 0, 0))
wall = add(bpy.ops.mesh.primitive_plane_add, matte, size=8, location=(0, 3, 4)); wall.rotation_euler = (math.radians(90), 0, 0)
s = add(bpy.ops.mesh.primitive_uv_sphere_add, principled("white", (0.9, 0.9, 0.9), 0, 0.3), radius=0.6, location=(0.2, 0.4, 0.6), segments=64, ring_count=32)
bpy.ops.object.shade_smooth()
add(bpy.ops.mesh.primitive_cube_add, principled("red", (0.7, 0.06, 0.05), 0, 0.6), size=0.8, location=(-1.5, -0.2, 0.4))
add(bpy.ops.mesh.primitive_cube_add, principled("gold", (1.0, 0.766, 0.336), 1, 0.35), size=1, location=(1.6, -0.4, 0.15)).scale = (1.2, 0.9, 0.3)
def lamp(kind, energy, loc, rot=(0, 0, 0), color=(1, 1, 1)):
    d = bpy.data.lights.new(kind, kind); d.energy = energy; d.color = color
    if kind in ("POINT", "SPOT"): d.shadow_soft_size = 0.0
    if kind == "SUN": d.angle = 0.0
    if kind == "SPOT": d.spot_size = math.radians(50); d.spot_blend = 0.4
    o = bpy.data.objects.new(kind, d); o.location = loc; o.rotation_euler = rot; bpy.context.scene.collection.objects.link(o)
lamp("POINT", 300, (-1.6, -0.6, 2.2), color=(1, 0.85, 0.6))
lamp("SPOT", 800, (2.6, -1.6, 2.4), (math.radians(50), 0, math.radians(60)), color=(0.6, 0.8, 1))
lamp("SUN", 1.0, (0, 0, 5), (math.radians(60), 0, math.radians(-30)))
cam = bpy.data.objects.new("camera", bpy.data.cameras.new("camera")); cam.location = (0.4, -5.2, 2.0)
cam.rotation_euler = (math.radians(78), 0, 0); bpy.context.scene.collection.objects.link(cam); bpy.context.scene.camera = cam
sc = bpy.context.scene; sc.render.engine = "CYCLES"; sc.cycles.samples = spp; sc.cycles.use_denoising = False
sc.render.resolution_x, sc.render.resolution_y = 320, 200
sc.cycles.max_bounces = 8; sc.cycles.diffuse_bounces = sc.cycles.glossy_bounces = 8
sc.cycles.pixel_filter_type = "BOX"; sc.cycles.filter_width = 1.0
sc.view_settings.view_transform = "Standard"
w = bpy.data.worlds.new("black"); w.use_nodes = True; w.node_tree.nodes["Background"].inputs["Strength"].default_value = 0; sc.world = w
sc.render.image_settings.file_format = "OPEN_EXR"; sc.render.image_settings.color_depth = "32"
sc.render.filepath = os.path.join(out, "cycles.exr"); sc.render.use_file_extension = False
bpy.ops.render.render(write_still=True)
bpy.ops.export_scene.gltf(filepath=os.path.join(out, "scene.gltf"), export_format="GLTF_SEPARATE", export_lights=True, export_cameras=True)
print("export_lamp_scene: wrote", out)
