"""What the Python tests share: the repository, raylab-render, and small versions of shipped scenes."""
import os
import subprocess
import tempfile

import raylab

ROOT = os.environ.get("RAYLAB_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))
RENDER = os.environ.get("RAYLAB_RENDER", os.path.join(ROOT, "build", "raylab-render"))


def scene_path(name):
    return os.path.join(ROOT, "scenes", name)


def small(name, width=32, height=18, **keys):
    """A shipped scene at a small size (keys: more overrides, dots as in FORMAT.md)."""
    overrides = {"render.width": width, "render.height": height}
    overrides.update(keys)
    return raylab.load(scene_path(name), set=overrides)


def run_render(*args):
    """raylab-render with args; returns (exit status, stdout, stderr)."""
    done = subprocess.run([RENDER, "-q", *args], capture_output=True, text=True, timeout=600)
    return done.returncode, done.stdout, done.stderr


class TempDir:
    def __enter__(self):
        self._dir = tempfile.TemporaryDirectory(prefix="raylab-python-test-")
        return self._dir.name

    def __exit__(self, *exc):
        self._dir.cleanup()
