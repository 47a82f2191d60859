#!/usr/bin/env python3
"""Writes the glTF file of scenes/examples/gltf.json: one .glb that shows what candela reads from
glTF (docs/scene-format.md, *glTF meshes*, *A camera from a glTF file*, *Lights from a glTF
file*): a camera, a spot light (KHR_lights_punctual), a node tree, one sphere mesh placed by three
nodes,
each mesh with a material of its own (a metal-rough mix by a texture under a clear coat
(KHR_materials_clearcoat), glass by
KHR_materials_transmission, an emission with KHR_materials_emissive_strength), a ground tiled by
KHR_texture_transform and a screen of holes cut by MASK alpha, the images held in the buffer.

    python3 tools/make_gltf_example.py scenes/meshes/gltf_showcase.glb

Standard library only, so that the file can be made again anywhere.
"""
import json
import math
import struct
import sys

from png8 import png8


class Glb:
    def __init__(self):
        self.buffer = bytearray()
        self.views, self.accessors, self.images = [], [], []

    def view(self, data):
        while len(self.buffer) % 4:
            self.buffer.append(0)
        self.views.append({"buffer": 0, "byteOffset": len(self.buffer), "byteLength": len(data)})
        self.buffer.extend(data)
        return len(self.views) - 1

    def accessor(self, values, fmt, component, kind, count, bounds=False):
        entry = {"bufferView": self.view(struct.pack('<%d%s' % (len(values), fmt), *values)),
                 "componentType": component, "count": count, "type": kind}
        if bounds:  # glTF asks POSITION accessors for their bounds
            entry["min"] = [min(values[i::3]) for i in range(3)]
            entry["max"] = [max(values[i::3]) for i in range(3)]
        self.accessors.append(entry)
        return len(self.accessors) - 1

    def image(self, png):
        self.images.append({"bufferView": self.view(png), "mimeType": "image/png"})
        return len(self.images) - 1


def sphere(glb, rings=24, segments=48):
    """A unit UV sphere: positions, normals, uvs (glTF's: v down the image) and indices."""
    pos, uv, idx = [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            pos += [math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi)]
            uv += [s / segments, r / rings]
    for r in range(rings):
        for s in range(segments):
            a, b = r * (segments + 1) + s, (r + 1) * (segments + 1) + s
            idx += [a, b, a + 1, a + 1, b, b + 1]
    n = len(pos) // 3
    return {"POSITION": glb.accessor(pos, 'f', 5126, "VEC3", n, True),
            "NORMAL": glb.accessor(pos, 'f', 5126, "VEC3", n),
            "TEXCOORD_0": glb.accessor(uv, 'f', 5126, "VEC2", n)}, \
        glb.accessor(idx, 'H', 5123, "SCALAR", len(idx))


def quad(glb, half, uv_repeat):
    """A square in y = 0 facing +y."""
    pos = [-half, 0, half, half, 0, half, half, 0, -half, -half, 0, -half]
    uv = [0, uv_repeat, uv_repeat, uv_repeat, uv_repeat, 0, 0, 0]
    return {"POSITION": glb.accessor(pos, 'f', 5126, "VEC3", 4, True),
            "NORMAL": glb.accessor([0, 1, 0] * 4, 'f', 5126, "VEC3", 4),
            "TEXCOORD_0": glb.accessor(uv, 'f', 5126, "VEC2", 4)}, \
        glb.accessor([0, 1, 2, 0, 2, 3], 'H', 5123, "SCALAR", 6)


def look_at(eye, target):
    """The quaternion (x, y, z, w) that turns a glTF camera or light (along -z, +y up) at `eye`
    towards `target`, keeping the world's +y up."""
    f = [t - e for t, e in zip(target, eye)]
    n = math.sqrt(sum(c * c for c in f))
    back = [-c / n for c in f]
    right = [back[2], 0.0, -back[0]]  # (0, 1, 0) x back
    n = math.sqrt(sum(c * c for c in right))
    right = [c / n for c in right]
    up = [back[1] * right[2] - back[2] * right[1], back[2] * right[0] - back[0] * right[2],
          back[0] * right[1] - back[1] * right[0]]
    m = [[right[0], up[0], back[0]], [right[1], up[1], back[1]], [right[2], up[2], back[2]]]
    w = math.sqrt(max(0.0, 1 + m[0][0] + m[1][1] + m[2][2])) / 2
    return [(m[2][1] - m[1][2]) / (4 * w), (m[0][2] - m[2][0]) / (4 * w),
            (m[1][0] - m[0][1]) / (4 * w), w]


