"""raylab.bsdf: the GLSL sampler's directions follow the density pdf() gives (χ², α = 0.01, fixed
seeds), and eval/pdf are the tracer's."""
import math
import unittest

import numpy as np

import raylab

MATERIALS = {
    "lambert": {"albedo": 0.7},
    "rough plastic": {"albedo": [0.6, 0.2, 0.2], "f0": 0.04, "roughness": 0.5},
    "glossy metal": {"albedo": 0, "f0": [0.95, 0.64, 0.54], "roughness": 0.3},
    "rough glass": {"transmission": 1, "ior": 1.5, "roughness": 0.4},
}
WO = [0.4, 0.1, 0.9]


class Bsdf(unittest.TestCase):
    def test_samplers_pass_chi_square(self):
        for name, material in MATERIALS.items():
            with self.subTest(material=name):
                result = raylab.bsdf.chi2(material, WO, n=200000, seed=7)
                self.assertTrue(result["passed"], f"{name}: p = {result['p_value']:.3g}")
                self.assertEqual(result["alpha"], 0.01)

    def test_chi_square_of_own_directions_tells_a_right_sampler_from_a_wrong_one(self):
        rng = np.random.default_rng(11)
        u1, u2 = rng.random(100000), rng.random(100000)
        phi = 2 * np.pi * u2
        # Cosine-weighted (Malley's method) matches Lambert's density; uniform over the hemisphere does not.
        r = np.sqrt(u1)
        cosine = np.stack([r * np.cos(phi), r * np.sin(phi), np.sqrt(1 - u1)], axis=1)
        uniform = np.stack([np.sqrt(1 - u1 ** 2) * np.cos(phi), np.sqrt(1 - u1 ** 2) * np.sin(phi), u1], axis=1)
        lambert = {"albedo": 0.5}
        right = raylab.bsdf.chi2(lambert, [0, 0, 1], wi=cosine)
        wrong = raylab.bsdf.chi2(lambert, [0, 0, 1], wi=uniform)
        self.assertTrue(right["passed"], f"cosine: p = {right['p_value']:.3g}")
        self.assertFalse(wrong["passed"], f"uniform: p = {wrong['p_value']:.3g}")
        self.assertLess(wrong["p_value"], 1e-6)

    def test_sample_weight_is_eval_over_pdf(self):
        for name, material in MATERIALS.items():
            s = raylab.bsdf.sample(material, WO, 2000, seed=3)
            ok = ~s["delta"] & (s["lobe"] > 0)
            f = raylab.bsdf.eval(material, WO, s["wi"][ok])
            p = raylab.bsdf.pdf(material, WO, s["wi"][ok])
            np.testing.assert_allclose(p, s["pdf"][ok], rtol=2e-3, err_msg=name)
            np.testing.assert_allclose(f / p[:, None], s["weight"][ok], rtol=2e-3, atol=1e-6, err_msg=name)

    def test_lambert_is_albedo_over_pi_times_cosine(self):
        wi = np.array([[0, 0, 1], [0.6, 0, 0.8], [0, 0, -1]], dtype=float)
        f = raylab.bsdf.eval({"albedo": 0.5}, [0, 0, 1], wi)
        np.testing.assert_allclose(f[:, 0], [0.5 / math.pi, 0.5 / math.pi * 0.8, 0.0], rtol=1e-6)
        np.testing.assert_allclose(raylab.bsdf.pdf({"albedo": 0.5}, [0, 0, 1], wi), [1 / math.pi, 0.8 / math.pi, 0],
                                   rtol=1e-6)

    def test_metallic_is_applied_as_the_tracer_does(self):
        # metallic 1: f0 becomes the base colour and the diffuse lobe vanishes (gpu_scene.cpp bakes it so)
        metal = raylab.bsdf.eval({"albedo": [0.9, 0.5, 0.1], "metallic": 1, "roughness": 0.4}, [0, 0, 1], [[0, 0, 1]])
        coated = raylab.bsdf.eval({"albedo": 0, "f0": [0.9, 0.5, 0.1], "roughness": 0.4}, [0, 0, 1], [[0, 0, 1]])
        np.testing.assert_allclose(metal, coated, rtol=1e-6)

    def test_material_fills_defaults(self):
        m = raylab.bsdf.material({"roughness": 0.5})
        self.assertAlmostEqual(m["roughness"], 0.5)
        self.assertEqual(m["ior"], 1.5)
        self.assertIn("none", raylab.bsdf.lobe_names())


if __name__ == "__main__":
    unittest.main()
