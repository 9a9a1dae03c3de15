#!/usr/bin/env python3
"""Writes assets/lamps.gltf: a small room corner lit only by KHR_lights_punctual lamps.

Run by hand (python3 tools/make_lamps_scene.py [output.gltf]); the output is committed.
Python 3 standard library only. Everything is plain glTF 2.0 as an exporter writes it
(triangle meshes, metallic-roughness materials without extras, a perspective camera), so
Blender's importer reads the same scene: the README's lamp figure, and the file the lamp
tests and the Blender comparison render.

The lamps, at the strengths a Blender user gives them and in the units its exporter writes
(cd = W * 683 / (4 pi) for point and spot, lux = W/m^2 * 683 for the sun): a warm 300 W
point light above the left, a cool 800 W spot (cones 15 and 25 degrees) aimed at the sphere
from the right, and a low 1 W/m^2 sun from behind the camera's left, all three in
extensionsRequired as Blender writes them. A matte floor and back wall, a
white dielectric sphere, a red cube and a brushed gold slab.
"""
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from gltf_builder import Gltf, UINT  # noqa: E402


def quad(g, corner, edge_u, edge_v, normal):
    positions = []
    for (a, b) in [(0, 0), (1, 0), (1, 1), (0, 1)]:
        positions += [corner[k] + a * edge_u[k] + b * edge_v[k] for k in range(3)]
    return positions, [normal] * 4, [0, 1, 2, 0, 2, 3]


def box(center, half):
    """Positions, normals and indices of an axis-aligned box, 4 vertices a face."""
    positions, normals, indices = [], [], []
    for axis in range(3):
        for sign in (-1, 1):
            n = [0.0, 0.0, 0.0]
            n[axis] = float(sign)
            u, v = (axis + 1) % 3, (axis + 2) % 3
            if sign < 0:
                u, v = v, u
            base = len(positions) // 3
            for a, b in [(-1, -1), (1, -1), (1, 1), (-1, 1)]:
                p = list(center)
                p[axis] += sign * half[axis]
                p[u] += a * half[u]
                p[v] += b * half[v]
                positions += p
                normals += n
            indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return positions, normals, indices


def uv_sphere(center, radius, rings=24, segments=48):
    positions, normals, indices = [], [], []
    for i in range(rings + 1):
        theta = math.pi * i / rings
        for j in range(segments + 1):
            phi = 2 * math.pi * j / segments
            n = [math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi)]
            positions += [center[k] + radius * n[k] for k in range(3)]
            normals += n
    for i in range(rings):
        for j in range(segments):
            a = i * (segments + 1) + j
            b = a + segments + 1
            indices += [a, a + 1, b, b, a + 1, b + 1]
    return positions, normals, indices


def add_mesh(g, name, geometry, material):
    positions, normals, indices = geometry
    if isinstance(normals[0], list):
        normals = [c for n in normals for c in n]
    primitive = {"attributes": {"POSITION": g.accessor(positions, "VEC3", minmax=True),
                                "NORMAL": g.accessor(normals, "VEC3")},
                 "indices": g.accessor(indices, "SCALAR", UINT), "material": material}
    g.node(mesh=g.mesh([primitive], name=name), name=name)


def look_at_rotation(eye, target):
    """The quaternion (x, y, z, w) turning -z towards target with +y up."""
    f = [target[k] - eye[k] for k in range(3)]
    n = math.sqrt(sum(c * c for c in f))
    f = [c / n for c in f]
    r = [-f[2], 0.0, f[0]]  # cross(f, up) with up = +y
    rn = math.sqrt(sum(c * c for c in r))
    r = [c / rn for c in r]
    u = [r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]]
    # Rotation matrix columns: x = r, y = u, z = -f.
    m = [[r[0], u[0], -f[0]], [r[1], u[1], -f[1]], [r[2], u[2], -f[2]]]
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0:
        s = 0.5 / math.sqrt(trace + 1.0)
        return [(m[2][1] - m[1][2]) * s, (m[0][2] - m[2][0]) * s, (m[1][0] - m[0][1]) * s, 0.25 / s]
    i = max(range(3), key=lambda k: m[k][k])
    j, k = (i + 1) % 3, (i + 2) % 3
    s = 2.0 * math.sqrt(1.0 + m[i][i] - m[j][j] - m[k][k])
    q = [0.0, 0.0, 0.0, (m[k][j] - m[j][k]) / s]
    q[i] = 0.25 * s
    q[j] = (m[j][i] + m[i][j]) / s
    q[k] = (m[k][i] + m[i][k]) / s
    return q


