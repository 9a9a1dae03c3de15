"""Imports a glTF file with Blender's own importer and renders it with Cycles, to compare with
wavepath's render of the same file (docs/lights.md, "Against Blender").

Measurement only (needs `apt-get install blender python3-numpy`; never used by the install step
or the tests):
    blender -b --factory-startup -noaudio -P tools/blender/import_and_render.py -- IN.gltf OUT.exr SPP WIDTH HEIGHT [unbiased] [time=SECONDS]
renders through the file's first camera with a box filter, 8 bounces, a black world and no
adaptive sampling. Blender's other defaults stay, among them two biased ones: Filter Glossy 1
(wavepath's --filter-glossy 1 is the same rule) and Clamp Indirect 10; "unbiased" turns both off.
"time=SECONDS" sets Cycles' Time Limit (SPP is then the most it renders), as wavepath's
--time-limit; Cycles prints the samples it reached ("Sample N/SPP").
"""
import numpy; numpy.bool = bool  # Blender 3.4's importer expects an older numpy
import bpy, sys
a = sys.argv[sys.argv.index("--") + 1:]
src, out, spp, w, h = a[0], a[1], int(a[2]), int(a[3]), int(a[4])
for ob in list(bpy.data.objects): bpy.data.objects.remove(ob, do_unlink=True)
bpy.ops.import_scene.gltf(filepath=src)
sc = bpy.context.scene
cams = [o for o in sc.objects if o.type == "CAMERA"]; sc.camera = cams[0]
sc.render.engine = "CYCLES"; sc.cycles.samples = spp; sc.cycles.use_denoising = False
# Every pixel gets its spp, as wavepath's do: Blender's default noise threshold would let Cycles
# stop converged pixels early (at the benchmark's 16 and 64 spp the times were the same with it
# on and off, but at higher counts it would render fewer samples than asked).
sc.cycles.use_adaptive_sampling = False
sc.render.resolution_x, sc.render.resolution_y = w, h
sc.cycles.max_bounces = 8; sc.cycles.diffuse_bounces = sc.cycles.glossy_bounces = 8
sc.cycles.pixel_filter_type = "BOX"; sc.cycles.filter_width = 1.0; sc.view_settings.view_transform = "Standard"
wd = bpy.data.worlds.new("black"); wd.use_nodes = True; wd.node_tree.nodes["Background"].inputs["Strength"].default_value = 0; sc.world = wd
sc.render.image_settings.file_format = "OPEN_EXR"; sc.render.image_settings.color_depth = "32"
sc.render.filepath = out; sc.render.use_file_extension = False
options = a[5:]
if "unbiased" in options: sc.cycles.blur_glossy = 0.0; sc.cycles.sample_clamp_indirect = 0.0
for o in options:
    if o.startswith("time="): sc.cycles.time_limit = float(o[len("time="):])
bpy.ops.render.render(write_still=True); print("import_and_render: wrote", out)
