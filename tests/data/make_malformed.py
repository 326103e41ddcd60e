#!/usr/bin/env python3
"""Writes tests/data/malformed/: small broken OBJ, glTF, GLB and image files, and expected.tsv,
which names each file a scene refers to and a piece of the error message loading it must give.

tests/scene/malformed_corpus_test.cpp loads every manifest entry through a scene (meshes as an
object's "file", images as a material's "albedo_texture"). Run from anywhere:
    python3 tests/data/make_malformed.py
The output is deterministic, so a rerun changes nothing unless this script changed.
"""
import base64
import json
import os
import re
import shutil
import struct
import zlib

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "malformed")
manifest = []  # (file, expected substring)
shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)


def write(name, data, expected=None):
    if isinstance(data, str):
        data = data.encode("latin-1")
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(data)
    if expected is not None:
        manifest.append((name, expected))


# --- OBJ ------------------------------------------------------------------------------------------
TRI = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
TRI_N = TRI + "vn 0 0 1\n"
TRI_T = TRI + "vt 0 0\nvt 1 0\nvt 0 1\n"


def obj(name, text, expected):
    """{TRI}, {TRI_N} and {TRI_T} in `text` stand for a triangle's vertices (with a normal, with uvs)."""
    if isinstance(text, str):
        text = text.replace("{TRI_N}", TRI_N).replace("{TRI_T}", TRI_T).replace("{TRI}", TRI)
    write("obj_" + name + ".obj", text, expected)


obj("face_two_vertices", "{TRI}f 1 2\n", ":4: a face needs at least 3 vertices, got 2")
obj("face_one_vertex", "{TRI}f 1\n", ":4: a face needs at least 3 vertices, got 1")
obj("face_no_vertices", "{TRI}f\n", ":4: a face needs at least 3 vertices, got 0")
obj("face_index_past_end", "{TRI}f 1 2 7\n", ":4: face vertex '7': position index 7 is out of range (3 positions)")
obj("face_index_zero", "{TRI}f 0 1 2\n", ":4: face vertex '0': position index 0 (OBJ counts from 1)")
obj("face_negative_past_start", "{TRI}f -1 -2 -4\n", "position index -4 is out of range (3 positions so far)")
obj("face_negative_before_vertices", "f -1 -2 -3\n{TRI}", ":1: face vertex '-1': position index -1 is out of range")
obj("face_letters", "{TRI}f a b c\n", ":4: face vertex 'a': position index 'a' is not an integer")
obj("face_float_index", "{TRI}f 1.5 2 3\n", "position index '1.5' is not an integer")
obj("face_index_overflow", "{TRI}f 1 2 99999999999999999999\n", "is not an integer")
obj("face_index_int_max", "{TRI}f 1 2 2147483648\n", "position index 2147483648 is out of range")
obj("normal_index_past_end", "{TRI_N}f 1//1 2//1 3//2\n", ":5: face vertex '3//2': normal index 2 is out of range (1 normals)")
obj("normal_index_far_past_end", "{TRI_N}f 1//1 2//1 3//100000\n", "normal index 100000 is out of range")
obj("normal_index_negative", "{TRI_N}f 1//-2 2//1 3//1\n", "normal index -2 is out of range (1 normals so far)")
obj("uv_index_past_end", "{TRI_T}f 1/1 2/2 3/4\n", ":7: face vertex '3/4': texture coordinate index 4 is out of range")
obj("uv_index_zero", "{TRI_T}f 1/1 2/0 3/3\n", "texture coordinate index 0 (OBJ counts from 1)")
obj("uv_and_normal_past_end", "{TRI_T}vn 0 0 1\nf 1/1/1 2/2/1 3/9/9\n", "texture coordinate index 9 is out of range")
obj("vertex_nan", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", ":2: a vertex position: 'nan' is not a finite 32-bit float")
obj("vertex_inf", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n", ":3: a vertex position: 'inf' is not a finite 32-bit float")
obj("vertex_minus_inf", "v 0 0 -inf\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", ":1: a vertex position: '-inf' is not a finite")
obj("vertex_float_overflow", "v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n", ":2: a vertex position: '1e39' is not a finite 32-bit float")
obj("vertex_double_overflow", "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n", "'1e999' is not a finite 32-bit float")
obj("vertex_letters", "v 0 0 0\nv 1 abc 0\nv 0 1 0\nf 1 2 3\n", ":2: a vertex position: 'abc' is not a number")
obj("vertex_trailing_letters", "v 0 0 0\nv 1 0 0x\nv 0 1 0\nf 1 2 3\n", ":2: a vertex position: '0x' is not a number")
obj("vertex_comma_decimal", "v 0 0 0\nv 1,5 0 0\nv 0 1 0\nf 1 2 3\n", "'1,5' is not a number")
obj("vertex_two_coordinates", "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", ":2: a vertex position needs 3 to 7 numbers, got 2")
obj("vertex_no_coordinates", "v 0 0 0\nv\nv 0 1 0\nf 1 2 3\n", ":2: a vertex position needs 3 to 7 numbers, got 0")
obj("vertex_eight_numbers", "v 0 0 0 1 1 1 1 1\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", ":1: a vertex position needs 3 to 7 numbers, got 8")
obj("normal_nan", "{TRI}vn 0 nan 1\nf 1//1 2//1 3//1\n", ":4: a normal: 'nan' is not a finite 32-bit float")
obj("normal_two_numbers", "{TRI}vn 0 1\nf 1//1 2//1 3//1\n", ":4: a normal needs 3 numbers, got 2")
obj("uv_letters", "{TRI}vt 0 q\nf 1/1 2/1 3/1\n", ":4: a texture coordinate: 'q' is not a number")
obj("uv_four_numbers", "{TRI}vt 0 0 0 0\nf 1/1 2/1 3/1\n", ":4: a texture coordinate needs 1 to 3 numbers, got 4")
obj("uv_inf", "{TRI}vt inf 0\nf 1/1 2/1 3/1\n", ":4: a texture coordinate: 'inf' is not a finite")
obj("truncated_face_two", "{TRI}f 1 2 3\nf 1 2", ":5: a face needs at least 3 vertices, got 2")
obj("truncated_face_slash", "{TRI_T}f 1/1 2/2 3/", ":7: face vertex '3/' is incomplete")
obj("truncated_face_double_slash", "{TRI_N}f 1//1 2//1 3//", ":5: face vertex '3//' is incomplete")
obj("face_four_parts", "{TRI_T}vn 0 0 1\nf 1/1/1 2/2/1 3/3/1/1\n", "face vertex '3/3/1/1' has more than 3 parts")
obj("face_empty_position", "{TRI_T}f /1 2/2 3/3\n", "face vertex '/1' is incomplete")
obj("truncated_in_vertex", "v 0 0 0\nv 1 0 0\nv 0 1", ":3: a vertex position needs 3 to 7 numbers, got 2")
obj("crlf_bad_index", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\n\r\nf 1 2 4\r\n", ":5: face vertex '4': position index 4 is out of range")
obj("cr_only_bad_index", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 4\r", ":4: face vertex '4': position index 4 is out of range")
obj("nul_in_number", "v 0 0 0\nv 1 0 0\x000\nv 0 1 0\nf 1 2 3\n", ":2: a vertex position: '0?0' is not a number")
obj("empty", "", "contains no faces")
obj("comments_only", "# nothing here\n# still nothing\n", "contains no faces")
obj("vertices_only", "{TRI}", "contains no faces")
obj("lines_only", "{TRI}l 1 2 3\n", "contains no faces")
obj("line_zero_index", "{TRI}l 0 1\nf 1 2 3\n", "Failed parse `l' line")
obj("comment_hides_coordinate", "v 0 0 0\nv 1 0 # 0\nv 0 1 0\nf 1 2 3\n", ":2: a vertex position needs 3 to 7 numbers, got 2")
obj("binary_garbage", bytes(range(256)) * 4, "contains no faces")
obj("long_bad_word", "v 0 0 0\nv 1 0 " + "9" * 40 + "z\nv 0 1 0\nf 1 2 3\n", "...' is not a number")

# --- glTF -----------------------------------------------------------------------------------------
POSITIONS = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
NORMALS = struct.pack("<9f", 0, 0, 1, 0, 0, 1, 0, 0, 1)
INDICES = struct.pack("<3H", 0, 1, 2) + b"\0\0"
BUFFER = POSITIONS + NORMALS + INDICES  # 36 + 36 + 8 bytes


def data_uri(data, mime="application/octet-stream"):
    return "data:%s;base64,%s" % (mime, base64.b64encode(data).decode())


def base_gltf(buffer=BUFFER):
    return {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2}]}],
        "buffers": [{"byteLength": len(buffer), "uri": data_uri(buffer)}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 36},
            {"buffer": 0, "byteOffset": 36, "byteLength": 36},
            {"buffer": 0, "byteOffset": 72, "byteLength": 6},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5123, "count": 3, "type": "SCALAR"},
        ],
    }


