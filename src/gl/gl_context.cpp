#include "gl/gl_context.h"

#include <glad/gl.h>

#include <stdexcept>

namespace raylab {

GlBackend parseGlBackend(std::string_view name) {
    if (name == "auto") return GlBackend::Auto;
    if (name == "osmesa") return GlBackend::OSMesa;
    if (name == "egl") return GlBackend::Egl;
    throw std::invalid_argument("unknown GL backend '" + std::string(name) +
                                "' (expected auto, osmesa or egl)");
}

std::string currentGlDescription() {
    auto str = [](GLenum e) {
        const auto* s = reinterpret_cast<const char*>(glGetString(e));
        return std::string(s ? s : "?");
    };
    return str(GL_RENDERER) + " | " + str(GL_VERSION);
}

} // namespace raylab
