#pragma once
// A current OpenGL 4.5 core context with no window, behind one interface so the renderer does not
// care where it came from: OSMesa (llvmpipe, CPU) today; EGL (surfaceless Mesa, or a GPU device)
// because Mesa 25.1 removed OSMesa and GPU benchmarks want a real driver.
#include <memory>
#include <string>
#include <string_view>

namespace raylab {

class GlContext {
public:
    virtual ~GlContext() = default;
    GlContext() = default;
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    // Backend name ("osmesa", "egl-surfaceless", "egl-device"), GL_RENDERER and GL_VERSION.
    virtual std::string description() const = 0;
    virtual void makeCurrent() = 0;
};

enum class GlBackend { Auto, OSMesa, Egl };

// Parses "auto", "osmesa" or "egl"; throws std::invalid_argument on anything else.
GlBackend parseGlBackend(std::string_view name);

// Creates a context, makes it current and loads GL entry points with glad. Auto tries EGL on a GPU
// device first when RAYLAB_GL=egl is set, otherwise OSMesa then EGL. Throws std::runtime_error with
// the reason when no context can be made.
std::unique_ptr<GlContext> createHeadlessContext(GlBackend backend = GlBackend::Auto);

// Implementations; each throws std::runtime_error when unavailable.
std::unique_ptr<GlContext> createOSMesaContext();
std::unique_ptr<GlContext> createEglContext();

// "renderer | version" of the current context.
std::string currentGlDescription();

} // namespace raylab