def gltf(name, edit, expected, buffer=BUFFER):
    g = base_gltf(buffer)
    edit(g)
    write("gltf_" + name + ".gltf", json.dumps(g, indent=1), expected)


def setter(path, value):
    def edit(g):
        o = g
        for k in path[:-1]:
            o = o[k]
        o[path[-1]] = value
    return edit


def deleter(path):
    def edit(g):
        o = g
        for k in path[:-1]:
            o = o[k]
        del o[path[-1]]
    return edit


U64 = 2**64
gltf("accessor_offset_wraps", setter(["accessors", 0, "byteOffset"], U64 - 8),
     "accessors[0]: byteOffset 18446744073709551608 + count 3 x stride 12 is past the end of bufferViews[0]")
gltf("accessor_count_wraps", setter(["accessors", 0, "count"], 2**62 + 1),
     "accessors[0]: byteOffset 0 + count 4611686018427387905 x stride 12 is past the end")
gltf("accessor_count_past_view", setter(["accessors", 0, "count"], 4), "accessors[0]: byteOffset 0 + count 4 x stride 12")
gltf("accessor_offset_past_view", setter(["accessors", 0, "byteOffset"], 4), "accessors[0]: byteOffset 4 + count 3")
gltf("accessor_stride_past_view", setter(["bufferViews", 0, "byteStride"], 16), "accessors[0]: byteOffset 0 + count 3 x stride 16")
gltf("accessor_stride_too_small", setter(["bufferViews", 0, "byteStride"], 4),
     "bufferViews[0].byteStride: 4 is smaller than an element of accessors[0] (12 bytes)")
gltf("view_offset_past_buffer", setter(["bufferViews", 0, "byteOffset"], 1000),
     "bufferViews[0]: byteOffset 1000 + byteLength 36 is past the end of buffers[0] (80 bytes)")
gltf("view_offset_wraps", setter(["bufferViews", 2, "byteOffset"], U64 - 2), "bufferViews[2]: byteOffset 18446744073709551614")
gltf("view_length_past_buffer", setter(["bufferViews", 1, "byteLength"], 1000),
     "bufferViews[1]: byteOffset 36 + byteLength 1000 is past the end of buffers[0]")
gltf("view_names_missing_buffer", setter(["bufferViews", 0, "buffer"], 5), "bufferViews[0].buffer: 5 is not a buffer (1 in the file)")
gltf("view_negative_buffer", setter(["bufferViews", 0, "buffer"], -3), "-3 is not a buffer")
gltf("accessor_names_missing_view", setter(["accessors", 1, "bufferView"], 9),
     "accessors[1].bufferView: 9 is not a bufferView (3 in the file)")
gltf("accessor_without_view", deleter(["accessors", 0, "bufferView"]), "accessors[0].bufferView: the accessor has no data")
gltf("accessor_component_double", setter(["accessors", 0, "componentType"], 5130), "componentType")
gltf("accessor_component_signed_byte", setter(["accessors", 1, "componentType"], 5120),
     "accessors[1].componentType: unsupported component type 5120")
gltf("position_scalar", setter(["accessors", 0, "type"], "SCALAR"),
     "accessors[0].type: meshes[0].primitives[0].attributes.POSITION needs 3 components per element, got 1")
gltf("position_vec2", setter(["accessors", 0, "type"], "VEC2"), "POSITION needs 3 components per element, got 2")
gltf("position_bad_type", setter(["accessors", 0, "type"], "VEC7"), "type")
gltf("normal_mat4", setter(["accessors", 1, "type"], "MAT4"), "NORMAL needs 3 components per element, got 16")
gltf("indices_vec3", setter(["accessors", 2, "type"], "VEC3"), "meshes[0].primitives[0].indices needs 1 component per element")
gltf("indices_float", setter(["accessors", 2, "componentType"], 5126),
     "accessors[2].componentType: meshes[0].primitives[0].indices needs unsigned integers")
gltf("normals_fewer_than_positions", setter(["accessors", 1, "count"], 2),
     "accessors[1].count: 2 elements, fewer than the 3 positions of accessors[0]")
