"""The figures of bench/estimator_stages.md: variance of each estimator stage's naive value against
its default, and the box and triangle tests per camera ray of the three render.accel modes.

Variance: per pixel and channel, the sample variance over SEEDS renders of SPP samples each, summed
over the image; the ratio is naive / default on the same scene at the same size and spp. Tests per
ray: the mean of the boxes debug view (a camera ray's box and triangle tests in red and green). Run from the
repository root after building:
    PYTHONPATH=build/python nice -n 5 /usr/bin/python3 bench/estimator_stages.py
"""
import numpy as np

import raylab

SEEDS = 8
SPP = 16
SIZE = {"render.width": 64, "render.height": 36}


def variance(scene_file, keys):
    scene = raylab.load("scenes/" + scene_file, set={**SIZE, **keys})
    images = np.stack([raylab.render(scene, spp=SPP, seed=1000 + 7919 * s)[..., :3] for s in range(SEEDS)])
    return float(images.var(axis=0, ddof=1).sum()), float(images.mean())


COMPARISONS = [
    # scene, fixed keys, stage key, naive value, default value
    ("lesson_one_sphere.json", {"render.nee": False}, "render.diffuse_sampling", "uniform", "cosine"),
    ("cornell_box.json", {}, "render.diffuse_sampling", "uniform", "cosine"),
    ("materials.json", {"render.nee": False}, "render.ggx_sampling", "d_cos", "vndf"),
    ("veach_mis.json", {}, "render.ggx_sampling", "d_cos", "vndf"),
    # veach_mis.json's four lamps have equal powers: the smallest made ten times as bright, so they differ.
    ("veach_mis.json", {"materials.lamp_xs.strength": 8000}, "render.light_selection", "uniform", "power"),
    ("cornell_box.json", {}, "render.light_sampling", "area", "solid_angle"),
    ("cornell_box.json", {"render.mis": False}, "render.light_sampling", "area", "solid_angle"),
]

print(f"variance over {SEEDS} seeds at {SPP} spp, {SIZE['render.width']}x{SIZE['render.height']}")
for scene_file, fixed, key, naive, default in COMPARISONS:
    v_naive, m_naive = variance(scene_file, {**fixed, key: naive})
    v_default, m_default = variance(scene_file, {**fixed, key: default})
    shown = " ".join(f"{k}={v}" for k, v in fixed.items())
    print(f"{scene_file} {shown} {key}: {naive} / {default} = {v_naive / v_default:.2f} "
          f"(means {m_naive:.4f} and {m_default:.4f})")

print("tests per camera ray (mean over the image, 1 spp)")
for scene_file in ("cornell_box.json", "textured_bricks.json", "displaced_terrain.json"):
    for accel in ("bvh", "boxes", "none"):
        scene = raylab.load("scenes/" + scene_file, set={**SIZE, "render.accel": accel})
        counts = raylab.debug_view(scene, "boxes", spp=1)   # red: boxes, green: triangles
        print(f"{scene_file} {accel}: {float(counts[..., 0].mean()):.1f} boxes, "
              f"{float(counts[..., 1].mean()):.1f} triangles")
