"""Where a scene's error lies, for bench/samplers.md: the MSE of a few seeds' renders (RUNS)
against the quick benchmark's cached reference, per pixel, and the share of it held by the
brightest pixels of the reference (the emitters seen directly and their edges) and by the worst
1 % of the pixels, with even and with adaptive spreading (render.adaptive).
Run from the repository root after building and after `raylab-bench convergence --mode quick`
has cached the reference:
    PYTHONPATH=build/python nice -n 5 /usr/bin/python3 bench/error_by_pixel.py [SCENE_NAME SCENE_FILE]
"""
import sys

import numpy as np

import raylab

SIZE = {"render.width": 96, "render.height": 54, "render.rpp": 16}
RUNS = [(64, 6), (256, 4), (1024, 2)]   # (spp, seeds)
BRIGHT = 1.0                 # reference radiance (mean of RGB) above which a pixel counts as bright


def main():
    name, scene_file = (sys.argv[1], sys.argv[2]) if len(sys.argv) > 2 else ("cornell_box", "scenes/cornell_box.json")
    ref = np.asarray(raylab.read_image(f"bench/references/{name}_96x54.exr"))[..., :3].astype(np.float64)
    bright = ref.mean(axis=2) > BRIGHT
    print(f"{name}: {bright.sum()} of {bright.size} pixels brighter than {BRIGHT} in the reference")
    print("| spreading | spp | seeds | RMSE, % of the mean | share of the MSE in the bright pixels | in the worst 1 % |")
    print("|---|---|---|---|---|---|")
    for spreading, adaptive in (("even", False), ("adaptive", True)):
        scene = raylab.load(scene_file, set={**SIZE, "render.adaptive": adaptive})
        for spp, seeds in RUNS:
            mse = np.mean([((np.asarray(raylab.render(scene, spp=spp, seed=s))[..., :3] - ref) ** 2).mean(axis=2)
                           for s in range(1, seeds + 1)], axis=0)
            worst = np.sort(mse.ravel())[::-1][: mse.size // 100].sum()
            print(f"| {spreading} | {spp} | {seeds} | {100 * np.sqrt(mse.mean()) / ref.mean():.1f} % | "
                  f"{100 * mse[bright].sum() / mse.sum():.0f} % | {100 * worst / mse.sum():.0f} % |")


if __name__ == "__main__":
    main()
