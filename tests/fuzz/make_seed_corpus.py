#!/usr/bin/env python3
"""Gathers the seed corpora and dictionaries of the libFuzzer harnesses into the build tree.

    python3 tests/fuzz/make_seed_corpus.py --source . --out build-asan/tests/fuzz/corpus

writes OUT/<harness>/ (one file per seed, named by its content's hash) and OUT/<harness>.dict, from
scenes/, lessons/, tests/data/malformed/ and scenes/FORMAT.md (whose key tables a test checks
against the parameter table). Nothing here is committed twice: the seeds are copies of files kept
elsewhere. CMake's fuzz_corpus target runs it.
"""
import argparse
import hashlib
import os
import re
import shutil

MAX_SEED = 16384   # the harnesses run with -max_len at most this; longer files are cut at a newline

# The scratch folder's files (tests/fuzz/fuzz_support.h) that fuzzed inputs may name.
SCRATCH_FILES = ["tiny.obj", "tiny.gltf", "tiny.bin", "tiny.ppm", "tiny.hdr", "scene.json"]

OBJ_TOKENS = ["v ", "vn ", "vt ", "vp ", "f ", "l ", "p ", "o ", "g ", "s ", "usemtl ", "mtllib ", "#", "/", "//",
              "\\\n", "\r\n", "nan", "inf", "-1", "1e38", "1e39", "2147483648", "0.5", "-0", "e-", "\t"]

GLTF_TOKENS = ["asset", "version", "2.0", "scene", "scenes", "nodes", "node", "mesh", "meshes", "primitives",
               "attributes", "POSITION", "NORMAL", "TEXCOORD_0", "TEXCOORD_1", "indices", "material", "materials",
               "buffers", "buffer", "bufferViews", "bufferView", "accessors", "byteOffset", "byteLength",
               "byteStride", "componentType", "count", "type", "SCALAR", "VEC2", "VEC3", "VEC4", "MAT4", "uri",
               "data:application/octet-stream;base64,", "data:image/png;base64,", "images", "textures",
               "samplers", "source", "sampler", "children", "matrix", "translation", "rotation", "scale", "mode",
               "min", "max", "sparse", "normalized", "extensions", "extensionsUsed", "extensionsRequired",
               "KHR_materials_emissive_strength", "emissiveStrength", "pbrMetallicRoughness", "baseColorTexture",
               "baseColorFactor", "metallicFactor", "roughnessFactor", "metallicRoughnessTexture",
               "normalTexture", "emissiveTexture", "emissiveFactor", "occlusionTexture", "alphaMode", "index",
               "texCoord", "wrapS", "wrapT", "magFilter", "minFilter", "mimeType", "image/png", "image/jpeg",
               "5120", "5121", "5122", "5123", "5125", "5126", "33071", "33648", "10497", "glTF", "JSON",
               "BIN\0", "18446744073709551615", "4294967295", "-1"] + SCRATCH_FILES

JSON_TOKENS = ["{", "}", "[", "]", ":", ",", "\"", "true", "false", "null", "1e999", "-1", "0.5", "1e39",
               "2147483648", "4294967296", "//", "/*", "*/", "\\u0000", "\0"]


def dict_line(token):
    out = []
    for b in token.encode("utf-8"):
        c = chr(b)
        if c in "\\\"":
            out.append("\\" + c)
        elif 32 <= b < 127:
            out.append(c)
        else:
            out.append("\\x%02X" % b)
    return '"' + "".join(out) + '"'


def write_dict(path, tokens):
    seen = []
    for t in tokens:
        if t and t not in seen:
            seen.append(t)
    with open(path, "w") as f:
        for t in seen:
            f.write(dict_line(t) + "\n")


class Corpus:
    def __init__(self, root, name):
        self.dir = os.path.join(root, name)
        os.makedirs(self.dir)
        self.count = 0

    def add(self, data):
        if isinstance(data, str):
            data = data.encode("utf-8", "surrogateescape")
        if len(data) > MAX_SEED:
            cut = data.rfind(b"\n", 0, MAX_SEED)
            data = data[:cut + 1 if cut > 0 else MAX_SEED]
        name = hashlib.sha1(data).hexdigest()
        path = os.path.join(self.dir, name)
        if not os.path.exists(path):
            with open(path, "wb") as f:
                f.write(data)
            self.count += 1


def read(path):
    with open(path, "rb") as f:
        return f.read()


def files(folder, *exts):
    if not os.path.isdir(folder):
        return []
    return sorted(os.path.join(folder, n) for n in os.listdir(folder) if n.endswith(exts))


