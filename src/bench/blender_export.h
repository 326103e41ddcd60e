#pragma once
// Writes a Blender (3.4, Cycles) Python script that rebuilds a raylab scene with matched settings:
// spheres (finely tessellated) and triangle meshes (custom normals when given) placed by their
// transforms, uvs and per-triangle (glTF) materials; the f0 material model as Lambert·(1−F at the
// view angle) + a Principled GGX lobe with Fresnel at the half vector, mixed with a Glass BSDF by
// transmission, plus Emission, every texture slot through Image Texture nodes (the mapping and
// its known mismatches are commented in the script's material()); constant / gradient / map skies
// → World; the same camera, thin lens included (aperture → f-stop); box pixel filter, bounces, no
// denoising, no clamping, no adaptive sampling unless asked.
//   blender --python scene.py                     opens the scene in Blender
//   blender -b --factory-startup --python scene.py -- --samples 64 --output out.exr --threads 2
// renders headless and prints "RAYLAB_RENDER_SECONDS <s>" (the time of the render call alone);
// "--seed N" sets Cycles' seed, "--adaptive-threshold T" turns adaptive sampling on at noise
// threshold T (0: Cycles sets it from the sample count).
// raylab is y-up, Blender z-up: (x, y, z) → (x, −z, y), a rotation, so handedness is kept.
#include "scene/scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

// embeddedDir: where writeBlenderScript puts the images decoded from glTF files (the script names
// them there); scene-file images are named by absolute path, resolved as the loader does.
std::string blenderScript(const Scene& scene, const std::filesystem::path& embeddedDir = "blender_textures");

// The script without its driver (the headless run's arguments and render call, at its end): what
// a cached Cycles reference is keyed by, so changing how runs are driven keeps the references.
std::string blenderSceneText(std::string script);

// How the script names texture `index` of the scene.
struct BlenderTexture {
    std::filesystem::path path;   // absolute
    std::string colourSpace;      // Blender's: "sRGB", "Linear" (float colour files) or "Non-Color" (data)
    bool embedded = false;        // decoded from a glTF file; writeBlenderScript writes it as EXR
};
BlenderTexture blenderTexture(const Scene& scene, const std::filesystem::path& embeddedDir, int index);

// Where the exported scene can only approximate raylab's (beyond sphere tessellation), in words,
// one entry per kind: Fresnel-weighted GGX (another Fresnel curve), textures (filtering), normal
// maps (tangents). Empty: Lambert, F = 1 GGX, glass and emission only, which map exactly. The
// benchmark prints it beside the measured difference of the two renderers' references.
std::vector<std::string> blenderExportApproximations(const Scene& scene);

// Writes blenderScript(scene) atomically, and the images decoded from glTF files into
// PATH_STEM_textures/ beside it; throws std::runtime_error naming the path on failure.
void writeBlenderScript(const Scene& scene, const std::filesystem::path& path);

} // namespace raylab
