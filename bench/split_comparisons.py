"""The figures of bench/split_comparisons.md: the three split comparisons of the thesis (Fig. 5.2's
render.accel none / boxes / bvh, render.diffuse_sampling uniform / cosine, render.ggx_sampling
d_cos / vndf) at equal time.

For each scene and side: the cost in ms per sample per pixel (the tracing seconds of TIME_SPP-sample
renders, REPEATS repeats with the sides interleaved so that the shared machine's load falls on both
alike; the median), the variance of one sample (per pixel and channel the variance over SEEDS
renders of VAR_SPP samples, times VAR_SPP, summed over the image), the relative efficiency
1 / (variance x time) as a ratio to the default side, and the RMSE each side reaches in the same
time (the time the default side takes for BUDGET_SPP samples; the other side gets the samples
that time buys) against a REF_SPP x 4 sample reference of the default side, averaged over SEEDS
seeds. The acceleration modes trace the same samples (checked: equal images), so only their cost
differs. Run from the repository root after building:
    PYTHONPATH=build/python nice -n 5 /usr/bin/python3 bench/split_comparisons.py [SCENE KEY ...]
(with SCENE KEY pairs, e.g. displaced_terrain.json render.accel, only those comparisons).
"""
import os
import statistics
import sys
import zlib

import numpy as np

import raylab

SIZE = {"render.width": 64, "render.height": 36}
REPEATS = 5
TIME_SPP = 8
SEEDS = 8
VAR_SPP = 16
BUDGET_SPP = 32
REF_SPP = 512
CACHE = "build/bench_split_references"

# scene, fixed keys, key, the sides (the default last), what it shows
COMPARISONS = [
    ("cornell_box.json", {}, "render.accel", ["none", "boxes", "bvh"]),
    ("textured_bricks.json", {}, "render.accel", ["none", "boxes", "bvh"]),
    ("displaced_terrain.json", {}, "render.accel", ["none", "boxes", "bvh"]),
    ("lesson_one_sphere.json", {"render.nee": False}, "render.diffuse_sampling", ["uniform", "cosine"]),
    ("cornell_box.json", {}, "render.diffuse_sampling", ["uniform", "cosine"]),
    ("materials.json", {"render.nee": False}, "render.ggx_sampling", ["d_cos", "vndf"]),
    ("veach_mis.json", {}, "render.ggx_sampling", ["d_cos", "vndf"]),
    # Lesson 8 step 3's split: the blue ball made glossy, light found by BSDF samples only.
    ("lesson_one_sphere.json", {"render.nee": False, "materials.ball.albedo": [0.1, 0.2, 0.8],
                                "materials.ball.f0": 0.04, "materials.ball.roughness": 0.6},
     "render.ggx_sampling", ["d_cos", "vndf"]),
]


def scene_of(scene_file, keys):
    return raylab.load("scenes/" + scene_file, set={**SIZE, **keys})


def ms_per_spp(scenes):
    """Median tracing ms per spp of each scene, the scenes interleaved within each repeat."""
    times = [[] for _ in scenes]
    for r in range(REPEATS):
        for i, s in enumerate(scenes):
            img = raylab.render(s, spp=TIME_SPP, seed=17 + r)
            times[i].append(img.meta["seconds"] * 1e3 / TIME_SPP)
    return [statistics.median(t) for t in times]


def sample_variance(scene):
    images = np.stack([raylab.render(scene, spp=VAR_SPP, seed=1000 + 7919 * s)[..., :3] for s in range(SEEDS)])
    return float(images.var(axis=0, ddof=1).sum()) * VAR_SPP


def equal_time_rmse(scene, spp, reference):
    return float(np.mean([raylab.rmse(raylab.render(scene, spp=spp, seed=5000 + 31 * s), reference)
                          for s in range(SEEDS)]))


def main():
    if len(sys.argv) % 2 == 0:
        sys.exit("usage: split_comparisons.py [SCENE KEY ...]")
    only = set(zip(sys.argv[1::2], sys.argv[2::2]))
    os.makedirs(CACHE, exist_ok=True)
    load = os.getloadavg()
    print(f"load average {load[0]:.1f} {load[1]:.1f} {load[2]:.1f} on {os.cpu_count()} CPUs; "
          f"{SIZE['render.width']}x{SIZE['render.height']}, times: median of {REPEATS} interleaved "
          f"{TIME_SPP}-spp renders; variance: {SEEDS} seeds x {VAR_SPP} spp; reference {REF_SPP} x 4 spp; "
          f"budget: {BUDGET_SPP} spp of the default side")
    print("| scene | fixed keys | key | side | ms / spp | variance / sample | efficiency vs default "
          "| spp in the budget | RMSE at equal time |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for scene_file, fixed, key, sides in COMPARISONS:
        if only and (scene_file, key) not in only:
            continue
        scenes = [scene_of(scene_file, {**fixed, key: side}) for side in sides]
        times = ms_per_spp(scenes)
        default = scenes[-1]
        ref, _ = raylab.reference(default, spp=REF_SPP, batches=4,
                                  cache=f"{CACHE}/{scene_file[:-5]}_{zlib.crc32(str(sorted(fixed.items())).encode())}")
        if key == "render.accel":
            same = all(np.array_equal(raylab.render(s, spp=2, seed=3), raylab.render(default, spp=2, seed=3))
                       for s in scenes[:-1])
            variances = [sample_variance(default)] * len(scenes)
            note = "equal images" if same else "IMAGES DIFFER"
        else:
            variances = [sample_variance(s) for s in scenes]
            note = ""
        budget_ms = BUDGET_SPP * times[-1]
        shown = " ".join(f"{k}={v}" for k, v in fixed.items()) or "-"
        for side, s, t, v in zip(sides, scenes, times, variances):
            spp = max(1, int(budget_ms / t))
            rmse = equal_time_rmse(s, spp, ref)
            efficiency = (variances[-1] * times[-1]) / (v * t)
            print(f"| {scene_file} | {shown} | {key} | {side} | {t:.2f} | {v:.4g} | {efficiency:.3f} | {spp} "
                  f"| {rmse:.4g} |{' ' + note if note and side == sides[-1] else ''}", flush=True)
    load = os.getloadavg()
    print(f"load average at the end {load[0]:.1f} {load[1]:.1f} {load[2]:.1f}")


main()