gltf("index_past_vertices", lambda g: None, "accessors[2][2]: index 7 is out of range (3 vertices)",
     buffer=POSITIONS + NORMALS + struct.pack("<3H", 0, 1, 7) + b"\0\0")
gltf("index_max_ushort", lambda g: None, "index 65535 is out of range (3 vertices)",
     buffer=POSITIONS + NORMALS + struct.pack("<3H", 65535, 1, 2) + b"\0\0")
gltf("position_nan", lambda g: None, "accessors[0][1]: not a finite 32-bit float",
     buffer=struct.pack("<9f", 0, 0, 0, float("nan"), 0, 0, 0, 1, 0) + NORMALS + INDICES)
gltf("position_inf", lambda g: None, "accessors[0][2]: not a finite 32-bit float",
     buffer=struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, float("inf"), 0) + NORMALS + INDICES)
gltf("normal_nan", lambda g: None, "accessors[1][0]: not a finite 32-bit float",
     buffer=POSITIONS + struct.pack("<9f", float("nan"), 0, 1, 0, 0, 1, 0, 0, 1) + INDICES)
gltf("attribute_missing_accessor", setter(["meshes", 0, "primitives", 0, "attributes", "POSITION"], 99),
     "meshes[0].primitives[0].attributes.POSITION: 99 is not an accessor (3 in the file)")
gltf("indices_missing_accessor", setter(["meshes", 0, "primitives", 0, "indices"], 3),
     "primitive indices accessor out of bounds")
gltf("primitive_without_position", deleter(["meshes", 0, "primitives", 0, "attributes", "POSITION"]),
     "meshes[0].primitives[0].attributes: a primitive has no POSITION")
gltf("primitive_missing_material", setter(["meshes", 0, "primitives", 0, "material"], 4),
     "meshes[0].primitives[0].material: 4 is not a material (0 in the file)")
gltf("node_missing_mesh", setter(["nodes", 0, "mesh"], 3), "nodes[0].mesh: 3 is not a mesh (1 in the file)")
gltf("scene_missing_node", setter(["scenes", 0, "nodes"], [7]), "scenes[0].nodes[0]: 7 is not a node (1 in the file)")
gltf("child_missing_node", setter(["nodes", 0, "children"], [5]), "nodes[0].children[0]: 5 is not a node")
gltf("node_cycle", setter(["nodes", 0, "children"], [0]), "nodes[0]: the node is reached twice")
gltf("node_two_parents", lambda g: g.update(nodes=[{"children": [2]}, {"children": [2]}, {"mesh": 0}],
                                            scenes=[{"nodes": [0, 1]}]), "nodes[2]: the node is reached twice")
gltf("node_matrix_overflow", setter(["nodes", 0, "matrix"], [1e300, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]),
     "nodes[0].matrix[0]: not a finite 32-bit float")
gltf("node_translation_overflow", setter(["nodes", 0, "translation"], [0, 1e39, 0]),
     "nodes[0].translation[1]: not a finite 32-bit float")
gltf("node_scale_overflow", setter(["nodes", 0, "scale"], [1, 1, -1e308]), "nodes[0].scale[2]: not a finite 32-bit float")
gltf("default_scene_missing", setter(["scene"], 3), "scene")
gltf("sparse_accessor", setter(["accessors", 0, "sparse"],
                                {"count": 1, "indices": {"bufferView": 2, "componentType": 5123},
                                 "values": {"bufferView": 0}}), "accessors[0].sparse: sparse accessors are not supported")
gltf("no_meshes", lambda g: g.update(nodes=[{}]), "contains no triangles")
gltf("points_only", setter(["meshes", 0, "primitives", 0, "mode"], 0), "contains no triangles")
gltf("buffer_bad_base64", setter(["buffers", 0, "uri"], "data:application/octet-stream;base64,@@@@"), "buffer")
gltf("buffer_longer_than_data", setter(["buffers", 0, "byteLength"], 4096), "buffer")
gltf("buffer_missing_file", setter(["buffers", 0, "uri"], "gltf_missing.bin"), "gltf_missing.bin")
gltf("texture_missing_image", lambda g: g.update(
    materials=[{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}], textures=[{"source": 3}]) or
    g["meshes"][0]["primitives"][0].update(material=0), "source")
gltf("material_missing_texture", lambda g: g.update(
    materials=[{"pbrMetallicRoughness": {"baseColorTexture": {"index": 2}}}]) or
    g["meshes"][0]["primitives"][0].update(material=0), "baseColorTexture: bad texture index 2")
gltf("emissive_strength_negative", lambda g: g.update(
    materials=[{"emissiveFactor": [1, 1, 1],
                "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": -2}}}]) or
    g["meshes"][0]["primitives"][0].update(material=0),
    "materials[0].extensions.KHR_materials_emissive_strength.emissiveStrength: must be a number >= 0")


def png(width, height, idat=b"", channels_type=2, depth=8, crc_ok=True):
    def chunk(kind, data):
        crc = zlib.crc32(kind + data) & 0xFFFFFFFF
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", crc if crc_ok else crc ^ 1)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, depth, channels_type, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(idat)) + chunk(b"IEND", b""))


PNG_BOMB = png(65535, 65535, b"\0" * 64)
gltf("image_header_too_large", lambda g: g.update(images=[{"uri": data_uri(PNG_BOMB, "image/png")}]),
     "images[0]: 65535x65535 is larger than raylab reads")
gltf("image_cut_in_header", lambda g: g.update(images=[{"uri": data_uri(PNG_BOMB[:30], "image/png")}]),
     "cannot decode image data for image[0]")
gltf("image_garbage", lambda g: g.update(images=[{"uri": data_uri(b"not an image at all", "image/png")}]),
     "cannot decode")


def buffer_view_image(g):
    g["images"] = [{"bufferView": 3, "mimeType": "image/png"}]
    g["bufferViews"].append({"buffer": 0, "byteOffset": 64, "byteLength": 4000})


gltf("image_view_past_buffer", buffer_view_image, "images[0].bufferView: bufferViews[3] (byteOffset 64, byteLength 4000)")
write("gltf_not_json.gltf", "this is not JSON\n", "gltf_not_json.gltf: parse error at line 1, column 2")
write("gltf_truncated.gltf", json.dumps(base_gltf(), indent=1)[:300], "gltf_truncated.gltf: parse error at line 32")
write("gltf_empty.gltf", "", "cannot read: the file is empty")
write("gltf_array.gltf", "[1, 2, 3]\n", "gltf_array.gltf: Root element is not a JSON object")
write("gltf_nul_after_json.gltf", json.dumps(base_gltf()) + "\0garbage", "is a NUL byte (a .gltf file is JSON text)")

