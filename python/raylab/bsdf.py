"""The tracer's BSDF in the local frame (+z the shading normal), for histograms and χ² in a notebook.

sample() runs the real GLSL sampling code on raylab's GL context (the harness of the self-test and
the BRDF explorer); eval() and pdf() run the same GLSL source compiled as C++. A material is a dict
of the material keys of scenes/FORMAT.md (albedo, roughness, f0, metallic, transmission, ior, ...);
scene.to_json()["materials"]["red"] gives a scene's own, material() fills in the defaults.
"""
from ._raylab import bsdf as _bsdf

sample = _bsdf.sample
eval = _bsdf.eval  # noqa: A001  (the BSDF's eval, as in pbrt and Mitsuba)
pdf = _bsdf.pdf
chi2 = _bsdf.chi2
material = _bsdf.material
lobe_names = _bsdf.lobe_names

__all__ = ["sample", "eval", "pdf", "chi2", "material", "lobe_names"]