def blender_watts(watts):
    """The candela Blender's exporter writes for a point or spot lamp of `watts`."""
    return watts * 683.0 / (4.0 * math.pi)


def main():
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent / "assets" / "lamps.gltf"
    g = Gltf()
    matte = g.material(name="matte", pbrMetallicRoughness={"baseColorFactor": [0.8, 0.8, 0.8, 1.0],
                                                           "metallicFactor": 0.0, "roughnessFactor": 1.0})
    white = g.material(name="white", pbrMetallicRoughness={"baseColorFactor": [0.9, 0.9, 0.9, 1.0],
                                                           "metallicFactor": 0.0, "roughnessFactor": 0.3})
    red = g.material(name="red", pbrMetallicRoughness={"baseColorFactor": [0.7, 0.06, 0.05, 1.0],
                                                       "metallicFactor": 0.0, "roughnessFactor": 0.6})
    gold = g.material(name="gold", pbrMetallicRoughness={"baseColorFactor": [1.0, 0.766, 0.336, 1.0],
                                                         "metallicFactor": 1.0, "roughnessFactor": 0.35})
    add_mesh(g, "floor", quad(g, [-3, 0, -2.5], [0, 0, 5], [6, 0, 0], [0, 1, 0]), matte)
    add_mesh(g, "wall", quad(g, [-3, 0, -2.5], [6, 0, 0], [0, 3, 0], [0, 0, 1]), matte)
    add_mesh(g, "sphere", uv_sphere([0.2, 0.6, -0.4], 0.6), white)
    add_mesh(g, "cube", box([-1.5, 0.4, 0.2], [0.4, 0.4, 0.4]), red)
    add_mesh(g, "slab", box([1.6, 0.15, 0.4], [0.6, 0.15, 0.45]), gold)

    g.doc["extensionsUsed"] = ["KHR_lights_punctual"]
    g.doc["extensionsRequired"] = ["KHR_lights_punctual"]
    g.doc["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "bulb", "type": "point", "color": [1.0, 0.85, 0.6], "intensity": blender_watts(300.0)},
        {"name": "spot", "type": "spot", "color": [0.6, 0.8, 1.0], "intensity": blender_watts(800.0),
         "spot": {"innerConeAngle": math.radians(15), "outerConeAngle": math.radians(25)}},
        {"name": "sun", "type": "directional", "color": [1.0, 0.95, 0.9], "intensity": 1.0 * 683.0}]}}
    g.node(name="bulb", translation=[-1.6, 2.2, 0.6], extensions={"KHR_lights_punctual": {"light": 0}})
    spot_at = [2.6, 2.4, 1.6]
    g.node(name="spot", translation=spot_at, rotation=look_at_rotation(spot_at, [0.2, 0.6, -0.4]),
           extensions={"KHR_lights_punctual": {"light": 1}})
    sun_from = [-3.0, 2.0, 4.0]
    g.node(name="sun", rotation=look_at_rotation(sun_from, [0.0, 0.0, 0.0]),
           extensions={"KHR_lights_punctual": {"light": 2}})

    eye = [0.4, 2.0, 5.2]
    g.doc["cameras"] = [{"name": "camera", "type": "perspective",
                         "perspective": {"yfov": math.radians(38), "aspectRatio": 1.6, "znear": 0.05}}]
    g.node(name="camera", camera=0, translation=eye, rotation=look_at_rotation(eye, [0.1, 0.6, -0.5]))
    g.write(out)


if __name__ == "__main__":
    main()
