#pragma once
// Runs one slot function of the code track, compiled from a pupil's file, on a table of inputs on
// the current GL context (shaders/entry/exercise_probe.comp), so the checks compare what it
// returns with double precision. Needs a current GL 4.5 context.
#include "gl/shader_program.h"

#include <glm/glm.hpp>

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

// The probe's modes, one per slot (exercise_probe.comp's uMode).
enum class ProbeMode {
    Sphere = 0,      // in: (origin, tMin), (dir, tMax), (center, radius); out a.x = t
    Triangle = 1,    // in: (origin, tMax), dir, p0, p1, p2; out a = (hit, t, b1, b2)
    Box = 2,         // in: (origin, tMax), invDir, boxMin, boxMax; out a.x = entry t
    Hemisphere = 3,  // in: (u, cosθ); out a = (direction, its pdf), b.x = pdf(cosθ)
    Lambert = 4,     // in: albedo, wo, wi; out a.xyz = f
    GgxD = 5,        // in: (h, α); out a.x = D
    SmithG = 6,      // in: (wo, α), wi; out a.x = G1(wo), a.y = G2(wo, wi)
    Schlick = 7,     // in: (f0, f90), wo, wi; out a.xyz = F
    ThinLens = 8,    // in: (origin, tanHalfFovY), (right, aspect), (up, lensRadius), (forward, focusDistance),
                     // (ndc, lensSample); out a.xyz = ray origin, b.xyz = ray direction
    RunningMean = 9, // in: (mean, count as uint bits), (sum, newCount as uint bits); out a.xyz
};

struct ProbeInput {
    std::array<glm::vec4, 6> v{};
};
struct ProbeOutput {
    glm::vec4 a{0.0f};
    glm::vec4 b{0.0f};
};

class ExerciseProbe {
public:
    // Compiles the probe with `pupilFile` in the slot `slotDefine`; throws ShaderError whose text
    // names the pupil's file:line on a compile error.
    ExerciseProbe(const std::string& slotDefine, const std::filesystem::path& pupilFile);
    std::vector<ProbeOutput> run(ProbeMode mode, const std::vector<ProbeInput>& inputs) const;

private:
    ShaderProgram program_;
};

} // namespace raylab
