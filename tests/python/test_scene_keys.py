"""Scene keys read and write through the resolver of --set, with its checks."""
import os
import unittest

import raylab
from support import TempDir, scene_path, small


class SceneKeys(unittest.TestCase):
    def test_load_with_set_equals_setting_keys_after(self):
        a = raylab.load(scene_path("default.json"), set={"render.spp": 12, "materials.red.albedo": [1, 0, 0],
                                                          "render.tone_map": "reinhard"})
        self.assertEqual(a["render.spp"], 12)
        self.assertEqual(a["materials.red.albedo"], (1.0, 0.0, 0.0))
        self.assertEqual(a["render.tone_map"], "reinhard")
        b = raylab.load(scene_path("default.json"))
        b["render.spp"] = 12
        b["materials.red.albedo"] = [1, 0, 0]
        b["render.tone_map"] = "reinhard"
        self.assertEqual(a.to_json(), b.to_json())

    def test_types(self):
        s = small("default.json")
        self.assertIsInstance(s["render.nee"], bool)
        self.assertIsInstance(s["render.spp"], int)
        self.assertIsInstance(s["camera.fov"], float)
        self.assertEqual(s["render.sampler"], "sobol")
        self.assertEqual(len(s["camera.position"]), 3)
        self.assertIn("materials.red.albedo", s.keys())
        self.assertIn("objects.0.radius", s)
        self.assertNotIn("objects.99.radius", s)
        self.assertEqual(s.size, (32, 18))

    def test_file_keys_read_as_written(self):
        s = raylab.load(scene_path("environment.json"))
        self.assertTrue(str(s["sky.map"]).endswith(".hdr"))

    def test_copy_is_independent(self):
        s = small("default.json")
        c = s.copy()
        c["camera.fov"] = 50
        self.assertNotEqual(s["camera.fov"], 50.0)

    def test_save_loads_back(self):
        s = small("default.json")
        s["materials.blue.roughness"] = 0.25
        with TempDir() as tmp:
            path = os.path.join(tmp, "saved.json")
            s.save(path)
            back = raylab.load(path)
        self.assertAlmostEqual(back["materials.blue.roughness"], 0.25, places=6)

    def test_parse_text(self):
        text = '{"render": {"width": 8, "height": 4}, "objects": [{"type": "sphere", "radius": 1}]}'
        s = raylab.parse(text, name="inline.json")
        self.assertEqual(s.size, (8, 4))
        self.assertEqual(raylab.render(s, spp=1).shape, (4, 8, 4))
        with self.assertRaisesRegex(raylab.SceneError, r"inline\.json:1:"):
            raylab.parse('{"render": {"width": -1}}', name="inline.json")


if __name__ == "__main__":
    unittest.main()
