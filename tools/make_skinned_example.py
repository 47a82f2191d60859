#!/usr/bin/env python3
"""Writes the glTF file of scenes/examples/gltf_animation.json: one .glb whose animation "dance"
moves its meshes apart (docs/scene-format.md, *glTF meshes*): a tapering tentacle skinned to a
chain of five joints that sway, each a little after the one below it, and a ball whose morph
target swells it into a flower and back.

    python3 tools/make_skinned_example.py scenes/meshes/skinned_showcase.glb

Standard library only, so that the file can be made again anywhere.
"""
import json
import math
import struct
import sys

from make_gltf_example import Glb

FLOAT, UBYTE, USHORT = 5126, 5121, 5123
SECONDS, KEYS = 2.0, 25  # the animation's length, and its keys (the last equals the first)
JOINTS, SEGMENT = 5, 0.8  # the tentacle's joints, and the length of each bone


def normals_of(pos, idx):
    """Area-weighted vertex normals of a triangle mesh."""
    n = [0.0] * len(pos)
    for t in range(0, len(idx), 3):
        a, b, c = (idx[t + k] for k in range(3))
        p = [pos[3 * v:3 * v + 3] for v in (a, b, c)]
        e1 = [p[1][i] - p[0][i] for i in range(3)]
        e2 = [p[2][i] - p[0][i] for i in range(3)]
        f = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
             e1[0] * e2[1] - e1[1] * e2[0]]
        for v in (a, b, c):
            for i in range(3):
                n[3 * v + i] += f[i]
    for v in range(len(pos) // 3):
        length = math.sqrt(sum(n[3 * v + i] ** 2 for i in range(3))) or 1.0
        for i in range(3):
            n[3 * v + i] /= length
    return n


def grid_indices(rows, columns):
    """Two triangles per cell of a (rows + 1) x (columns + 1) grid of vertices, wound outwards."""
    idx = []
    for r in range(rows):
        for s in range(columns):
            a, b = r * (columns + 1) + s, (r + 1) * (columns + 1) + s
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return idx


def tentacle(glb):
    """A tube along +y, tapering from radius 0.35 to 0.08 over the chain's length, each vertex
    weighted between the two joints nearest it; returns the mesh's primitive."""
    rings, segments, length = 40, 32, JOINTS * SEGMENT
    pos, joints, weights = [], [], []
    for r in range(rings + 1):
        y = length * r / rings
        radius = 0.35 + (0.08 - 0.35) * r / rings
        # The bone this ring lies on, and how far along it: weights shift to the next joint over
        # the bone's second half.
        bone = min(int(y / SEGMENT), JOINTS - 1)
        along = y / SEGMENT - bone
        share = max(0.0, min(1.0, (along - 0.5) * 2)) if bone < JOINTS - 1 else 0.0
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            pos += [radius * math.cos(phi), y, -radius * math.sin(phi)]
            joints += [bone, min(bone + 1, JOINTS - 1), 0, 0]
            weights += [1.0 - share, share, 0.0, 0.0]
    idx = grid_indices(rings, segments)
    count = len(pos) // 3
    return {"attributes": {
        "POSITION": glb.accessor(pos, 'f', FLOAT, "VEC3", count, bounds=True),
        "NORMAL": glb.accessor(normals_of(pos, idx), 'f', FLOAT, "VEC3", count),
        "JOINTS_0": glb.accessor(joints, 'B', UBYTE, "VEC4", count),
        "WEIGHTS_0": glb.accessor(weights, 'f', FLOAT, "VEC4", count)},
        "indices": glb.accessor(idx, 'H', USHORT, "SCALAR", len(idx)), "material": 0}


def flower(glb):
    """A unit sphere and a morph target that swells it into six petals; returns the primitive."""
    rings, segments = 48, 96
    pos, bloom = [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            d = [math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi)]
            swell = 0.45 * max(0.0, math.cos(3 * phi)) ** 2 * math.sin(theta) ** 2
            pos += d
            bloom += [swell * c for c in d]
    idx = grid_indices(rings, segments)
    count = len(pos) // 3
    base = normals_of(pos, idx)
    bloomed = normals_of([p + b for p, b in zip(pos, bloom)], idx)
    return {"attributes": {
        "POSITION": glb.accessor(pos, 'f', FLOAT, "VEC3", count, bounds=True),
        "NORMAL": glb.accessor(base, 'f', FLOAT, "VEC3", count)},
        "targets": [{
            "POSITION": glb.accessor(bloom, 'f', FLOAT, "VEC3", count, bounds=True),
            "NORMAL": glb.accessor([b - a for a, b in zip(base, bloomed)], 'f', FLOAT, "VEC3",
                                   count)}],
        "indices": glb.accessor(idx, 'H', USHORT, "SCALAR", len(idx)), "material": 1}


def about_z(degrees):
    half = math.radians(degrees) / 2
    return [0.0, 0.0, math.sin(half), math.cos(half)]


def main(path):
    glb = Glb()
    meshes = [{"name": "tentacle", "primitives": [tentacle(glb)]},
              {"name": "flower", "primitives": [flower(glb)], "weights": [0.0]}]
    materials = [
        {"name": "skin", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.42, 0.16, 1],
                                                  "metallicFactor": 0, "roughnessFactor": 0.45}},
        {"name": "petals", "pbrMetallicRoughness": {"baseColorFactor": [0.62, 0.3, 0.78, 1],
                                                    "metallicFactor": 0, "roughnessFactor": 0.3}}]
    # Nodes: 0 the tentacle's mesh (skinned: its own transform is ignored), 1..5 its joints in a
    # chain, 6 the flower, beside it.
    nodes = [{"name": "tentacle", "mesh": 0, "skin": 0}]
    for j in range(JOINTS):
        joint = {"name": "joint%d" % j, "translation": [0, 0 if j == 0 else SEGMENT, 0]}
        if j + 1 < JOINTS:
            joint["children"] = [2 + j]
        nodes.append(joint)
    nodes.append({"name": "flower", "mesh": 1, "translation": [2.4, 0.8, 0.3], "scale": [0.8] * 3})
    # Inverse bind matrices: joint j rests at (0, j SEGMENT, 0), so its inverse moves back down.
    binds = []
    for j in range(JOINTS):
        binds += [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -j * SEGMENT, 0, 1]
    skin = {"joints": list(range(1, 1 + JOINTS)),
            "inverseBindMatrices": glb.accessor(binds, 'f', FLOAT, "MAT4", JOINTS)}
    times = [SECONDS * k / (KEYS - 1) for k in range(KEYS)]
    time_accessor = glb.accessor(times, 'f', FLOAT, "SCALAR", KEYS)
    samplers, channels = [], []
    for j in range(JOINTS):
        # Each joint sways about +z, a little later and a little wider than the one below it.
        amplitude = 10 + 5 * j
        keys = []
        for t in times:
            keys += about_z(amplitude * math.sin(2 * math.pi * t / SECONDS - 0.7 * j))
        samplers.append({"input": time_accessor,
                         "output": glb.accessor(keys, 'f', FLOAT, "VEC4", KEYS)})
        channels.append({"sampler": j, "target": {"node": 1 + j, "path": "rotation"}})
    bloom = [0.5 - 0.5 * math.cos(2 * math.pi * t / SECONDS) for t in times]
    samplers.append({"input": time_accessor, "output": glb.accessor(bloom, 'f', FLOAT, "SCALAR", KEYS)})
    channels.append({"sampler": JOINTS, "target": {"node": 1 + JOINTS, "path": "weights"}})
    doc = {"asset": {"version": "2.0", "generator": "candela tools/make_skinned_example.py"},
           "scene": 0, "scenes": [{"nodes": [0, 1, 1 + JOINTS]}], "nodes": nodes,
           "meshes": meshes, "materials": materials, "skins": [skin],
           "animations": [{"name": "dance", "samplers": samplers, "channels": channels}],
           "accessors": glb.accessors, "bufferViews": glb.views,
           "buffers": [{"byteLength": len(glb.buffer)}]}
    text = json.dumps(doc, separators=(',', ':')).encode()
    while len(text) % 4:
        text += b' '
    while len(glb.buffer) % 4:
        glb.buffer.append(0)
    out = struct.pack('<4sII', b'glTF', 2, 12 + 8 + len(text) + 8 + len(glb.buffer))
    out += struct.pack('<I4s', len(text), b'JSON') + text
    out += struct.pack('<I4s', len(glb.buffer), b'BIN\0') + bytes(glb.buffer)
    with open(path, 'wb') as f:
        f.write(out)


if __name__ == '__main__':
    main(sys.argv[1])
