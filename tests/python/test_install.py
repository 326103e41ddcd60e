"""cmake --install puts a package that works without the build tree's PYTHONPATH: the module, its
Python half, the type stubs and the shaders it compiles at run time."""
import os
import subprocess
import sys
import unittest

from support import ROOT, TempDir

BUILD = os.environ.get("RAYLAB_BUILD_DIR", os.path.join(ROOT, "build"))
CMAKE = os.environ.get("RAYLAB_CMAKE", "cmake")


class Install(unittest.TestCase):
    def test_installed_package_renders_with_its_own_shaders(self):
        with TempDir() as prefix:
            done = subprocess.run([CMAKE, "--install", BUILD, "--prefix", prefix], capture_output=True, text=True)
            self.assertEqual(done.returncode, 0, done.stderr)
            site = os.path.join(prefix, f"lib/python{sys.version_info.major}.{sys.version_info.minor}/dist-packages")
            package = os.path.join(site, "raylab")
            for name in ("__init__.py", "__init__.pyi", "bsdf.py", "bsdf.pyi", "py.typed", "shaders/entry"):
                self.assertTrue(os.path.exists(os.path.join(package, name)), name)
            env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "RAYLAB_SHADER_DIR")}
            env["PYTHONPATH"] = site
            code = ("import os, raylab; print(raylab.__file__); print(os.environ['RAYLAB_SHADER_DIR']); "
                    f"print(raylab.render(raylab.load({os.path.join(ROOT, 'scenes', 'default.json')!r}, "
                    "set={'render.width': 8, 'render.height': 4}), spp=1).shape)")
            run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=prefix)
            self.assertEqual(run.returncode, 0, run.stderr)
            module, shaders, shape = run.stdout.split("\n")[:3]
            self.assertTrue(module.startswith(package), module)
            self.assertEqual(shaders, os.path.join(package, "shaders"))
            self.assertEqual(shape, "(4, 8, 4)")


if __name__ == "__main__":
    unittest.main()