# External .bin buffers (the .bin files sit beside the .gltf and are not manifest entries).
write("gltf_external.bin", BUFFER)
write("gltf_external_short.bin", BUFFER[:40])


def external(name, edit, expected, uri="gltf_external.bin"):
    def both(g):
        g["buffers"][0]["uri"] = uri
        edit(g)
    gltf(name, both, expected)


external("external_accessor_wraps", setter(["accessors", 1, "byteOffset"], U64 - 4),
         "accessors[1]: byteOffset 18446744073709551612 + count 3 x stride 12 is past the end of bufferViews[1]")
external("external_view_past_buffer", setter(["bufferViews", 2, "byteLength"], 100),
         "bufferViews[2]: byteOffset 72 + byteLength 100 is past the end of buffers[0] (80 bytes)")
external("external_missing_view_buffer", setter(["bufferViews", 1, "buffer"], 1), "bufferViews[1].buffer: 1 is not a buffer")
external("external_short_bin", lambda g: None, "gltf_external_short.bin", uri="gltf_external_short.bin")


# --- GLB ------------------------------------------------------------------------------------------
def glb(g, binary, json_pad=True):
    text = json.dumps(g).encode()
    if json_pad:
        text += b" " * (-len(text) % 4)
    binary = binary + b"\0" * (-len(binary) % 4)
    body = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(binary), b"BIN\0") + binary
    return struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body


def glb_model(edit=None):
    g = base_gltf()
    del g["buffers"][0]["uri"]
    if edit:
        edit(g)
    return g


write("glb_bad_magic.glb", b"glTX" + glb(glb_model(), BUFFER)[4:], "glb_bad_magic.glb: Invalid magic")
write("glb_truncated_header.glb", glb(glb_model(), BUFFER)[:10], "glb_truncated_header.glb: Too short data size for glTF Binary")
write("glb_length_past_end.glb", glb(glb_model(), BUFFER)[:8] + struct.pack("<I", 1 << 30) + glb(glb_model(), BUFFER)[12:],
      "glb_length_past_end.glb: Invalid glTF binary")
whole = glb(glb_model(), BUFFER)
chunk_len_past = whole[:12] + struct.pack("<I", 1 << 30) + whole[16:]
write("glb_chunk_past_end.glb", chunk_len_past, "glb_chunk_past_end.glb: Invalid glTF binary")
write("glb_accessor_wraps.glb", glb(glb_model(setter(["accessors", 0, "byteOffset"], U64 - 12)), BUFFER),
      "accessors[0]: byteOffset 18446744073709551604")
write("glb_view_missing_buffer.glb", glb(glb_model(setter(["bufferViews", 2, "buffer"], 2)), BUFFER),
      "bufferViews[2].buffer: 2 is not a buffer")
write("glb_index_past_vertices.glb", glb(glb_model(), POSITIONS + NORMALS + struct.pack("<3H", 0, 9, 2) + b"\0\0"),
      "accessors[2][1]: index 9 is out of range (3 vertices)")
write("glb_empty.glb", b"", "cannot read: the file is empty")


# --- Images (as a material's albedo_texture) ------------------------------------------------------
def image(name, data, expected):
    write("image_" + name, data, expected)


image("png_65535_square.png", PNG_BOMB, "65535x65535 is larger than raylab reads (at most 32768 pixels per side)")
image("png_wide.png", png(40000, 1, b"\0" * 64), "40000x1 is larger than raylab reads (at most 32768 pixels per side)")
image("png_too_many_pixels.png", png(16000, 16800, b"\0" * 64), "16000x16800 is larger than raylab reads (at most 268435456 pixels)")
image("png_zero_width.png", png(0, 4, b"\0" * 64), "image_png_zero_width.png: ")
image("png_truncated_idat.png", png(4, 4, b"\0" * 3), "image_png_truncated_idat.png: ")
image("png_bad_crc.png", png(4, 4, b"\0" * 52, crc_ok=False), "image_png_bad_crc.png: PNG read error: IHDR: CRC error")
image("png_bad_depth.png", png(4, 4, b"\0" * 52, depth=7), "image_png_bad_depth.png: ")
image("png_signature_only.png", b"\x89PNG\r\n\x1a\n", "image_png_signature_only.png: ")
image("png_empty.png", b"", "image_png_empty.png: Not a PNG file")
image("png_text.png", "hello, I am not a PNG\n", "image_png_text.png: Not a PNG file")
image("png_cut_in_header.png", PNG_BOMB[:20], "image_png_cut_in_header.png: ")
HDR_HEAD = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n"
image("hdr_huge.hdr", HDR_HEAD + "-Y 100000 +X 100000\n" + "\0" * 16, "100000x100000 is larger than raylab reads")
image("hdr_tall.hdr", HDR_HEAD + "-Y 40000 +X 2\n" + "\0" * 16, "2x40000 is larger than raylab reads")
image("hdr_panorama_too_many_pixels.hdr", HDR_HEAD + "-Y 16385 +X 32768\n" + "\0" * 16,
      "32768x16385 is larger than raylab reads (at most 268435456 pixels)")
image("hdr_int_overflow.hdr", HDR_HEAD + "-Y 99999999999 +X 99999999999\n", "is larger than raylab reads")
image("hdr_truncated_pixels.hdr", HDR_HEAD + "-Y 8 +X 8\n" + "\x80" * 10, "image_hdr_truncated_pixels.hdr: ")
image("hdr_bad_resolution.hdr", HDR_HEAD + "-Y eight +X 8\n", "image_hdr_bad_resolution.hdr: missing image size specifier")
image("hdr_garbage.hdr", bytes(range(256)), "image_hdr_garbage.hdr: ")
image("hdr_empty.hdr", b"", "image_hdr_empty.hdr: ")
image("hdr_header_only.hdr", "#?RADIANCE\n", "image_hdr_header_only.hdr: ")


def exr_attr(name, kind, value):
    return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value


def exr(xmax, ymax, xmin=0, ymin=0, offsets=True):
    channels = b"".join(c.encode() + b"\0" + struct.pack("<iBBBBii", 2, 0, 0, 0, 0, 1, 1) for c in "BGR") + b"\0"
    box = struct.pack("<iiii", xmin, ymin, xmax, ymax)
    header = (struct.pack("<ii", 20000630, 2) + exr_attr("channels", "chlist", channels) +
              exr_attr("compression", "compression", b"\0") + exr_attr("dataWindow", "box2i", box) +
              exr_attr("displayWindow", "box2i", box) + exr_attr("lineOrder", "lineOrder", b"\0") +
              exr_attr("pixelAspectRatio", "float", struct.pack("<f", 1)) +
              exr_attr("screenWindowCenter", "v2f", struct.pack("<ff", 0, 0)) +
              exr_attr("screenWindowWidth", "float", struct.pack("<f", 1)) + b"\0")
    if offsets:
        header += struct.pack("<Q", len(header) + 8 * 1) * 1
    return header


