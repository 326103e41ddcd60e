"""How much per-pixel adaptive sampling could gain on each peer scene, for bench/adaptive_sampling.md:
the ceiling of the image MSE's fall at an equal number of samples when every pixel (or block of
pixels) gets samples in proportion to its standard deviation, against the same number spread evenly.
With n_i samples, pixel i's mean has variance s_i^2 / n_i; over N pixels and n samples each in all,
even spreading gives sum(s_i^2) / n and the best spreading (n_i proportional to s_i, found by a
Lagrange multiplier) gives (sum s_i)^2 / (N n), so the ratio is mean(s^2) / mean(s)^2. A block
(the SIMD batch of llvmpipe's fragment shader is 4x2 pixels) shares one count: its s is the root of
its pixels' mean variance. Equal cost per sample is assumed, so pixels that see only the sky (one
ray, no variance) count as dear as the rest: the ceiling at equal time is lower there.
The s_i come from SEEDS renders of SPP samples each (sobol: each render's per-pixel variance is that
of a SPP-sample mean, its stratification included).
Run from the repository root after building:
    PYTHONPATH=build/python nice -n 5 /usr/bin/python3 bench/adaptive_ceiling.py [SCENE_FILE...]
"""
import sys

import numpy as np

import raylab

SIZE = {"render.width": 96, "render.height": 54}   # the quick benchmark's image
SPP = 64
SEEDS = 32
BLOCKS = [(1, 1), (4, 2), (4, 4), (8, 8)]
PEER_SCENES = ["default", "cornell_box", "materials", "veach_mis", "textured_bricks", "displaced_terrain",
               "environment"]


def ceiling(variance, bw, bh):
    h, w = variance.shape[0] // bh * bh, variance.shape[1] // bw * bw
    blocks = variance[:h, :w].reshape(h // bh, bh, w // bw, bw).mean(axis=(1, 3))
    s = np.sqrt(blocks)
    return float((s ** 2).mean() / s.mean() ** 2)


def main():
    scenes = sys.argv[1:] or [f"scenes/{name}.json" for name in PEER_SCENES]
    print(f"{SEEDS} seeds x {SPP} spp, {SIZE['render.width']}x{SIZE['render.height']}")
    print("| scene | pixels without variance | " + " | ".join(f"{bw}×{bh}" for bw, bh in BLOCKS) + " |")
    print("|---|---|" + "---|" * len(BLOCKS))
    for path in scenes:
        scene = raylab.load(path, SIZE)
        images = np.stack([np.asarray(raylab.render(scene, spp=SPP, seed=seed, rpp=16))[..., :3]
                           for seed in range(1, SEEDS + 1)])
        variance = images.var(axis=0, ddof=1).mean(axis=2)   # per pixel, RGB averaged
        cells = " | ".join(f"{ceiling(variance, bw, bh):.2f}×" for bw, bh in BLOCKS)
        print(f"| {path} | {np.mean(variance == 0.0) * 100:.1f} % | {cells} |", flush=True)


if __name__ == "__main__":
    main()
