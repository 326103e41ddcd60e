"""The binding renders what raylab-render renders: the same scene and seed give the same bits."""
import json
import os
import unittest

import numpy as np

import raylab
from support import TempDir, run_render, scene_path, small


class RenderMatchesCli(unittest.TestCase):
    def assert_same_as_cli(self, name, spp, seed, cli_args, **keys):
        scene = small(name, **keys)
        image = raylab.render(scene, spp=spp, seed=seed)
        with TempDir() as tmp:
            out = os.path.join(tmp, "cli.exr")
            sets = [f"--set={k}={json.dumps(v)}" for k, v in {"render.width": 32, "render.height": 18, **keys}.items()]
            status, _, err = run_render(scene_path(name), "-o", out, "--spp", str(spp), "--seed", str(seed), *sets,
                                        *cli_args)
            self.assertEqual(status, 0, err)
            cli = raylab.read_image(out)
        self.assertEqual(image.shape, (18, 32, 4))
        self.assertEqual(image.dtype, np.float32)
        self.assertTrue(np.array_equal(image, cli), f"{name}: max |difference| {np.abs(image - cli).max()}")
        self.assertEqual(image.meta["spp"], cli.meta["spp"])
        self.assertEqual(image.meta["settings_hash"], cli.meta["settings_hash"])
        for stage in ("diffuse_sampling", "ggx_sampling", "light_selection", "light_sampling", "accel"):
            self.assertEqual(image.meta[stage], cli.meta[stage], stage)   # the EXR's raylab:<stage>
        return image

    def test_default_scene_bit_for_bit(self):
        self.assert_same_as_cli("default.json", 8, 5, [])

    def test_every_sampler_and_estimator_bit_for_bit(self):
        for sampler in ("independent", "stratified", "sobol", "zsobol"):
            with self.subTest(sampler=sampler):
                self.assert_same_as_cli("cornell_box.json", 4, 2, [], **{"render.sampler": sampler})
        self.assert_same_as_cli("veach_mis.json", 4, 3, [], **{"render.nee": False})

    def test_estimator_stages_bit_for_bit_and_in_the_metadata(self):
        # Each stage through --set and the module alike, named in both metadata (the EXR's
        # raylab:* attributes and the module's dict); the defaults are named too.
        stages = {"render.diffuse_sampling": "uniform", "render.ggx_sampling": "d_cos",
                  "render.light_selection": "uniform", "render.light_sampling": "area", "render.accel": "boxes"}
        image = self.assert_same_as_cli("cornell_box.json", 2, 4, [], **stages)
        for key, value in stages.items():
            self.assertEqual(image.meta[key.split(".")[1]], value)
        none = self.assert_same_as_cli("cornell_box.json", 2, 4, [], **{"render.accel": "none"})
        self.assertEqual(none.meta["accel"], "none")
        self.assertEqual(none.meta["diffuse_sampling"], "cosine")

    def test_several_samples_per_pass_bit_for_bit(self):
        self.assert_same_as_cli("materials.json", 6, 1, ["--rpp", "3"], **{"render.rpp": 3})

    def test_an_edit_renders_as_the_same_key_on_the_command_line(self):
        scene = small("default.json")
        scene["materials.red.albedo"] = [0.1, 0.9, 0.1]
        edited = raylab.render(scene, spp=2, seed=1)
        with TempDir() as tmp:
            out = os.path.join(tmp, "cli.exr")
            status, _, err = run_render(scene_path("default.json"), "-o", out, "--spp", "2", "--seed", "1",
                                        "--width", "32", "--height", "18", "--set", "materials.red.albedo=[0.1,0.9,0.1]")
            self.assertEqual(status, 0, err)
            self.assertTrue(np.array_equal(edited, raylab.read_image(out)))
        self.assertFalse(np.array_equal(edited, raylab.render(small("default.json"), spp=2, seed=1)))

    def test_debug_view_matches_cli(self):
        scene = small("cornell_box.json")
        view = raylab.debug_view(scene, "normals", spp=1)
        with TempDir() as tmp:
            out = os.path.join(tmp, "normals.exr")
            status, _, err = run_render(scene_path("cornell_box.json"), "--debug-view", "normals", "-o", out,
                                        "--spp", "1", "--width", "32", "--height", "18")
            self.assertEqual(status, 0, err)
            self.assertTrue(np.array_equal(view, raylab.read_image(out)))
        self.assertEqual(view.meta["view"], "normals")
        self.assertIn("BVH boxes tested", raylab.debug_view(scene, "boxes", spp=1).meta["legend"])

    def test_inspect_matches_cli(self):
        scene = small("cornell_box.json")
        records = raylab.inspect(scene, 16, 9, paths=3)
        with TempDir() as tmp:
            out = os.path.join(tmp, "paths.json")
            status, _, err = run_render(scene_path("cornell_box.json"), "--inspect", "16,9", "--inspect-paths", "3",
                                        "--inspect-out", out, "--width", "32", "--height", "18")
            self.assertEqual(status, 0, err)
            with open(out) as f:
                self.assertEqual(records, json.load(f))
        self.assertEqual(len(records), 3)
        for r in records:   # the recorded value is the sum of its terms
            np.testing.assert_allclose(r["value"], r["sum_of_terms"], rtol=1e-4, atol=1e-6)

    def test_progressive_checkpoints_equal_renders_of_that_many_samples(self):
        scene = small("default.json")
        seen = []
        for image in raylab.progressive(scene, [1, 3, 8], seed=4):
            seen.append(image.meta["spp"])
            last = image
        self.assertEqual(seen, [1, 3, 8])
        self.assertTrue(np.array_equal(last, raylab.render(scene, spp=8, seed=4)))

    def test_same_seed_same_image_other_seed_other_image(self):
        scene = small("default.json")
        a, b, c = (raylab.render(scene, spp=2, seed=s) for s in (7, 7, 8))
        self.assertTrue(np.array_equal(a, b))
        self.assertFalse(np.array_equal(a, c))


if __name__ == "__main__":
    unittest.main()
