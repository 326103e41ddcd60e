#include "gl/gl_context.h"

#include <glad/gl.h>

#include <cstdlib>
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

std::unique_ptr<GlContext> createHeadlessContext(GlBackend backend) {
    if (backend == GlBackend::Auto) {
        if (const char* env = std::getenv("RAYLAB_GL"); env && *env) backend = parseGlBackend(env);
    }
    switch (backend) {
    case GlBackend::OSMesa: return createOSMesaContext();
    case GlBackend::Egl: return createEglContext();
    case GlBackend::Auto: break;
    }
    std::string errors;
    try {
        return createOSMesaContext();
    } catch (const std::exception& e) {
        errors += std::string("osmesa: ") + e.what();
    }
    try {
        return createEglContext();
    } catch (const std::exception& e) {
        errors += std::string("; egl: ") + e.what();
    }
    throw std::runtime_error("no OpenGL 4.5 context: " + errors);
}

#ifndef RAYLAB_HAVE_EGL
std::unique_ptr<GlContext> createEglContext() {
    throw std::runtime_error("raylab was built without EGL (install libegl-dev and rebuild)");
}
#endif

} // namespace raylab
