#!/usr/bin/env python3
"""Writes the images and the glTF panel of scenes/material_textures.json, so it needs no download:
  textures/tiles_mr.png   metallic-roughness tiles (glTF packing: roughness in green, metallic in
                          blue): polished metal tiles (roughness 0.15, metallic 1) alternate with
                          rough stone (roughness 0.9, metallic 0); 64 x 64, 8 x 8 tiles
  textures/glow.png       emission mask: three warm stripes on black, 64 x 64 (sRGB)
  meshes/panel.gltf       a 2 x 1 upright panel (embedded buffer) whose glTF material uses both
                          images: base colour, metallicRoughnessTexture, emissiveTexture
PNG is written with zlib only (no imaging library). Deterministic.
Usage: python3 scenes/textures/make_material_maps.py [SCENES_DIR]"""
import base64
import os
import struct
import sys
import zlib


def write_png(path, width, height, rows):
    """rows: list of bytes objects, RGB 8-bit, top row first."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    raw = b"".join(b"\x00" + bytes(r) for r in rows)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        f.write(chunk(b"IEND", b""))


scenes = sys.argv[1] if len(sys.argv) > 1 else "scenes"
N, TILE = 64, 8
tiles = []
for y in range(N):
    row = bytearray()
    for x in range(N):
        metal = ((x // TILE) + (y // TILE)) % 2 == 0
        row += bytes((0, round(0.15 * 255), 255)) if metal else bytes((0, round(0.9 * 255), 0))
    tiles.append(row)
write_png(os.path.join(scenes, "textures", "tiles_mr.png"), N, N, tiles)

glow = []
for y in range(N):
    lit = (y // 8) % 3 == 1 and 8 <= y < 56
    glow.append(bytearray((255, 170, 80) if lit else (0, 0, 0)) * N)
write_png(os.path.join(scenes, "textures", "glow.png"), N, N, glow)

# The panel: x in [-1, 1], y in [0, 1], facing +z; glTF uvs have v = 0 at the image's top.
buf = struct.pack("<12f", -1, 0, 0, 1, 0, 0, 1, 1, 0, -1, 1, 0)
buf += struct.pack("<12f", *([0, 0, 1] * 4))
buf += struct.pack("<8f", 0, 1, 1, 1, 1, 0, 0, 0)
buf += struct.pack("<6H", 0, 1, 2, 0, 2, 3)
gltf = f"""{{
  "asset": {{ "version": "2.0", "generator": "scenes/textures/make_material_maps.py" }},
  "extensionsUsed": ["KHR_materials_emissive_strength"],
  "scene": 0, "scenes": [ {{ "nodes": [0] }} ],
  "nodes": [ {{ "name": "panel", "mesh": 0, "translation": [0, 0.1, 0] }} ],
  "meshes": [ {{ "primitives": [ {{ "attributes": {{ "POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2 }}, "indices": 3, "material": 0 }} ] }} ],
  "materials": [ {{ "name": "GlowingTiles",
    "pbrMetallicRoughness": {{ "baseColorFactor": [0.9, 0.75, 0.5, 1], "metallicFactor": 1, "roughnessFactor": 1,
                              "metallicRoughnessTexture": {{ "index": 0 }} }},
    "emissiveFactor": [1, 1, 1], "emissiveTexture": {{ "index": 1 }},
    "extensions": {{ "KHR_materials_emissive_strength": {{ "emissiveStrength": 3 }} }} }} ],
  "textures": [ {{ "source": 0, "sampler": 0 }}, {{ "source": 1, "sampler": 0 }} ],
  "samplers": [ {{ "wrapS": 33071, "wrapT": 33071 }} ],
  "images": [ {{ "uri": "../textures/tiles_mr.png" }}, {{ "uri": "../textures/glow.png" }} ],
  "accessors": [
    {{ "bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, 0, 0], "max": [1, 1, 0] }},
    {{ "bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3" }},
    {{ "bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2" }},
    {{ "bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR" }} ],
  "bufferViews": [ {{ "buffer": 0, "byteOffset": 0, "byteLength": 48 }}, {{ "buffer": 0, "byteOffset": 48, "byteLength": 48 }},
                   {{ "buffer": 0, "byteOffset": 96, "byteLength": 32 }}, {{ "buffer": 0, "byteOffset": 128, "byteLength": 12 }} ],
  "buffers": [ {{ "byteLength": {len(buf)}, "uri": "data:application/octet-stream;base64,{base64.b64encode(buf).decode()}" }} ]
}}
"""
with open(os.path.join(scenes, "meshes", "panel.gltf"), "w") as f:
    f.write(gltf)
