"""How much of the convergence curves' error is the reference's own noise, for bench/samplers.md:
raylab's MSE against the quick benchmark's cached reference at 16 … 1024 spp (mean over SEEDS),
the reference's variance of the mean (its .variance.exr, mean over pixels and RGB) as a share of
it, and the log–log RMSE slope over those points with and without that variance subtracted
(E[(X − R)²] = Var X + Var R for independent X and R, both unbiased).
Run from the repository root after building and after `raylab-bench convergence --mode quick`
has cached the reference:
    PYTHONPATH=build/python nice -n 5 /usr/bin/python3 bench/reference_noise.py [SCENE_NAME SCENE_FILE]
"""
import sys

import numpy as np

import raylab

SIZE = {"render.width": 96, "render.height": 54}
SPPS = [16, 32, 64, 128, 256, 512, 1024]
SEEDS = 3


def main():
    name, scene_file = (sys.argv[1], sys.argv[2]) if len(sys.argv) > 2 else ("default", "scenes/default.json")
    base = f"bench/references/{name}_96x54"
    ref = np.asarray(raylab.read_image(base + ".exr"))[..., :3].astype(np.float64)
    ref_var = np.asarray(raylab.read_image(base + ".variance.exr"))[..., :3].astype(np.float64).mean()
    scene = raylab.load(scene_file, set=SIZE)
    mse = [np.mean([((np.asarray(raylab.render(scene, spp=spp, seed=s))[..., :3] - ref) ** 2).mean()
                    for s in range(1, SEEDS + 1)]) for spp in SPPS]
    print(f"{name}: reference variance of the mean {ref_var:.3g} (mean {ref.mean():.4f})")
    print("| spp | MSE | reference's share | RMSE, % of the mean | less the reference's variance |")
    print("|---|---|---|---|---|")
    for spp, m in zip(SPPS, mse):
        print(f"| {spp} | {m:.3g} | {100 * ref_var / m:.0f} % | {100 * np.sqrt(m) / ref.mean():.2f} % | "
              f"{100 * np.sqrt(max(m - ref_var, 0.0)) / ref.mean():.2f} % |")
    x = np.log(SPPS)
    raw = np.polyfit(x, 0.5 * np.log(mse), 1)[0]
    net = np.polyfit(x, 0.5 * np.log(np.maximum(np.array(mse) - ref_var, 1e-30)), 1)[0]
    print(f"slope {SPPS[0]}–{SPPS[-1]} spp: {raw:.3f} as measured, {net:.3f} less the reference's variance")


if __name__ == "__main__":
    main()
