#!/usr/bin/env python3
"""Writes assets/animated.gltf: a small room with the three kinds of glTF animation.

Run by hand (python3 tools/make_animated_scene.py [output.gltf]); the output is committed.
Python 3 standard library only. In a 2 m room (white floor, ceiling and back wall, red left
and green right wall, a square ceiling light), over 2 s, looping:
- an orange cube bounces and turns about +y (node translation and rotation channels, LINEAR),
- a blue sphere morphs into a rounded cube and back (one morph target, weights CUBICSPLINE
  with zero tangents, so it eases in and out),
- a yellow bar, skinned to a chain of three joints, bends left and right (joint rotations).
"""
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from gltf_builder import UBYTE, UINT, Gltf  # noqa: E402

DURATION = 2.0
LIGHT_RADIANCE = 12.0


def lambert(g, name, albedo):
    return g.material(name=name, pbrMetallicRoughness={"baseColorFactor": [*albedo, 1.0], "metallicFactor": 0.0},
                      extras={"wavepath": {"bsdf": "lambert"}})


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def quads_mesh(g, quads, material):
    """Quads (4 corners, any winding) with the front face towards each quad's `facing`."""
    positions, indices = [], []
    for corners, facing in quads:
        if dot(cross(sub(corners[1], corners[0]), sub(corners[2], corners[0])), facing) < 0:
            corners = corners[::-1]
        base = len(positions) // 3
        for c in corners:
            positions += c
        indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return g.mesh([{"attributes": {"POSITION": g.accessor(positions, "VEC3", minmax=True)},
                    "indices": g.accessor(indices, "SCALAR", UINT), "material": material}])


def box_quads(lo, hi):
    """The six outward-facing faces of an axis-aligned box."""
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    return [
        ([[x0, y0, z0], [x0, y1, z0], [x0, y1, z1], [x0, y0, z1]], [-1, 0, 0]),
        ([[x1, y0, z0], [x1, y1, z0], [x1, y1, z1], [x1, y0, z1]], [1, 0, 0]),
        ([[x0, y0, z0], [x1, y0, z0], [x1, y0, z1], [x0, y0, z1]], [0, -1, 0]),
        ([[x0, y1, z0], [x1, y1, z0], [x1, y1, z1], [x0, y1, z1]], [0, 1, 0]),
        ([[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0]], [0, 0, -1]),
        ([[x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]], [0, 0, 1]),
    ]


def room(g):
    white = lambert(g, "white", [0.75, 0.75, 0.75])
    red = lambert(g, "red", [0.6, 0.05, 0.05])
    green = lambert(g, "green", [0.1, 0.45, 0.08])
    light = g.material(name="light", emissiveFactor=[1.0, 0.9, 0.75],
                       extensions={"KHR_materials_emissive_strength": {"emissiveStrength": LIGHT_RADIANCE}})
    g.doc["extensionsUsed"] = ["KHR_materials_emissive_strength"]
    walls = [
        ([[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]], [0, 1, 0], white),       # floor
        ([[-1, 2, -1], [1, 2, -1], [1, 2, 1], [-1, 2, 1]], [0, -1, 0], white),      # ceiling
        ([[-1, 0, -1], [1, 0, -1], [1, 2, -1], [-1, 2, -1]], [0, 0, 1], white),     # back
        ([[-1, 0, -1], [-1, 2, -1], [-1, 2, 1], [-1, 0, 1]], [1, 0, 0], red),       # left
        ([[1, 0, -1], [1, 2, -1], [1, 2, 1], [1, 0, 1]], [-1, 0, 0], green),        # right
        ([[-0.3, 1.999, -0.3], [0.3, 1.999, -0.3], [0.3, 1.999, 0.3], [-0.3, 1.999, 0.3]], [0, -1, 0], light),
    ]
    for corners, facing, material in walls:
        g.node(mesh=quads_mesh(g, [(corners, facing)], material))


def bouncing_cube(g, channels):
    half = 0.16
    cube = quads_mesh(g, box_quads([-half] * 3, [half] * 3), lambert(g, "orange", [0.8, 0.35, 0.05]))
    node = g.node(name="bouncing cube", mesh=cube, translation=[-0.5, half, 0.1])
    times = [DURATION * k / 16 for k in range(17)]
    heights = [half + 0.7 * abs(math.sin(2 * math.pi * t / DURATION)) for t in times]  # two bounces
    channels.append((node, "translation", "LINEAR", times, [v for y in heights for v in (-0.5, y, 0.1)]))
    quarter_turns = [DURATION * k / 4 for k in range(5)]  # 90 degree steps: slerp needs less than 180
    rotations = []
    for k in range(5):
        angle = math.pi / 2 * k
        rotations += [0, math.sin(angle / 2), 0, math.cos(angle / 2)]
    channels.append((node, "rotation", "LINEAR", quarter_turns, rotations))


