"""A copy of a scene with every inline mesh's transform applied to its positions (and normals), so
that all meshes share the identity transform: the sizing of the lead in bench/mesh_rays.md, "Mesh
transforms baked into positions". Texture paths become absolute; glTF and OBJ objects are copied as
they are. The transform is FORMAT.md's: scale, then rotation about x, then y, then z (degrees,
world axes), then translation.
    python3 bench/bake_mesh_transforms.py SCENE_IN SCENE_OUT
"""
import json
import math
import os
import sys


def rotation(rx, ry, rz):
    cx, sx = math.cos(math.radians(rx)), math.sin(math.radians(rx))
    cy, sy = math.cos(math.radians(ry)), math.sin(math.radians(ry))
    cz, sz = math.cos(math.radians(rz)), math.sin(math.radians(rz))
    x = [[1, 0, 0], [0, cx, -sx], [0, sx, cx]]
    y = [[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]]
    z = [[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]]
    mul = lambda a, b: [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    return mul(z, mul(y, x))


def apply(m, v):
    return [sum(m[i][k] * v[k] for k in range(3)) for i in range(3)]


def bake(obj):
    t = obj.pop("transform", None)
    if t is None or obj.get("type") != "mesh" or "positions" not in obj:
        if t is not None:
            obj["transform"] = t
        return
    s = t.get("scale", 1.0)
    s = [s, s, s] if isinstance(s, (int, float)) else s
    r = rotation(*t.get("rotation", [0, 0, 0]))
    d = t.get("translation", [0, 0, 0])
    p = obj["positions"]
    for i in range(0, len(p), 3):
        q = apply(r, [p[i] * s[0], p[i + 1] * s[1], p[i + 2] * s[2]])
        p[i:i + 3] = [q[0] + d[0], q[1] + d[1], q[2] + d[2]]
    n = obj.get("normals", [])
    for i in range(0, len(n), 3):   # the inverse transpose: rotation of the normal divided by the scale
        q = apply(r, [n[i] / s[0], n[i + 1] / s[1], n[i + 2] / s[2]])
        length = math.sqrt(sum(c * c for c in q)) or 1.0
        n[i:i + 3] = [c / length for c in q]


def main():
    src, dst = sys.argv[1], sys.argv[2]
    text = "\n".join(line for line in open(src) if not line.lstrip().startswith("//"))
    scene = json.loads(text)
    base = os.path.dirname(os.path.abspath(src))
    for m in scene.get("materials", {}).values():
        for k, v in m.items():
            if k.endswith("_texture") and isinstance(v, str) and not os.path.isabs(v):
                m[k] = os.path.join(base, v)
    for obj in scene.get("objects", []):
        if isinstance(obj.get("file"), str) and not os.path.isabs(obj["file"]):
            obj["file"] = os.path.join(base, obj["file"])
        bake(obj)
    with open(dst, "w") as f:
        json.dump(scene, f)


if __name__ == "__main__":
    main()
