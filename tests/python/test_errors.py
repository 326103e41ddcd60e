"""Mistakes become Python exceptions with raylab's located messages; nothing aborts the interpreter."""
import os
import unittest

import raylab
from support import TempDir, scene_path, small


class Errors(unittest.TestCase):
    def test_scene_file_mistake_names_file_line_column_and_key(self):
        with TempDir() as tmp:
            path = os.path.join(tmp, "bad.json")
            with open(path, "w") as f:
                f.write('{\n  "render": { "spp": 0 }\n}\n')
            with self.assertRaises(raylab.SceneError) as caught:
                raylab.load(path)
        self.assertRegex(str(caught.exception), r"bad\.json:2:\d+: error: render\.spp: ")
        self.assertIsInstance(caught.exception, ValueError)

    def test_missing_file(self):
        with self.assertRaisesRegex(raylab.SceneError, r"nowhere\.json: error: cannot read"):
            raylab.load("nowhere.json")

    def test_unknown_key_in_set_suggests_the_closest(self):
        with self.assertRaisesRegex(raylab.SceneError, r"--set render\.spq=3: .*did you mean 'spp'"):
            raylab.load(scene_path("default.json"), set={"render.spq": 3})

    def test_edit_out_of_range_names_the_key_and_leaves_the_scene(self):
        scene = small("default.json")
        before = scene["materials.red.roughness"]
        with self.assertRaisesRegex(raylab.SceneError, r"^materials\.red\.roughness: must be in \[0, 1\], got 3"):
            scene["materials.red.roughness"] = 3
        self.assertEqual(scene["materials.red.roughness"], before)
        with self.assertRaisesRegex(raylab.SceneError, r"^materials\.red\.rougness: .*no key 'rougness'"):
            scene["materials.red.rougness"] = 0.5
        with self.assertRaisesRegex(raylab.SceneError, r"unknown key"):
            scene["camera.fovv"]
        with self.assertRaises(TypeError):
            scene["camera.fov"] = object()

    def test_render_arguments(self):
        scene = small("default.json")
        with self.assertRaisesRegex(raylab.SceneError, r"render\.spp"):
            raylab.render(scene, spp=0)
        with self.assertRaisesRegex(ValueError, r"tracer"):
            raylab.render(scene, spp=1, tracer="vulkan")
        with self.assertRaisesRegex(ValueError, r"unknown view 'normal'"):
            raylab.debug_view(scene, "normal")
        with self.assertRaisesRegex(ValueError, r"increasing"):
            list(raylab.progressive(scene, [4, 2]))
        with self.assertRaisesRegex(IndexError, r"outside the 32x18 image"):
            raylab.inspect(scene, 32, 0)

    def test_bsdf_material_mistakes(self):
        with self.assertRaisesRegex(raylab.SceneError, r"unknown key 'rougness'; did you mean 'roughness'"):
            raylab.bsdf.sample({"rougness": 0.5}, [0, 0, 1], 4)
        with self.assertRaisesRegex(raylab.SceneError, r"material\.ior: "):
            raylab.bsdf.pdf({"ior": -1}, [0, 0, 1], [[0, 0, 1]])
        with self.assertRaisesRegex(ValueError, r"wo: not a direction"):
            raylab.bsdf.eval({}, [0, 0, 0], [[0, 0, 1]])

    def test_unreadable_image_and_bad_array(self):
        with self.assertRaises(Exception) as caught:
            raylab.read_image("missing.exr")
        self.assertIn("missing.exr", str(caught.exception))
        with self.assertRaisesRegex(ValueError, r"shape \(height, width, 3 or 4\)"):
            raylab.rmse([1, 2, 3], [1, 2, 3])

    def test_the_module_still_renders_after_errors(self):
        self.assertEqual(raylab.render(small("default.json", 8, 8), spp=1).shape, (8, 8, 4))


if __name__ == "__main__":
    unittest.main()
