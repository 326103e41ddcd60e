// OpenGL 4.5 core through EGL without a window: a GPU device when one is enumerable
// (EGL_EXT_platform_device), else Mesa's surfaceless platform (llvmpipe here).
#include "gl/gl_context.h"

#include <glad/gl.h>
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace raylab {
namespace {

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

class EglContext final : public GlContext {
public:
    EglContext() {
        const char* clientExts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
            eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!getPlatformDisplay) throw std::runtime_error("eglGetPlatformDisplayEXT missing");

        // Prefer a hardware device: the first one that is not Mesa's software device.
        if (hasExtension(clientExts, "EGL_EXT_platform_device")) {
            auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(
                eglGetProcAddress("eglQueryDevicesEXT"));
            auto queryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
                eglGetProcAddress("eglQueryDeviceStringEXT"));
            EGLDeviceEXT devices[16];
            EGLint count = 0;
            if (queryDevices && queryDevices(16, devices, &count)) {
                for (EGLint i = 0; i < count && display_ == EGL_NO_DISPLAY; ++i) {
                    const char* exts =
                        queryDeviceString ? queryDeviceString(devices[i], EGL_EXTENSIONS) : nullptr;
                    if (hasExtension(exts, "EGL_MESA_device_software")) continue;
                    display_ = tryInitialize(
                        getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr));
                    if (display_ != EGL_NO_DISPLAY) kind_ = "egl-device";
                }
            }
        }
        if (display_ == EGL_NO_DISPLAY && hasExtension(clientExts, "EGL_MESA_platform_surfaceless")) {
            display_ = tryInitialize(
                getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
            kind_ = "egl-surfaceless";
        }
        if (display_ == EGL_NO_DISPLAY) throw std::runtime_error("no usable EGL display");

        if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error("eglBindAPI(OpenGL) failed");
        const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
                                        EGL_PBUFFER_BIT, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint numConfigs = 0;
        eglChooseConfig(display_, configAttribs, &config, 1, &numConfigs);
        const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        context_ = eglCreateContext(display_, numConfigs > 0 ? config : EGL_NO_CONFIG_KHR,
                                    EGL_NO_CONTEXT, contextAttribs);
        if (context_ == EGL_NO_CONTEXT) {
            eglTerminate(display_);
            throw std::runtime_error("eglCreateContext failed (no GL 4.5 core)");
        }
        makeCurrent();
        if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress))) {
            eglDestroyContext(display_, context_);
            eglTerminate(display_);
            throw std::runtime_error("glad could not load GL 4.5 entry points through EGL");
        }
    }
    ~EglContext() override {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }

    std::string description() const override { return kind_ + " | " + currentGlDescription(); }

    void makeCurrent() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw std::runtime_error("eglMakeCurrent failed");
    }

private:
    static EGLDisplay tryInitialize(EGLDisplay display) {
        if (display == EGL_NO_DISPLAY) return EGL_NO_DISPLAY;
        EGLint major = 0, minor = 0;
        return eglInitialize(display, &major, &minor) ? display : EGL_NO_DISPLAY;
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    std::string kind_;
};

} // namespace

std::unique_ptr<GlContext> createEglContext() { return std::make_unique<EglContext>(); }

} // namespace raylab