image("exr_huge.exr", exr(65534, 65534, offsets=False), "image_exr_huge.exr\". Unexpected end of file")
image("exr_wide.exr", exr(99999, 0), "100000x1 is larger than raylab reads")
image("exr_inverted_window.exr", exr(-5, 3, offsets=False), "Invalid display window in image header")
image("exr_truncated_pixels.exr", exr(3, 3), "image_exr_truncated_pixels.exr: ")
image("exr_bad_magic.exr", b"\0\0\0\0" + exr(3, 3)[4:], "image_exr_bad_magic.exr\" is not an OpenEXR file")
image("exr_cut_in_header.exr", exr(3, 3)[:40], "image_exr_cut_in_header.exr: ")
image("exr_empty.exr", b"", "image_exr_empty.exr: ")
image("exr_text.exr", "just text\n", "image_exr_text.exr\" is not an OpenEXR file")
image("ppm_huge.ppm", "P6\n65535 65535\n255\n" + "\0" * 12, "65535x65535 is larger than raylab reads")
image("ppm_truncated.ppm", "P6\n4 4\n255\n" + "\0" * 5, "image_ppm_truncated.ppm: ")


# --- Scene JSON ------------------------------------------------------------------------------------
# These files are scenes themselves; the message must locate the bad value. Each case's text is the
# document pretty-printed with the bad value's raw JSON spliced in, so its line and column are known.
FORMAT_MD = os.path.join(os.path.dirname(OUT), "..", "..", "scenes", "FORMAT.md")
SENTINEL = "@@BAD@@"


def located(doc, raw, focus=None):
    """The document's text with `raw` spliced in at the sentinel, and the line:column of `focus` in it."""
    text = json.dumps(doc, indent=2)
    at = text.index('"' + SENTINEL + '"')
    text = text[:at] + raw + text[at + len(SENTINEL) + 2:]
    at += raw.index(focus) if focus else 0
    line = text.count("\n", 0, at) + 1
    return text, "%d:%d" % (line, at - (text.rfind("\n", 0, at) + 1) + 1)


def scene(name, text, expected, overrides=()):
    write("json_" + name + ".json", text)
    manifest.append(("json_" + name + ".json", expected) + (("|".join(overrides),) if overrides else ()))


def bad_value(name, doc, path, raw, message, focus=None):
    text, where = located(doc, raw, focus)
    scene(name, text, ":%s: error: %s: %s" % (where, path, message))


# Every key of the parameter table, from FORMAT.md's tables (format_doc_test checks them against the
# table): (section heading, key, type, range).
def format_keys():
    keys, section = [], None
    with open(FORMAT_MD, encoding="utf-8") as f:
        for line in f:
            if line.startswith("## "):
                section = line[3:].strip().strip("`")
            cells = [c.strip() for c in line.split("|")]
            if len(cells) > 6 and cells[1].startswith("`") and cells[1].endswith("`"):
                keys.append((section, cells[1].strip("`"), cells[2], cells[5]))
    return keys


MESH = {"type": "mesh", "positions": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1, 2]}


def place(section, key):
    """A scene whose value of `key` is the sentinel, and the key's path in messages."""
    if section in ("camera", "render", "sky", "ao"):
        sect, name = key.split(".")
        doc = {sect: {name: SENTINEL}}
        if key == "sky.map":
            doc["sky"]["type"] = "map"
        return doc, key
    if section == "materials":
        return {"materials": {"m": {key: SENTINEL}}, "objects": [{"material": "m"}]}, "materials.m." + key
    if key.startswith("transform."):
        return {"objects": [{"transform": {key.split(".")[1]: SENTINEL}}]}, "objects[0]." + key
    if key in MESH or key in ("normals", "uvs", "file", "emission_sides", "displacement_texture", "displacement_scale",
                              "displacement_subdivision"):
        obj = dict(MESH)
        if key == "file":
            obj = {"type": "mesh"}
        obj[key] = SENTINEL
        return {"objects": [obj]}, "objects[0]." + key
    if section == "objects":
        return {"objects": [{"type": "sphere", key: SENTINEL}]}, "objects[0]." + key
    if section == "lights":
        name = key.split(".")[1]
        light = {"type": SENTINEL} if name == "type" else {
            "type": {"direction": "spot", "inner_angle": "spot", "outer_angle": "spot", "irradiance": "distant",
                     "angular_radius": "distant"}.get(name, "point"), name: SENTINEL}
        return {"objects": [{"type": "sphere"}], "lights": [light]}, "lights[0]." + name
    raise SystemExit("make_malformed.py: no place in a scene for key %s of section %s" % (key, section))


def parse_range(text):
    """'[1, 16384]', '(0, 180)', '>= 0', '> 0', 'any' -> ((low, inclusive) or None, (high, inclusive) or None)."""
    m = re.fullmatch(r"([\[(])(-?[0-9.e+]+), (-?[0-9.e+]+)([\])])", text)
    if m:
        return (float(m.group(2)), m.group(1) == "["), (float(m.group(3)), m.group(4) == "]")
    m = re.fullmatch(r"(>=?) (-?[0-9.e+]+)", text)
    if m:
        return (float(m.group(2)), m.group(1) == ">="), None
    return None, None


def num(x):
    return str(int(x)) if x == int(x) else repr(x)


def out_of_range(rng, integral):
    """A value just outside the range and the message's range words, or None when the range is open."""
    low, high = parse_range(rng)
    step = 1 if integral else 0.5
    if high:
        value = high[0] + (step if high[1] else 0)
    elif low:
        value = low[0] - (step if low[1] else 0)
    else:
        return None
    return value, ("must be in %s" % rng) if (low and high) else ("must be %s" % rng)


