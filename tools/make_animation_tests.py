#!/usr/bin/env python3
"""Writes the small animated glTF files of tests/data/ that tests/animation_test.cpp and
tests/cli_test.cpp load: node TRS channels (LINEAR, STEP, CUBICSPLINE), morph targets, a
skin, and one file per kind of bad animation input.

Run by hand (python3 tools/make_animation_tests.py); the outputs are committed. The tests
compute what they expect from the numbers written here, not from wavepath's output.
"""
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from gltf_builder import UBYTE, USHORT, Gltf  # noqa: E402

OUT = Path(__file__).resolve().parent.parent / "tests" / "data"


def triangle_mesh(g):
    """A triangle of dark Lambertian grey (albedo 0.2), which stands out against a white sky."""
    material = g.material(pbrMetallicRoughness={"baseColorFactor": [0.2, 0.2, 0.2, 1]},
                          extras={"wavepath": {"bsdf": "lambert"}})
    positions = g.accessor([0, 0, 0, 1, 0, 0, 0, 1, 0], "VEC3", minmax=True)
    return g.mesh([{"attributes": {"POSITION": positions}, "material": material}])


def trs():
    """Nodes 0 (translated, LINEAR) with child 1, 2 (rotated, LINEAR, second key negated),
    3 (static), 4 (a sphere scaled by CUBICSPLINE), 5 (the camera, translated by STEP)."""
    g = Gltf()
    mesh = triangle_mesh(g)
    g.node(name="mover", mesh=mesh, children=[1])
    g.node(root=False, name="child", mesh=mesh, translation=[0, 0, -1])
    g.node(name="spinner", mesh=mesh)
    g.node(name="static", mesh=mesh, translation=[5, 0, 0])
    g.node(name="ball", translation=[0, 3, 0], extras={"wavepath": {"shape": "sphere", "radius": 0.5}})
    g.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}]
    g.node(name="eye", camera=0, translation=[0, 0, 5])
    s60, c60 = math.sin(math.radians(60)), math.cos(math.radians(60))
    g.animation([
        (0, "translation", "LINEAR", [0, 1], [0, 0, 0, 2, 0, 0]),
        # 120 degrees about +y over 2 s, the end written as -q: the same rotation, which
        # slerp along the shorter arc must reach through +60 degrees at 1 s.
        (2, "rotation", "LINEAR", [0, 2], [0, 0, 0, 1, 0, -s60, 0, -c60]),
        # (in-tangent, value, out-tangent) per keyframe
        (4, "scale", "CUBICSPLINE", [0, 1], [0, 0, 0, 1, 1, 1, 1, 1, 1, -1, -1, -1, 2, 2, 2, 0, 0, 0]),
        (5, "translation", "STEP", [0, 1], [0, 0, 5, 0, 1, 5]),
    ])
    return g


def morph(g=None, second_primitive_targets=None):
    """One triangle with NORMALs and two morph targets; mesh weights (0.5, 0), animated
    (0, 0) -> (1, 1) over 2 s on node 0; node 1 uses the mesh with its own weights (0, 1)."""
    g = g or Gltf()
    positions = g.accessor([0, 0, 0, 1, 0, 0, 0, 1, 0], "VEC3", minmax=True)
    normals = g.accessor([0, 0, 1] * 3, "VEC3")
    t0 = {"POSITION": g.accessor([0, 0, 1, 0, 0, 0, 0, 0, 0], "VEC3", minmax=True),
          "NORMAL": g.accessor([1, 0, 0, 0, 0, 0, 0, 0, 0], "VEC3")}
    t1 = {"POSITION": g.accessor([0, 0, 0, 1, 0, 0, 0, 0, 0], "VEC3", minmax=True)}
    primitives = [{"attributes": {"POSITION": positions, "NORMAL": normals}, "targets": [t0, t1]}]
    if second_primitive_targets is not None:
        primitives.append({"attributes": {"POSITION": positions}, "targets": second_primitive_targets(t0, t1)})
    mesh = g.mesh(primitives, weights=[0.5, 0])
    g.node(name="morphed", mesh=mesh)
    g.node(name="own weights", mesh=mesh, weights=[0, 1], translation=[0, 0, -2])
    g.animation([(0, "weights", "LINEAR", [0, 2], [0, 0, 1, 1])])
    return g


def skin():
    """A bar from x = 0 to 2 (vertices at x = 0, 1, 2 and y = 0, 1) skinned to joint 0 at the
    origin and its child joint 1 at x = 1, which turns 90 degrees about +z over 1 s. The
    middle vertices weigh both joints half (normalized UNSIGNED_BYTE weights, UNSIGNED_SHORT
    joints). The mesh node's translation (10, 0, 0) must be ignored, as glTF says."""
    g = Gltf()
    positions = g.accessor([0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0], "VEC3", minmax=True)
    indices = g.accessor([0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4], "SCALAR", USHORT)
    joints = g.accessor([0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0] * 2, "VEC4", USHORT)
    weights = g.accessor([255, 0, 0, 0, 128, 128, 0, 0, 255, 0, 0, 0] * 2, "VEC4", UBYTE, normalized=True)
    mesh = g.mesh([{"attributes": {"POSITION": positions, "JOINTS_0": joints, "WEIGHTS_0": weights},
                    "indices": indices}])
    j0 = g.node(name="root joint", children=[1])
    j1 = g.node(root=False, name="elbow", translation=[1, 0, 0])
    inverse_bind = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
                    1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 1]
    g.doc["skins"] = [{"joints": [j0, j1], "inverseBindMatrices": g.accessor(inverse_bind, "MAT4")}]
    g.node(name="bar", mesh=mesh, skin=0, translation=[10, 0, 0])
    s45 = math.sin(math.radians(45))
    g.animation([(j1, "rotation", "LINEAR", [0, 1], [0, 0, 0, 1, 0, 0, s45, s45])])
    return g


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    trs().write(OUT / "anim_trs.gltf")
    morph().write(OUT / "anim_morph.gltf")
    skin().write(OUT / "anim_skin.gltf")

    g = trs()
    g.doc["animations"][0]["channels"][0]["target"]["node"] = 99
    g.write(OUT / "bad_channel_node.gltf")

    g = trs()
    g.doc["animations"][0]["samplers"][0]["input"] = g.accessor([0, 1, 1], "SCALAR")
    g.doc["animations"][0]["samplers"][0]["output"] = g.accessor([0, 0, 0, 1, 0, 0, 2, 0, 0], "VEC3")
    g.write(OUT / "bad_input_order.gltf")

    g = trs()
    g.doc["animations"][0]["samplers"][0]["output"] = g.accessor([0, 0, 0, 1, 0, 0, 2, 0, 0], "VEC3")
    g.write(OUT / "bad_output_count.gltf")

    g = trs()
    g.doc["animations"][0]["samplers"][0]["interpolation"] = "SMOOTH"
    g.write(OUT / "bad_interpolation.gltf")

    morph(second_primitive_targets=lambda t0, t1: [t0]).write(OUT / "bad_morph_count.gltf")

    g = morph()
    g.doc["meshes"][0]["weights"] = [0, 0, 0]
    g.write(OUT / "bad_mesh_weights.gltf")

    g = morph()
    g.doc["animations"][0]["samplers"][0]["output"] = g.accessor([0, 0, 0, 1, 1, 1], "SCALAR")
    g.write(OUT / "bad_weights_count.gltf")


if __name__ == "__main__":
    main()
