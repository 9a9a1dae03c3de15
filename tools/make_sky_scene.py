#!/usr/bin/env python3
"""Writes assets/sky-spheres.gltf: three Lambertian spheres on a ground plane, lit by nothing
but a sky (render it with --sky assets/sky.hdr), for the camera and sky pictures of
docs/camera-and-sky.md. Spheres and the plane use wavepath's node extras (docs/scenes.md)."""
import json
import math
import pathlib

# Pure Lambertian surfaces (wavepath's material extras), as the pictures in docs/ show them.
LAMBERT = {"extras": {"wavepath": {"bsdf": "lambert"}}}

def sphere(x, z, material):
    return {"translation": [x, 0.5, z],
            "extras": {"wavepath": {"shape": "sphere", "radius": 0.5, "material": material}}}

def main():
    pitch = math.radians(-8.0)  # the camera looks slightly down
    scene = {
        "asset": {"version": "2.0", "generator": "wavepath tools/make_sky_scene.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2, 3, 4]}],
        "nodes": [
            {"extras": {"wavepath": {"shape": "plane", "material": 0}}},
            sphere(-1.3, -1.6, 1),
            sphere(0.0, 0.0, 2),
            sphere(1.1, 0.6, 3),
            {"camera": 0, "translation": [0.0, 0.8, 2.7],
             "rotation": [math.sin(pitch / 2), 0.0, 0.0, math.cos(pitch / 2)]},
        ],
        "cameras": [{"type": "perspective",
                     "perspective": {"yfov": 0.6, "aspectRatio": 16 / 9, "znear": 0.01}}],
        "materials": [
            {"name": "ground", "pbrMetallicRoughness": {"baseColorFactor": [0.45, 0.45, 0.45, 1]}, **LAMBERT},
            {"name": "white", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1]}, **LAMBERT},
            {"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.25, 0.2, 1]}, **LAMBERT},
            {"name": "blue", "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.35, 0.8, 1]}, **LAMBERT},
        ],
    }
    out = pathlib.Path(__file__).resolve().parent.parent / "assets" / "sky-spheres.gltf"
    out.write_text(json.dumps(scene, indent=1) + "\n")

if __name__ == "__main__":
    main()
