#include "inspect/light_names.h"

namespace raylab {

std::string lightName(Light::Type type, int index) {
    const std::string n = std::to_string(index);
    switch (type) {
    case Light::Type::Point: return "point light " + n;
    case Light::Type::Spot: return "spot " + n;
    case Light::Type::Distant: return "sun " + n;
    }
    return "light " + n;
}

bool isDeltaLight(const Light& light) { return light.type != Light::Type::Distant || !(light.angularRadius > 0.0f); }

const Light* sceneLight(const LightNumbering& numbering, int index) {
    const int i = index - numbering.spheres - numbering.triangles;
    if (index < 0 || i < 0 || i >= int(numbering.lights.size())) return nullptr;
    return &numbering.lights[std::size_t(i)];
}

std::string lightSampleName(const LightNumbering& numbering, int index) {
    if (index < 0) return "sky";
    if (index < numbering.spheres) return "sphere light " + std::to_string(index);
    if (index < numbering.spheres + numbering.triangles)
        return "triangle light " + std::to_string(index - numbering.spheres);
    if (const Light* l = sceneLight(numbering, index))
        return lightName(l->type, index - numbering.spheres - numbering.triangles);
    return "light " + std::to_string(index);
}

} // namespace raylab