def morphing_sphere(g, channels):
    radius, rings, segments = 0.26, 16, 32
    positions, normals, cube_delta, cube_normal_delta, indices = [], [], [], [], []
    for i in range(rings + 1):
        theta = math.pi * i / rings
        for j in range(segments + 1):
            phi = 2 * math.pi * j / segments
            n = [math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi)]
            # The rounded cube: the sphere pushed out towards the cube of the same size.
            m = max(abs(c) for c in n)
            cube = [radius * 0.9 * c / m for c in n]
            axis = max(range(3), key=lambda a: abs(n[a]))
            face = [0.0, 0.0, 0.0]
            face[axis] = math.copysign(1.0, n[axis])
            positions += [radius * c for c in n]
            normals += n
            cube_delta += [cube[a] - radius * n[a] for a in range(3)]
            cube_normal_delta += [face[a] - n[a] for a in range(3)]
    for i in range(rings):
        for j in range(segments):
            a, b = i * (segments + 1) + j, (i + 1) * (segments + 1) + j
            indices += [a, a + 1, b, a + 1, b + 1, b]
    target = {"POSITION": g.accessor(cube_delta, "VEC3", minmax=True), "NORMAL": g.accessor(cube_normal_delta, "VEC3")}
    mesh = g.mesh([{"attributes": {"POSITION": g.accessor(positions, "VEC3", minmax=True),
                                   "NORMAL": g.accessor(normals, "VEC3")},
                    "indices": g.accessor(indices, "SCALAR", UINT), "targets": [target],
                    "material": lambert(g, "blue", [0.1, 0.2, 0.7])}], weights=[0.0])
    node = g.node(name="morphing sphere", mesh=mesh, translation=[0.5, radius, 0.25])
    # (in-tangent, value, out-tangent) per keyframe; zero tangents ease in and out.
    channels.append((node, "weights", "CUBICSPLINE", [0, DURATION / 2, DURATION], [0, 0, 0, 0, 1, 0, 0, 0, 0]))


def skinned_bar(g, channels):
    x, z, half, height, segments = 0.0, -0.55, 0.08, 1.2, 12
    joint_heights = [0.0, height / 3, 2 * height / 3]
    positions, joints, weights, indices = [], [], [], []

    def joint_weights(y):
        """Piecewise linear between the joints above and below, all on the top joint above it."""
        if y >= joint_heights[2]:
            return [2, 0], [255, 0]
        k = 0 if y < joint_heights[1] else 1
        f = (y - joint_heights[k]) / (joint_heights[k + 1] - joint_heights[k])
        upper = round(255 * f)
        return [k, k + 1], [255 - upper, upper]

    corners = [(-half, -half), (half, -half), (half, half), (-half, half)]
    for i in range(segments + 1):
        y = height * i / segments
        js, ws = joint_weights(y)
        for cx, cz in corners:
            positions += [x + cx, y, z + cz]
            joints += [*js, 0, 0]
            weights += [*ws, 0, 0]
    for i in range(segments):
        for c in range(4):
            a, b = i * 4 + c, i * 4 + (c + 1) % 4
            indices += [a, b, b + 4, a, b + 4, a + 4]  # outward-facing sides
    top = segments * 4
    indices += [0, 2, 1, 0, 3, 2, top, top + 1, top + 2, top, top + 2, top + 3]  # bottom and top caps
    mesh = g.mesh([{"attributes": {"POSITION": g.accessor(positions, "VEC3", minmax=True),
                                   "JOINTS_0": g.accessor(joints, "VEC4", UBYTE),
                                   "WEIGHTS_0": g.accessor(weights, "VEC4", UBYTE, normalized=True)},
                    "indices": g.accessor(indices, "SCALAR", UINT),
                    "material": lambert(g, "yellow", [0.8, 0.7, 0.1])}])
    base = g.node(name="bar base", translation=[x, 0, z], children=[len(g.doc["nodes"]) + 1])
    middle = g.node(root=False, name="bar middle", translation=[0, joint_heights[1], 0],
                    children=[len(g.doc["nodes"]) + 1])
    upper = g.node(root=False, name="bar top", translation=[0, joint_heights[2] - joint_heights[1], 0])
    inverse_bind = []
    for h in joint_heights:  # the inverse of each joint's rest world transform, a translation
        inverse_bind += [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -x, -h, -z, 1]
    g.doc["skins"] = [{"joints": [base, middle, upper], "inverseBindMatrices": g.accessor(inverse_bind, "MAT4")}]
    g.node(name="bar", mesh=mesh, skin=0)
    times = [DURATION * k / 8 for k in range(9)]
    for joint in (middle, upper):
        rotation = []
        for t in times:
            angle = math.radians(28) * math.sin(2 * math.pi * t / DURATION)  # about +z
            rotation += [0, 0, math.sin(angle / 2), math.cos(angle / 2)]
        channels.append((joint, "rotation", "LINEAR", times, rotation))


def build():
    g = Gltf()
    room(g)
    channels = []
    bouncing_cube(g, channels)
    morphing_sphere(g, channels)
    skinned_bar(g, channels)
    g.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.8, "aspectRatio": 1.0, "znear": 0.05}}]
    g.node(name="camera", camera=0, translation=[0, 1.0, 2.8])
    g.animation(channels, "demo")
    return g


def main():
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent / "assets" / "animated.gltf"
    build().write(out)


if __name__ == "__main__":
    main()
