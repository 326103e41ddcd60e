"""Which bounces a scene's noise comes from, for bench/samplers.md: the per-pixel variance of the
`direct` debug view (emitters seen and light at the first hit, bounces 0 and 1), of the `indirect`
view (bounces 2 and more) and of the whole estimate, over SEEDS renders of SPP samples with even
spreading, summed over the pixels outside the directly seen emitters (reference brighter than
BRIGHT, grown by MARGIN pixels: their coverage noise is the camera's, not the light transport's).
Run from the repository root after building and after `raylab-bench convergence --mode quick`
has cached the reference:
    PYTHONPATH=build/python /usr/bin/python3 bench/noise_by_bounce.py [SCENE_NAME SCENE_FILE]
"""
import sys

import numpy as np

import raylab

SIZE = {"render.width": 96, "render.height": 54, "render.rpp": 16, "render.adaptive": False}
SPP, SEEDS = 128, 8
BRIGHT, MARGIN = 0.5, 2


def grow(mask, steps):
    for _ in range(steps):
        m = mask.copy()
        m[1:] |= mask[:-1]; m[:-1] |= mask[1:]; m[:, 1:] |= mask[:, :-1]; m[:, :-1] |= mask[:, 1:]
        mask = m
    return mask


def main():
    name, scene_file = (sys.argv[1], sys.argv[2]) if len(sys.argv) > 2 else ("cornell_box", "scenes/cornell_box.json")
    ref = np.asarray(raylab.read_image(f"bench/references/{name}_96x54.exr"))[..., :3].astype(np.float64)
    emitters = grow(ref.mean(axis=2) > BRIGHT, MARGIN)
    scene = raylab.load(scene_file, set=SIZE)
    print(f"{name}, {SPP} spp, seeds 1-{SEEDS}, {emitters.sum()} of {emitters.size} pixels left out as emitters")
    print("| part | summed variance outside the emitters | on the emitters |")
    print("|---|---|---|")
    for view in ("direct", "indirect", None):
        images = np.array([np.asarray(raylab.debug_view(scene, view, spp=SPP, seed=s) if view else
                                      raylab.render(scene, spp=SPP, seed=s))[..., :3] for s in range(1, SEEDS + 1)],
                          dtype=np.float64)
        var = images.var(axis=0, ddof=1).mean(axis=2)
        print(f"| {view or 'whole estimate'} | {var[~emitters].sum():.4g} | {var[emitters].sum():.4g} |")


if __name__ == "__main__":
    main()