def checker(size, cells, a, b):
    return png8(size, size, [[c for x in range(size) for c in
                              (a if (x * cells // size + y * cells // size) % 2 else b)]
                             for y in range(size)])


def main(path):
    glb = Glb()
    # The sphere's base colour: terracotta and cream checks; its metal-roughness map: stripes of
    # polished metal (roughness 0.15, metalness 1) and rough plastic (0.6, 0), green and blue.
    colour = glb.image(checker(64, 8, (200, 90, 50), (235, 225, 200)))
    metal_rough = glb.image(png8(64, 64, [[c for x in range(64) for c in
                                           ((0, 38, 255) if (x // 8) % 2 else (0, 153, 0))]
                                          for _ in range(64)]))
    tiles = glb.image(checker(64, 2, (90, 90, 95), (160, 160, 165)))
    holes = glb.image(png8(64, 64, [[c for x in range(64) for c in
                                     (255, 255, 255, 0 if (x % 16 - 8) ** 2 + (y % 16 - 8) ** 2 < 30
                                      else 255)]
                                    for y in range(64)], channels=4))
    textures = [{"source": i} for i in (colour, metal_rough, tiles, holes)]
    attributes, indices = sphere(glb)
    ground_attr, ground_idx = quad(glb, 6, 1)
    screen_attr, screen_idx = quad(glb, 1, 1)
    materials = [
        {"name": "striped", "pbrMetallicRoughness": {
            "baseColorTexture": {"index": 0}, "metallicRoughnessTexture": {"index": 1}},
         "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1,
                                                    "clearcoatRoughnessFactor": 0.05}}},
        {"name": "glass", "pbrMetallicRoughness": {
            "baseColorFactor": [0.95, 0.98, 1, 1], "metallicFactor": 0, "roughnessFactor": 0.05},
         "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1},
                        "KHR_materials_ior": {"ior": 1.5}}},
        {"name": "lantern", "pbrMetallicRoughness": {
            "baseColorFactor": [0.1, 0.1, 0.1, 1], "metallicFactor": 0, "roughnessFactor": 0.3},
         "emissiveFactor": [1, 0.55, 0.2],
         "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 1.5}}},
        {"name": "tiles", "pbrMetallicRoughness": {
            "baseColorTexture": {"index": 2, "extensions": {"KHR_texture_transform": {
                "scale": [6, 6], "rotation": 0.3}}},
            "metallicFactor": 0, "roughnessFactor": 0.7}},
        {"name": "screen", "pbrMetallicRoughness": {
            "baseColorFactor": [0.9, 0.85, 0.3, 1], "baseColorTexture": {"index": 3},
            "metallicFactor": 1, "roughnessFactor": 0.35},
         "alphaMode": "MASK", "doubleSided": True},
    ]
    meshes = [{"primitives": [{"attributes": attributes, "indices": indices, "material": m}]}
              for m in range(3)]
    meshes.append({"primitives": [{"attributes": ground_attr, "indices": ground_idx, "material": 3}]})
    meshes.append({"primitives": [{"attributes": screen_attr, "indices": screen_idx, "material": 4}]})
    s = math.sqrt(0.5)
    camera = look_at((0.4, 2.5, 9.5), (0.0, 0.9, 0.0))
    nodes = [
        {"name": "root", "children": [1, 2, 3, 4, 5], "rotation": [0, math.sin(0.15), 0, math.cos(0.15)]},
        {"mesh": 0, "translation": [-2.2, 1, 0]},
        {"mesh": 1, "translation": [0, 1, 0]},
        {"mesh": 2, "translation": [2.2, 0.6, 0.4], "scale": [0.6, 0.6, 0.6]},
        {"mesh": 3},
        {"mesh": 4, "translation": [0, 1.3, -2.2], "rotation": [s, 0, 0, s], "scale": [2.6, 1, 1.3]},
        {"name": "camera", "camera": 0, "translation": [0.4, 2.5, 9.5], "rotation": camera},
        {"name": "spot", "translation": [-3.5, 6, 3], "rotation": look_at((-3.5, 6, 3), (-0.3, 0, 2.4)),
         "extensions": {"KHR_lights_punctual": {"light": 0}}},
    ]
    # A narrow warm spot of 300,000 cd: an irradiance of about 9 where it points, 6.8 away, a pool
    # on the tiles beside the sky's light.
    lights = {"lights": [{"type": "spot", "color": [1, 0.85, 0.65], "intensity": 300000,
                          "spot": {"innerConeAngle": 0.14, "outerConeAngle": 0.22}}]}
    # 44 degrees across a 16:9 image.
    cameras = [{"type": "perspective", "perspective": {
        "yfov": 2 * math.atan(math.tan(math.radians(22)) * 9 / 16), "aspectRatio": 16 / 9,
        "znear": 0.05}}]
    while len(glb.buffer) % 4:
        glb.buffer.append(0)
    doc = {"asset": {"version": "2.0", "generator": "candela tools/make_gltf_example.py"},
           "extensionsUsed": ["KHR_materials_transmission", "KHR_materials_ior",
                              "KHR_materials_emissive_strength", "KHR_texture_transform",
                              "KHR_lights_punctual", "KHR_materials_clearcoat"],
           "extensions": {"KHR_lights_punctual": lights},
           "scene": 0, "scenes": [{"nodes": [0, 6, 7]}], "nodes": nodes, "meshes": meshes,
           "cameras": cameras,
           "materials": materials, "textures": textures, "images": glb.images,
           "accessors": glb.accessors, "bufferViews": glb.views,
           "buffers": [{"byteLength": len(glb.buffer)}]}
    text = json.dumps(doc, separators=(',', ':')).encode()
    text += b' ' * (-len(text) % 4)
    with open(path, 'wb') as f:
        f.write(b'glTF' + struct.pack('<II', 2, 12 + 8 + len(text) + 8 + len(glb.buffer)))
        f.write(struct.pack('<I', len(text)) + b'JSON' + text)
        f.write(struct.pack('<I', len(glb.buffer)) + b'BIN\0' + bytes(glb.buffer))


if __name__ == '__main__':
    main(sys.argv[1])
