#include "inspect/path_record.h"

#include "shaders/include/bsdf_sample.glsl"

#include <iomanip>
#include <sstream>

namespace raylab {

std::string lobeName(int lobe) {
    switch (lobe) {
    case glsl::LOBE_NONE: return "none";
    case glsl::LOBE_DIFFUSE: return "diffuse";
    case glsl::LOBE_SPECULAR: return "specular";
    case glsl::LOBE_GLASS_REFLECT: return "glass reflect";
    case glsl::LOBE_GLASS_TRANSMIT: return "glass transmit";
    default: return "-";
    }
}

std::string lightMisPdfText(const BounceRecord& b) {
    if (b.lightDelta) return "delta (never hit by BSDF rays)";
    std::ostringstream o;
    o << std::setprecision(4) << b.lightMisPdf;
    return o.str();
}

std::string lightStatusName(LightStatus s) {
    switch (s) {
    case LightStatus::Occluded: return "occluded";
    case LightStatus::Visible: return "visible";
    case LightStatus::Zero: return "f = 0";   // also L = 0; the name stays, as saved files hold it
    default: return "-";
    }
}

glm::dvec3 PathRecord::sumOfTerms() const {
    glm::dvec3 sum(0.0);
    for (const BounceRecord& b : bounces) {
        const glm::dvec3 beta(b.throughputBefore);
        if (b.emissionCounted) sum += beta * (glm::dvec3(b.emission) * double(b.emissionWeight) + glm::dvec3(b.stageAlbedo));
        if (b.lightCounted) sum += beta * glm::dvec3(b.lightContribution);
    }
    return sum;
}

} // namespace raylab
