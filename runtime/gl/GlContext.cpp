#include "gl/GlContext.h"

#include <cstring>
#include <mutex>
#include <set>
#include <vector>

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include "gl/GlDebugOutput.h"

namespace rmfx {
namespace {

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

struct Candidate {
    EGLDisplay display;
    std::string name;
};

std::vector<Candidate> candidateDisplays(std::string& tried) {
    std::vector<Candidate> out;
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY) out.push_back({d, "EGL surfaceless"});
    } else {
        tried += " EGL_MESA_platform_surfaceless is not offered;";
    }
    if (hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (eglQueryDevicesEXT(8, devices, &count)) {
            for (EGLint i = 0; i < count; ++i) {
                EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (d != EGL_NO_DISPLAY) out.push_back({d, "EGL device " + std::to_string(i)});
            }
        }
    } else {
        tried += " EGL_EXT_platform_device is not offered;";
    }
    if (EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY); d != EGL_NO_DISPLAY) out.push_back({d, "EGL default display"});
    return out;
}

// Displays that have held a context of ours. A failed attempt terminates a display only if it is
// not one of them: eglTerminate is not counted (it ends the display however often it was
// initialised), so it would end the display under a living context (a compatibility-profile
// attempt failing beside the core context). Nor are they terminated when their last context goes:
// that unloads Mesa's driver, and what the driver never freed turns into leak reports at exit.
std::mutex displaysInUseMutex;
std::set<void*> displaysInUse;

void terminateIfUnused(EGLDisplay display) {
    std::lock_guard lock(displaysInUseMutex);
    if (!displaysInUse.contains(display)) eglTerminate(display);
}

}  // namespace

void GlContext::prepareHeadlessDisplay() {
    std::string tried;
    for (const Candidate& c : candidateDisplays(tried)) {
        EGLint major = 0, minor = 0;
        if (eglInitialize(c.display, &major, &minor)) return;
    }
}

Result<std::unique_ptr<GlContext>> GlContext::createHeadless(GlProfile profile) {
    std::string tried;
    const bool core = profile == GlProfile::Core;
    const char* profileName = core ? "core" : "compatibility";
    for (const Candidate& c : candidateDisplays(tried)) {
        EGLint major = 0, minor = 0;
        if (!eglInitialize(c.display, &major, &minor)) {
            tried += " " + c.name + ": eglInitialize failed;";
            continue;
        }
        if (!eglBindAPI(EGL_OPENGL_API)) {
            tried += " " + c.name + ": no desktop OpenGL;";
            terminateIfUnused(c.display);
            continue;
        }
        const bool debug = glDebugOutputAsked();
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     core ? EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT : EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                                     debug ? EGL_CONTEXT_OPENGL_DEBUG : EGL_NONE, EGL_TRUE, EGL_NONE};
        EGLConfig config = EGL_NO_CONFIG_KHR;
        bool noConfig = hasExtension(eglQueryString(c.display, EGL_EXTENSIONS), "EGL_KHR_no_config_context");
        if (!noConfig) {
            const EGLint configAttributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
            EGLint count = 0;
            if (!eglChooseConfig(c.display, configAttributes, &config, 1, &count) || count == 0) {
                tried += " " + c.name + ": no OpenGL config;";
                terminateIfUnused(c.display);
                continue;
            }
        }
        EGLContext context = eglCreateContext(c.display, config, EGL_NO_CONTEXT, attributes);
        if (context == EGL_NO_CONTEXT) {
            tried += " " + c.name + ": no OpenGL 4.5 " + profileName + " context (EGL error 0x" +
                     [] { char b[16]; std::snprintf(b, sizeof b, "%x", eglGetError()); return std::string(b); }() + ");";
            terminateIfUnused(c.display);
            continue;
        }
        if (!eglMakeCurrent(c.display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
            tried += " " + c.name + ": the context cannot be made current without a surface;";
            eglDestroyContext(c.display, context);
            terminateIfUnused(c.display);
            continue;
        }
        std::unique_ptr<GlContext> gl(new GlContext);
        {
            std::lock_guard lock(displaysInUseMutex);
            displaysInUse.insert(c.display);
        }
        gl->display_ = c.display;
        gl->context_ = context;
        gl->profile_ = profile;
        if (debug) installGlDebugOutput();
        std::string version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
        // Mesa names the profile in its version string ("4.5 (Compatibility Profile) Mesa"); NVIDIA does not.
        GLint mask = 0;
        glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
        if ((mask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT) && version.find("Compatibility") == std::string::npos)
            version += " (Compatibility Profile)";
        gl->description_ = version + ", " + reinterpret_cast<const char*>(glGetString(GL_RENDERER)) + " via " + c.name;
        return gl;
    }
    return Error{"cannot open an EGL display with an OpenGL 4.5 " + std::string(profileName) + " context:" + tried +
                 " (on a machine without a GPU, install Mesa's EGL and DRI drivers: libegl-mesa0 libgl1-mesa-dri)"};
}

GlContext::~GlContext() {
    if (display_) {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);  // the display stays initialised: see displaysInUse
    }
}

void GlContext::makeCurrent() { eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_); }

}  // namespace rmfx
