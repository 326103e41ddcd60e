// The headless context factory: OSMesa or EGL (raylab_headless library, not the viewer).
#include "gl/gl_context.h"

#include <cstdlib>
#include <stdexcept>

namespace raylab {

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
