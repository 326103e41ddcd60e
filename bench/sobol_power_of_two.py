"""Is sobol's error at a power of two lower than the log-log line through its neighbours says?

Even spreading is measured at 2^k spp, where each pixel holds a whole Owen-scrambled net; an
adaptive block holds any multiple of rpp. This renders each scene at 256, 384, 512, 768 and 1024 spp
(seeds 1-4, 96x54, rpp 16, the defaults) against the quick benchmark's cached reference and prints
each MSE beside the line through the three powers of two (bench/adaptive_sampling.md).

    PYTHONPATH=build/python /usr/bin/python3 bench/sobol_power_of_two.py large_mesh cornell_box materials default
"""
import sys

import numpy as np
import raylab

SCENES = {"large_mesh": "scenes/displaced_terrain.json", "cornell_box": "scenes/cornell_box.json",
          "materials": "scenes/materials.json", "default": "scenes/default.json"}
COUNTS = (256, 384, 512, 768, 1024)

for name in sys.argv[1:] or SCENES:
    reference = np.asarray(raylab.read_image(f"bench/references/{name}_96x54.exr"))[..., :3]
    scene = raylab.load(SCENES[name], {"render.width": 96, "render.height": 54})
    mse = []
    for spp in COUNTS:
        images = [np.asarray(raylab.render(scene, spp=spp, seed=seed, rpp=16))[..., :3] for seed in (1, 2, 3, 4)]
        mse.append(float(np.mean([np.mean((image - reference) ** 2) for image in images])))
    powers = [i for i, spp in enumerate(COUNTS) if spp & (spp - 1) == 0]
    line = np.polyfit(np.log([COUNTS[i] for i in powers]), np.log([mse[i] for i in powers]), 1)
    for spp, m in zip(COUNTS, mse):
        expected = float(np.exp(np.polyval(line, np.log(spp))))
        print(f"{name} {spp}: MSE {m:.4g}, the powers' line {expected:.4g}, ratio {m / expected:.3f}", flush=True)
