"""The pixels that hold a render's error, for bench/samplers.md: per seed, a render at SPP against
the quick benchmark's cached reference, its RMSE in % of the reference's mean and the worst
pixels with their share of the image's MSE, the reference's value and the render's.
Run from the repository root after building and after `raylab-bench convergence --mode quick`
has cached the reference:
    PYTHONPATH=build/python nice -n 5 /usr/bin/python3 bench/worst_pixels.py NAME SCENE_FILE SPP SEED...
e.g. `veach_mis scenes/veach_mis.json 1024 1 2 4`.
"""
import sys

import numpy as np

import raylab

SIZE = {"render.width": 96, "render.height": 54}
SHOWN = 5


def main():
    name, scene_file, spp, seeds = sys.argv[1], sys.argv[2], int(sys.argv[3]), [int(s) for s in sys.argv[4:]]
    ref = np.asarray(raylab.read_image(f"bench/references/{name}_96x54.exr"))[..., :3].astype(np.float64)
    scene = raylab.load(scene_file, set=SIZE)
    for seed in seeds:
        img = np.asarray(raylab.render(scene, spp=spp, seed=seed))[..., :3]
        err = ((img - ref) ** 2).mean(axis=2)
        print(f"seed {seed}: RMSE {100 * np.sqrt(err.mean()) / ref.mean():.1f} % of the mean")
        for k in np.argsort(err.ravel())[::-1][:SHOWN]:
            y, x = divmod(int(k), err.shape[1])
            print(f"  x {x} y {y}: {100 * err[y, x] / err.sum():.1f} % of the MSE, "
                  f"reference {ref[y, x].mean():.4g}, render {img[y, x].mean():.4g}")


if __name__ == "__main__":
    main()