def format_keys(source):
    """Keys of FORMAT.md's tables and the enum names of their range column."""
    keys, names = [], []
    with open(os.path.join(source, "scenes", "FORMAT.md"), encoding="utf-8") as f:
        for line in f:
            cells = [c.strip() for c in line.split("|")]
            if len(cells) > 6 and cells[1].startswith("`") and cells[1].endswith("`"):
                keys.append(cells[1].strip("`"))
                if cells[2] == "enum":
                    names += [n.strip("() ") for n in re.split(r"[ ,]+", cells[5]) if n not in ("or",)]
    return keys, names


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--source", required=True)
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    src, out = args.source, args.out
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    malformed = os.path.join(src, "tests", "data", "malformed")

    # fuzz_scene: the first line is the '|'-separated --set list (fuzz_scene.cpp).
    scene = Corpus(out, "fuzz_scene")
    for path in files(os.path.join(src, "scenes"), ".json"):
        text = read(path)
        scene.add(b"\n" + text)
        scene.add(b"render.spp=4|camera.fov=30|objects.0.radius=2|sky.type=constant\n" + text)
    with open(os.path.join(malformed, "expected.tsv"), encoding="utf-8") as f:
        for line in f:
            cells = line.rstrip("\n").split("\t")
            if cells[0].startswith("json_"):
                scene.add((cells[2] if len(cells) > 2 else "").encode() + b"\n" + read(os.path.join(malformed, cells[0])))
    scene.add('\n{"objects": [{"type": "mesh", "file": "tiny.obj", "transform": {"scale": 2}}]}')
    scene.add('\n{"objects": [{"type": "mesh", "file": "tiny.gltf"}]}')
    scene.add('\n{"materials": {"m": {"albedo_texture": "tiny.ppm", "normal_texture": "tiny.ppm"}},'
              ' "objects": [{"material": "m"}]}')
    scene.add('\n{"sky": {"type": "map", "map": "tiny.hdr"}}')
    keys, enum_names = format_keys(src)
    parts = sorted({p for k in keys for p in k.split(".")})
    write_dict(os.path.join(out, "fuzz_scene.dict"),
               ['"%s"' % k for k in parts] + ["%s=" % k for k in keys] + ['"%s"' % n for n in enum_names] +
               ['"camera"', '"render"', '"sky"', '"materials"', '"objects"', '"sphere"', '"mesh"', "|", "\n"] +
               ['"%s"' % f for f in SCRATCH_FILES] + JSON_TOKENS)

    obj = Corpus(out, "fuzz_obj")
    for path in files(malformed, ".obj") + files(os.path.join(src, "scenes", "meshes"), ".obj"):
        obj.add(read(path))
    write_dict(os.path.join(out, "fuzz_obj.dict"), OBJ_TOKENS)

    gltf = Corpus(out, "fuzz_gltf")
    for path in files(malformed, ".gltf", ".glb") + files(os.path.join(src, "scenes", "meshes"), ".gltf", ".glb"):
        gltf.add(read(path))
    write_dict(os.path.join(out, "fuzz_gltf.dict"), ['"%s"' % t for t in GLTF_TOKENS] + GLTF_TOKENS + JSON_TOKENS)

    # fuzz_script: lessons (their scene named as the scratch folder's scene.json) and their blocks.
    script = Corpus(out, "fuzz_script")
    commands = set()
    for path in files(os.path.join(src, "lessons"), ".md"):
        text = read(path).decode("utf-8")
        script.add(re.sub(r"(?m)^Scene: .*$", "Scene: scene.json", text))
        for block in re.findall(r"```raylab\n(.*?)```", text, re.S):
            script.add(block)
            commands.update(line.split()[0] for line in block.splitlines() if line.split())
    with open(os.path.join(src, "src", "script", "script.h"), encoding="utf-8") as f:
        for line in f:
            m = re.match(r"//   ([a-z][a-z-]+) ", line)
            if m:
                commands.add(m.group(1))
    write_dict(os.path.join(out, "fuzz_script.dict"),
               sorted(commands) + keys + enum_names + ["```raylab\n", "```\n", "## Step 1: ", "# ", "Scene: ",
                                                      "## Learning goals", "## Questions", "## Exercise",
                                                      "## Teacher's notes", "## Sources", "{#goals}", "{#step}",
                                                      "{#step .optional}", "{#questions}", "{#exercise}", "{#code}",
                                                      "{#further}", "{#notes}", "{#sources}", "Language: ", "on",
                                                      "off", "next"])
    for c in (scene, obj, gltf, script):
        print("%s: %d seeds" % (os.path.basename(c.dir), c.count))


if __name__ == "__main__":
    main()