def key_cases(section, key, kind, rng):
    """One case for every key (its range, else its type), and every kind of wrong value for the first
    key of each type: a new type in the table stops this script until it has its cases."""
    doc, path = place(section, key)
    slug = key.replace("[]", "").replace(".", "_")
    integral = kind in ("int", "uint")
    bounded = out_of_range(rng, integral) if kind in ("int", "uint", "float", "vec3", "rgb") else None
    if bounded:
        value, words = bounded
        raw = {"vec3": "[1, %s, 1]", "rgb": "[0, %s, 0]"}.get(kind, "%s") % num(value)
        where = "[1]" if kind in ("vec3", "rgb") else ""
        bad_value("key_%s_out_of_range" % slug, doc, path + where, raw, "%s, got %s" % (words, num(value)),
                  focus=num(value) if where else None)
    first = kind not in seen_types
    seen_types.add(kind)
    if kind == "int":
        if not bounded:
            bad_value("key_%s_wrong_type" % slug, doc, path, '"7"', "expected an integer, got string")
        if first:
            bad_value("type_int_fraction", doc, path, "1.5", "must be an integer, got 1.5")
            bad_value("type_int_too_large", doc, path, "1e20", "must be ")
            bad_value("type_int_overflow", doc, path, "1e999", "must be finite, got 1e999 (too large for a double)")
            bad_value("type_int_string", doc, path, '"7"', "expected an integer, got string")
            bad_value("type_int_null", doc, path, "null", "expected an integer, got null")
            bad_value("type_int_bool", doc, path, "true", "expected an integer, got boolean")
    elif kind == "uint":
        if first:
            bad_value("type_uint_negative", doc, path, "-1", "must be in [0, 4294967295], got -1")
            bad_value("type_uint_fraction", doc, path, "0.5", "must be an integer, got 0.5")
            bad_value("type_uint_string", doc, path, '"1"', "expected an integer, got string")
            bad_value("type_uint_overflow", doc, path, "-1e999", "must be finite, got -1e999")
    elif kind == "float":
        if not bounded:
            bad_value("key_%s_wrong_type" % slug, doc, path, "[1]", "expected a number, got array")
        if first:
            bad_value("type_float_string", doc, path, '"0.5"', "expected a number, got string")
            bad_value("type_float_object", doc, path, "{}", "expected a number, got object")
            bad_value("type_float_overflow", doc, path, "1e999", "must be finite, got 1e999 (too large for a double)")
            bad_value("type_float_single_overflow", doc, path, "1e39", "{...}got 1e+39")
            bad_value("type_float_bool", doc, path, "false", "expected a number, got boolean")
    elif kind == "vec3":
        if not bounded:
            bad_value("key_%s_arity" % slug, doc, path, "[1, 2]", "expected 3 numbers, got 2")
        if first:
            bad_value("type_vec3_string", doc, path, '"1 2 3"', "expected [x, y, z], an array of 3 numbers, got string")
            bad_value("type_vec3_number", doc, path, "1", "expected [x, y, z], an array of 3 numbers, got number")
            bad_value("type_vec3_four", doc, path, "[1, 2, 3, 4]", "expected 3 numbers, got 4")
            bad_value("type_vec3_component_string", doc, path + "[1]", '[1, "2", 3]', "expected a number, got string",
                      focus='"2"')
            bad_value("type_vec3_component_overflow", doc, path + "[2]", "[1, 2, -1e999]", "must be finite, got -1e999",
                      focus="-1e999")
            bad_value("type_vec3_nested", doc, path + "[0]", "[[1], 2, 3]", "expected a number, got array", focus="[1]")
    elif kind == "rgb":
        if first:
            bad_value("type_rgb_two", doc, path, "[0.5, 0.5]", "expected 3 numbers, got 2")
            bad_value("type_rgb_four", doc, path, "[0.5, 0.5, 0.5, 1]", "expected 3 numbers, got 4")
            bad_value("type_rgb_string", doc, path, '"red"', "expected a colour, [r, g, b] or one number for grey, got string")
            bad_value("type_rgb_grey_negative", doc, path, "-1", "must be ")
            bad_value("type_rgb_component_null", doc, path + "[2]", "[0, 0, null]", "expected a number, got null",
                      focus="null")
            bad_value("type_rgb_component_overflow", doc, path + "[0]", "[1e999, 0, 0]", "must be finite, got 1e999",
                      focus="1e999")
    elif kind == "enum":
        names = [n.split(" ")[0] for n in rng.split(", ")]
        bad_value("key_%s_unknown" % slug, doc, path, '"%sx"' % names[-1],
                  "unknown value '%sx'; did you mean '%s'?" % (names[-1], names[-1]))
        if first:
            bad_value("type_enum_number", doc, path, "1", "expected a string (")
            bad_value("type_enum_far", doc, path, '"zzzzzzzzzz"', "unknown value 'zzzzzzzzzz'")
            bad_value("type_enum_case", doc, path, '"%s"' % names[0].upper(), "unknown value '%s'" % names[0].upper())
    elif kind == "bool":
        bad_value("key_%s_number" % slug, doc, path, "1", "expected true or false, got number")
        if first:
            bad_value("type_bool_string", doc, path, '"true"', "expected true or false, got string")
            bad_value("type_bool_null", doc, path, "null", "expected true or false, got null")
    elif kind == "string" and rng == "an image file":
        bad_value("key_%s_missing_file" % slug, doc, path, '"no_such_image.png"', "{...}no_such_image.png")
        if not first:
            bad_value("key_%s_number" % slug, doc, path, "3", "{...}got number")
        if first:
            bad_value("type_path_number", doc, path, "3", "{...}got number")
            bad_value("type_path_empty", doc, path, '""', "{...}got empty string")
            bad_value("type_path_directory", doc, path, '"."', "{...}cannot read")
    elif kind == "string" and key == "file":
        bad_value("key_file_missing", doc, path, '"no_such_mesh.obj"', "{...}no_such_mesh.obj: cannot read: no such file")
        bad_value("key_file_missing_gltf", doc, path, '"no_such_mesh.glb"', "{...}no_such_mesh.glb: cannot read")
        bad_value("key_file_number", doc, path, "3", "expected the path of an OBJ or glTF file (a string), got number")
        bad_value("key_file_empty", doc, path, '""', "{...}got empty string")
    elif kind == "string" and key == "type":
        bad_value("key_type_unknown", doc, path, '"cube"', "unknown object type 'cube' (known types: sphere, mesh)")
        bad_value("key_type_typo", doc, path, '"shpere"', "unknown object type 'shpere'; did you mean 'sphere'?")
        bad_value("key_type_number", doc, path, "1", "expected a string (sphere, mesh), got number")
    elif kind == "string" and key == "emission_sides":
        bad_value("key_emission_sides_unknown", doc, path, '"back"', "unknown value 'back' (allowed values: both, front, gltf)")
        bad_value("key_emission_sides_number", doc, path, "1", "expected a string (both, front, gltf), got number")
        bad_value("key_emission_sides_gltf_inline", doc, path, '"gltf"',
                  "\"gltf\" takes the sides from a glTF file's materials (doubleSided); this mesh is not read from a .gltf or .glb file")
    elif kind == "string" and key == "material":
        bad_value("key_material_unknown", doc, path, '"nobody"', "unknown material 'nobody'")
        bad_value("key_material_number", doc, path, "0", "expected a material name (a string), got number")
    elif kind == "array":
        bad_value("key_%s_string" % slug, doc, path, '"0 1 2"', "expected a flat array of ")
        component = {"uvs": '[0, "1", 1, 0, 0, 1]', "normals": '[0, "1", 1, 0, 0, 1, 0, 0, 1]',
                     "positions": '[0, "1", 0, 1, 0, 0, 0, 1, 0]'}.get(key, '[0, "1", 2]')
        bad_value("key_%s_component" % slug, doc, path + "[1]", component, "expected a number, got string"
                  if key != "indices" else "expected an integer, got string", focus='"1"')
        if key == "indices":
            bad_value("key_indices_out_of_range", doc, path + "[2]", "[0, 1, 3]", "vertex index 3 is out of range (3 vertices)",
                      focus="3")
            bad_value("key_indices_negative", doc, path + "[0]", "[-1, 1, 2]", "must be in [0, 4294967295], got -1", focus="-1")
            bad_value("key_indices_count", doc, path, "[0, 1]", "expected a multiple of 3 numbers, got 2")
        if key == "positions":
            bad_value("key_positions_count", doc, path, "[0, 0, 0, 1, 0, 0, 0, 1]", "expected a multiple of 3 numbers, got 8")
            bad_value("key_positions_single_overflow", doc, path + "[4]", "[0, 0, 0, 1, 1e39, 0, 0, 1, 0]", "{...}got 1e+39",
                      focus="1e39")
        if key == "normals":
            bad_value("key_normals_zero", doc, path + "[0]", "[0, 0, 0, 0, 0, 1, 0, 0, 1]", "a normal must not be zero",
                      focus="0")
            bad_value("key_normals_count", doc, path, "[0, 0, 1]", "expected one normal per vertex (9 numbers), got 3 numbers")
        if key == "uvs":
            bad_value("key_uvs_count", doc, path, "[0, 0, 1]", "expected a multiple of 2 numbers, got 3")
    else:
        raise SystemExit("make_malformed.py: no malformed cases for key %s of type %s: add them here" % (key, kind))


