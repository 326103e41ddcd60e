#pragma once
// Writes a Blender (3.4, Cycles) Python script that rebuilds a raylab scene with matched settings:
// spheres (finely tessellated) and triangle meshes (custom normals when given) placed by their
// transforms; the f0 material model as Diffuse(albedo·(1−F)) + Glossy GGX(F) with Schlick F built
// from nodes, mixed with a Glass BSDF by transmission, plus Emission (the mapping and its known
// mismatches are commented in the script's material()); constant / gradient / map skies → World;
// the same camera, thin lens included (aperture → f-stop); box pixel filter, bounces, no
// denoising, no clamping, no adaptive sampling. A scalar metallic becomes its f0/albedo mix. Not
// exported: textures (any kind) and per-triangle (glTF) materials (a glTF mesh takes its object's).
//   blender --python scene.py                     opens the scene in Blender
//   blender -b --factory-startup --python scene.py -- --samples 64 --output out.exr --threads 2
// renders headless and prints "RAYLAB_RENDER_SECONDS <s>" (the time of the render call alone).
// raylab is y-up, Blender z-up: (x, y, z) → (x, −z, y), a rotation, so handedness is kept.
#include "scene/scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

std::string blenderScript(const Scene& scene);

// Where the exported scene can only approximate raylab's (beyond sphere tessellation), in words,
// one entry per kind: Fresnel-weighted layers (plastics, coloured metals: Blender takes F at the
// view angle, raylab at the half vector), textures, per-triangle materials. Empty: Lambert, F = 1
// GGX, glass and emission only, which map exactly. The benchmark prints it beside the difference
// of the two renderers' references.
std::vector<std::string> blenderExportApproximations(const Scene& scene);

// Writes blenderScript(scene) atomically; throws std::runtime_error naming the path on failure.
void writeBlenderScript(const Scene& scene, const std::filesystem::path& path);

} // namespace raylab
