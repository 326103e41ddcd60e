// OpenGL 4.5 core through OSMesa (Mesa's off-screen renderer; llvmpipe on this machine).
#include "gl/gl_context.h"

#include <glad/gl.h>
#include <GL/osmesa.h>

#include <stdexcept>
#include <vector>

namespace raylab {
namespace {

class OSMesaGlContext final : public GlContext {
public:
    OSMesaGlContext() {
        const int attribs[] = {OSMESA_FORMAT,        OSMESA_RGBA,
                               OSMESA_DEPTH_BITS,    0,
                               OSMESA_PROFILE,       OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION, 4,
                               OSMESA_CONTEXT_MINOR_VERSION, 5,
                               0};
        context_ = OSMesaCreateContextAttribs(attribs, nullptr);
        if (!context_) throw std::runtime_error("OSMesaCreateContextAttribs failed (no GL 4.5 core)");
        // The renderer draws into its own framebuffer objects; OSMesa still wants a bound buffer.
        makeCurrent();
        if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress))) {
            OSMesaDestroyContext(context_);
            throw std::runtime_error("glad could not load GL 4.5 entry points through OSMesa");
        }
    }
    ~OSMesaGlContext() override { OSMesaDestroyContext(context_); }

    std::string description() const override { return "osmesa | " + currentGlDescription(); }

    void makeCurrent() override {
        if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1))
            throw std::runtime_error("OSMesaMakeCurrent failed");
    }

private:
    ::OSMesaContext context_ = nullptr;
    std::vector<unsigned char> buffer_ = std::vector<unsigned char>(4);
};

} // namespace

std::unique_ptr<GlContext> createOSMesaContext() { return std::make_unique<OSMesaGlContext>(); }

} // namespace raylab