seen_types = set()
for section, key, kind, rng in format_keys():
    key_cases(section, key, kind, rng)

# Displacement: a negative level, a mesh without uvs, and subdivision past the triangle limit
# (62 triangles x 4^8 > 4000000). The image is a valid one of the shipped scenes.
IMAGE = "../../../scenes/textures/bricks.ppm"
bad_value("displacement_subdivision_negative", {"objects": [dict(MESH, displacement_texture=IMAGE, displacement_subdivision=SENTINEL)]},
          "objects[0].displacement_subdivision", "-1", "must be in [0, 8], got -1")
bad_value("displacement_without_uvs", {"objects": [dict(MESH, displacement_texture=SENTINEL)]},
          "objects[0].displacement_texture", '"%s"' % IMAGE, "the mesh has no uvs to read the displacement texture at")
bad_value("displacement_too_many_triangles",
          {"objects": [dict(MESH, indices=[0, 1, 2] * 62, uvs=[0, 0, 1, 0, 0, 1], displacement_texture=IMAGE,
                            displacement_subdivision=SENTINEL)]},
          "objects[0].displacement_subdivision", "8", "62 triangles x 4^8 exceed the limit of 4000000 displaced triangles")

# The ambient-occlusion view's keys below their ranges (the table's cases take the other side).
bad_value("ao_rays_zero", {"ao": {"rays": SENTINEL}}, "ao.rays", "0", "must be in [1, 64], got 0")
bad_value("ao_distance_negative", {"ao": {"distance": SENTINEL}}, "ao.distance", "-1", "must be > 0, got -1")
bad_value("occlusion_strength_negative", {"materials": {"m": {"occlusion_strength": SENTINEL}}, "objects": [{"material": "m"}]},
          "materials.m.occlusion_strength", "-0.5", "must be in [0, 1], got -0.5")

# Values inside a range as doubles that single precision rounds out of it.
bad_value("float_underflow_radius", {"objects": [{"radius": SENTINEL}]}, "objects[0].radius", "1e-50",
          "must be > 0, got 1e-50 (0 as a 32-bit float)")
bad_value("float_underflow_scale", {"objects": [dict(MESH, transform={"scale": SENTINEL})]},
          "objects[0].transform.scale[0]", "[1e-46, 1, 1]", "must be > 0, got 1e-46 (0 as a 32-bit float)", focus="1e-46")
bad_value("float_rounds_to_bound", {"camera": {"fov": SENTINEL}}, "camera.fov", "179.999999999",
          "must be in (0, 180), got 179.999999999 (180 as a 32-bit float)")

