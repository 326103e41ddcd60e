"""raylab from Python: load scenes, render them, inspect paths and sample the tracer's BSDF.

The renderer is raylab's own (the C++ and GLSL that raylab-render runs), on the same headless
OpenGL 4.5 context: OSMesa or EGL, chosen as for raylab-render (the RAYLAB_GL environment
variable: auto, osmesa or egl). Images are float32 numpy arrays of shape (height, width, 4),
linear, top row first. Renders run on raylab's GL thread with the GIL released; mistakes in
scenes and keys raise SceneError with raylab-render's located message.

    import raylab
    scene = raylab.load("scenes/default.json", set={"render.spp": 64})
    scene["materials.red.roughness"] = 0.3
    img = raylab.render(scene, spp=16, seed=1)
    img.meta["seconds"], img.shape
"""
from __future__ import annotations

import atexit
import os

# An installed package carries the shaders (cmake --install); in the build tree the tracer finds
# them in the source tree.
_SHADERS = os.path.join(os.path.dirname(__file__), "shaders")
if not os.environ.get("RAYLAB_SHADER_DIR") and os.path.isdir(os.path.join(_SHADERS, "entry")):
    os.environ["RAYLAB_SHADER_DIR"] = _SHADERS
from typing import Any, Iterable, Iterator, Optional

import numpy as np

from . import _raylab
from ._raylab import (  # noqa: F401  (re-exported)
    RenderError,
    Scene,
    SceneError,
    debug_views,
    error,
    export_blender,
    gl_info,
    inspect,
    load,
    mean,
    parse,
    rmse,
    write_image,
)
from . import bsdf  # noqa: F401

__all__ = [
    "Image", "RenderError", "Scene", "SceneError", "bsdf", "debug_view", "debug_views", "error",
    "export_blender", "gl_info", "inspect", "load", "mean", "parse", "progressive", "read_image",
    "reference", "render", "rmse", "write_image",
]

atexit.register(_raylab._shutdown)


class Image(np.ndarray):
    """A float32 (height, width, 4) array with the render's metadata in .meta (a dict)."""

    meta: dict

    def __new__(cls, array: np.ndarray, meta: Optional[dict] = None) -> "Image":
        obj = np.asarray(array).view(cls)
        obj.meta = dict(meta or {})
        return obj

    def __array_finalize__(self, obj: Any) -> None:
        self.meta = getattr(obj, "meta", {})


def _image(result: tuple) -> Image:
    array, meta = result
    return Image(array, meta)


def render(scene: Scene, spp: Optional[int] = None, seed: Optional[int] = None,
           time: Optional[float] = None, rpp: Optional[int] = None, tracer: str = "fragment") -> Image:
    """Renders the scene as raylab-render does and returns the linear image.

    spp, seed, time (seconds, 0 = no limit) and rpp override render.spp, render.seed, render.time
    and render.rpp for this call only. For the same scene and seed the array equals raylab-render's
    EXR bit for bit. .meta holds spp, seconds (tracing only), non_finite (NaN/Inf samples replaced
    by 0), variant (the compiled shader variant), sampler, seed, rpp, passes, rays and the GL context.
    """
    return _image(_raylab._render(scene, spp=spp, seed=seed, time=time, rpp=rpp, tracer=tracer))


def progressive(scene: Scene, checkpoints: Iterable[int] = (1, 2, 4, 8, 16, 32, 64, 128, 256),
                seed: Optional[int] = None, rpp: Optional[int] = None,
                tracer: str = "fragment") -> Iterator[Image]:
    """Yields the image at each checkpoint (increasing sample counts) of one progressive render.

    The samples of earlier checkpoints are kept, so the whole series costs what its last image
    costs. The last checkpoint is the render's spp (the stratified sampler lays its strata out for
    it); .meta["seconds"] counts from the first sample.
    """
    state = _raylab._Progressive(scene, list(checkpoints), seed=seed, rpp=rpp, tracer=tracer)
    while True:
        try:
            result = state.next()
        except StopIteration:
            return
        yield _image(result)


def debug_view(scene: Scene, view: str, spp: Optional[int] = None, seed: Optional[int] = None,
               bounce: int = 1, tracer: str = "fragment") -> Image:
    """Traces one of the viewer's debug views (debug_views() lists them) as raw per-pixel means,
    as raylab-render --debug-view does: normals, depth, albedo, the heat maps (R = box tests,
    G = triangle tests of the camera ray; .meta has the largest counts), a bounce's light, ...
    material-id and object-id hold one false colour per id, as the viewer shows them, not the id;
    .meta["legend"] says how the viewer reads each view."""
    return _image(_raylab._debug_view(scene, view, spp=spp, seed=seed, bounce=bounce, tracer=tracer))


def read_image(path: str) -> Image:
    """Reads an .exr or .png as linear float32 (height, width, 4); an EXR written by raylab-render
    brings its render metadata in .meta."""
    return _image(_raylab._read_image(path))


def reference(scene: Scene, spp: int = 1024, batches: int = 4,
              cache: Optional[str] = None) -> tuple[Image, Image]:
    """raylab-bench's reference: the mean of `batches` renders of `spp` samples (seeds 1000 + k)
    and the per-pixel variance of that mean. With `cache` (a path without extension) the pair is
    kept as EXR files and reused while the scene and settings are the same."""
    mean_, variance, meta = _raylab._reference(scene, spp=spp, batches=batches, cache=cache)
    return Image(mean_, meta), Image(variance, meta)