# JSON syntax, depth, NUL bytes and text after the document.
SPHERE = '{ "objects": [ { "type": "sphere" } ] }'
scene("syntax_empty", "", ":1:1: error: ")
scene("syntax_whitespace_only", "\n  \n", ":3:1: error: ")
scene("syntax_missing_comma", '{\n  "camera": { "fov": 30 }\n  "objects": []\n}\n', ":3:11: error: syntax error")
scene("syntax_trailing_comma", '{\n  "objects": [ { "type": "sphere" }, ]\n}\n', ":2:38: error: syntax error")
scene("syntax_single_quotes", "{ 'objects': [] }", ":1:3: error: syntax error")
scene("syntax_unterminated_string", '{ "objects": [ { "type": "sph', ":1:30: error: syntax error{...}missing closing quote")
scene("syntax_unterminated_comment", SPHERE + "\n/* never closed", ":2:1: error: a /* comment is never closed")
scene("syntax_truncated", SPHERE[:20], ":1:21: error: syntax error")
scene("syntax_bare_word", '{ "render": { "nee": yes } }', ":1:22: error: syntax error")
scene("syntax_nan_literal", '{ "camera": { "fov": NaN } }', ":1:22: error: syntax error")
scene("syntax_infinity_literal", '{ "sky": { "strength": Infinity } }', ":1:24: error: syntax error")
scene("syntax_hex_number", '{ "render": { "spp": 0x10 } }', ":1:23: error: syntax error")
scene("syntax_leading_zero", '{ "render": { "spp": 010 } }', ":1:24: error: syntax error")
scene("syntax_top_level_array", "[ " + SPHERE + " ]", ":1:1: error: (top level): a scene file must be a JSON object")
scene("syntax_top_level_number", "42", ":1:1: error: (top level): a scene file must be a JSON object { ... }, got number")
scene("syntax_duplicate_key", '{\n  "render": { "spp": 4, "spp": 8 }\n}\n', ":2:25: error: render.spp: duplicate key 'spp' (first given at line 2, column 15)")
scene("syntax_unknown_key_typo", '{ "rendr": {} }', ":1:3: error: rendr: unknown key 'rendr' at the top level; did you mean 'render'?")
scene("syntax_unknown_section_key", '{ "camera": { "fvo": 30 } }', ":1:15: error: camera.fvo: unknown key 'fvo'")
scene("syntax_invalid_utf8", b'{ "materials": { "\xff\xfe": {} } }', ":1:19: error: syntax error{...}ill-formed UTF-8")
scene("syntax_control_character", '{ "objects": [ { "type": "sp\x01here" } ] }', ":1:29: error: syntax error{...}control character U+0001")
scene("depth_past_limit", '{ "objects": ' + "[" * 200 + "]" * 200 + " }", "nested too deeply: more than ")
scene("depth_ten_thousand", "[" * 10000 + "]" * 10000, "nested too deeply: more than ")
scene("depth_objects_unclosed", '{"a": ' * 5000, "nested too deeply: more than ")
scene("nul_after_document", SPHERE + "\0garbage", ":1:40: error: unexpected NUL byte (a scene file is text)")
scene("nul_in_comment", "// a comment \0\n" + SPHERE, ":1:14: error: unexpected NUL byte (a scene file is text)")
scene("nul_between_tokens", '{ "objects":\0 [] }', ":1:13: error: unexpected NUL byte (a scene file is text)")
scene("trailing_text", SPHERE + "\n  x", ":2:3: error: unexpected text after the end of the document")
scene("trailing_second_document", SPHERE + " " + SPHERE, ":1:41: error: unexpected text after the end of the document")
scene("number_overflow_in_array", '{ "objects": [ { "center": [0, 1e400, 0] } ] }', ":1:32: error: ")
scene("objects_not_array", '{ "objects": { "type": "sphere" } }', ":1:14: error: objects: expected an array")
scene("materials_not_object", '{ "materials": [] }', ":1:16: error: materials: expected an object")
scene("object_not_object", '{ "objects": [ 3 ] }', ":1:16: error: objects[0]: expected an object")
scene("section_not_object", '{ "render": 3 }', ":1:13: error: render: expected an object")

# Lights: each bad value of an entry of "lights", and a mesh's emission_sides.
LIT = '{ "objects": [ { "type": "sphere" } ],\n  "lights": [ %s ] }\n'
for name, light, expected in [
        ("light_unknown_type", '{ "type": "lamp" }', ":2:25: error: lights[0].type: unknown value 'lamp' (allowed values: point, spot, distant)"),
        ("light_no_type", '{ "position": [0, 1, 0] }', ":2:15: error: lights[0]: a light needs \"type\""),
        ("light_intensity_and_power", '{ "type": "point", "intensity": 1, "power": 10 }', ":2:50: error: lights[0].power: give either \"intensity\" or \"power\", not both"),
        ("light_inner_above_outer", '{ "type": "spot", "inner_angle": 40, "outer_angle": 30 }', ":2:48: error: lights[0].inner_angle: inner_angle (40) must not exceed outer_angle (30)"),
        ("light_zero_direction", '{ "type": "distant", "direction": [0, 0, 0] }', ":2:49: error: lights[0].direction: must be a non-zero direction, got [0, 0, 0]"),
        ("light_key_of_other_type", '{ "type": "point", "irradiance": 1 }', ":2:34: error: lights[0].irradiance: 'irradiance' does not apply to a point light"),
        ("light_negative_intensity", '{ "type": "spot", "intensity": [1, -1, 1] }', ":2:50: error: lights[0].intensity[1]: must be >= 0, got -1"),
        ("light_spot_power_no_cone", '{ "type": "spot", "power": 5, "inner_angle": 0, "outer_angle": 0 }', ":2:42: error: lights[0].power: a spot with outer_angle 0 has no cone"),
        ("light_not_object", '3', ":2:15: error: lights[0]: expected an object")]:
    scene(name, LIT % light, expected)
scene("lights_not_array", '{ "objects": [ { "type": "sphere" } ], "lights": { "type": "point" } }', ":1:50: error: lights: expected an array")
scene("lights_too_many", '{ "objects": [ { "type": "sphere" } ], "lights": [' + ", ".join(['{ "type": "point" }'] * 65) + "] }",
      "error: lights[64]: a scene takes at most 64 lights")

# The renderer's --set overrides (and so its number flags, which become overrides): each a case
# with a valid scene file, the override in the manifest's third column.
for name, override, expected in [
        ("set_time_nan", "render.time=nan", "--set render.time=nan: error: render.time: expected a number, got string"),
        ("set_spp_overflow", "render.spp=1e999", "--set render.spp=1e999: error: the value is not valid JSON: must be finite"),
        ("set_width_negative", "render.width=-5", "--set render.width=-5: error: render.width: must be in [1, 16384], got -5"),
        ("set_seed_fraction", "render.seed=1.5", "--set render.seed=1.5: error: render.seed: must be an integer, got 1.5"),
        ("set_index_past_end", "objects.5.radius=1", "--set objects.5.radius=1: error: objects[5]: index 5 is past the end"),
        ("set_no_value", "render.spp", "--set render.spp: error: expected KEY=VALUE"),
        ("set_empty_part", "render..spp=1", "--set render..spp=1: error: the key 'render..spp' has an empty part"),
        ("set_vec3_arity", "camera.position=[1,2]", "--set camera.position=[1,2]: error: camera.position: expected 3 numbers, got 2"),
        ("set_unknown_key", "camera.fvo=30", "--set camera.fvo=30: error: camera.fvo: unknown key 'fvo'"),
        ("set_fov_single_overflow", "camera.fov=1e39", "--set camera.fov=1e39: error: camera.fov: must be in (0, 180), got 1e+39")]:
    scene(name, SPHERE + "\n", expected, overrides=[override])

with open(os.path.join(OUT, "expected.tsv"), "w") as f:
    f.write("# file\tpiece of the error message\t[--set overrides, '|' between them] (written by make_malformed.py)\n")
    for name, *columns in manifest:
        assert all("\t" not in c and "\n" not in c for c in columns)
        f.write(name + "\t" + "\t".join(columns) + "\n")
print(len(manifest), "malformed files in", OUT)
