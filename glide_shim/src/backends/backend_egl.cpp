// EGL surfaceless backend (Mesa's EGL_PLATFORM_SURFACELESS_MESA): the alternative for Mesa
// 25.1 and later, which dropped OSMesa. Loads libEGL at run time; no surface is ever created.
#include "backends/backend.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>

namespace glide_shim {
namespace {

class EglBackend final : public Backend {
 public:
  ~EglBackend() override {
    if (display_ != EGL_NO_DISPLAY) {
      make_current_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      if (context_ != EGL_NO_CONTEXT) destroy_context_(display_, context_);
      terminate_(display_);
    }
    if (library_ != nullptr) dlclose(library_);
  }
  const char *name() const override { return "egl"; }
  void *proc_address(const char *function) const override {
    return reinterpret_cast<void *>(get_proc_(function));
  }

  bool open(std::string &error) {
    // RTLD_NODELETE: the driver (Mesa and its LLVM) stays mapped after dlclose, so reopening a
    // window does not load it again, and LeakSanitizer can still name the allocations the
    // driver keeps (cmake/lsan.supp) instead of reporting frames in an unloaded module.
    library_ = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    if (library_ == nullptr) {
      error = std::string("cannot load libEGL.so.1 (install libegl1 libegl-mesa0): ") + dlerror();
      return false;
    }
    get_proc_ =
        reinterpret_cast<decltype(&eglGetProcAddress)>(dlsym(library_, "eglGetProcAddress"));
    auto get_proc = get_proc_;
    if (get_proc == nullptr) {
      error = "libEGL.so.1 has no eglGetProcAddress";
      return false;
    }
    auto lookup = [&](const char *fn) { return reinterpret_cast<void *>(get_proc(fn)); };
    auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(lookup("eglGetPlatformDisplayEXT"));
    auto initialize = reinterpret_cast<decltype(&eglInitialize)>(lookup("eglInitialize"));
    auto bind_api = reinterpret_cast<decltype(&eglBindAPI)>(lookup("eglBindAPI"));
    auto choose_config =
        reinterpret_cast<decltype(&eglChooseConfig)>(lookup("eglChooseConfig"));
    auto create_context =
        reinterpret_cast<decltype(&eglCreateContext)>(lookup("eglCreateContext"));
    make_current_ = reinterpret_cast<decltype(&eglMakeCurrent)>(lookup("eglMakeCurrent"));
    destroy_context_ =
        reinterpret_cast<decltype(&eglDestroyContext)>(lookup("eglDestroyContext"));
    terminate_ = reinterpret_cast<decltype(&eglTerminate)>(lookup("eglTerminate"));
    if (get_platform_display == nullptr || initialize == nullptr || bind_api == nullptr ||
        choose_config == nullptr || create_context == nullptr || make_current_ == nullptr ||
        destroy_context_ == nullptr || terminate_ == nullptr) {
      error = "libEGL lacks EGL 1.4 entry points or EGL_EXT_platform_base";
      return false;
    }
    display_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display_ == EGL_NO_DISPLAY || !initialize(display_, nullptr, nullptr)) {
      display_ = EGL_NO_DISPLAY;
      error = "EGL surfaceless platform unavailable (install libegl-mesa0 libgl1-mesa-dri)";
      return false;
    }
    if (!bind_api(EGL_OPENGL_API)) {
      error = "EGL cannot bind desktop OpenGL";
      return false;
    }
    const EGLint config_attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                        EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!choose_config(display_, config_attributes, &config, 1, &count) || count < 1) {
      error = "EGL has no OpenGL config";
      return false;
    }
    const EGLint context_attributes[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
    context_ = create_context(display_, config, EGL_NO_CONTEXT, context_attributes);
    if (context_ == EGL_NO_CONTEXT) {
      error = "eglCreateContext failed for a compatibility profile";
      return false;
    }
    if (!make_current_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      error = "eglMakeCurrent without a surface failed (EGL_KHR_surfaceless_context missing?)";
      return false;
    }
    std::string missing = gl.load(lookup);
    if (!missing.empty()) {
      error = "EGL has no " + missing;
      return false;
    }
    return true;
  }

 private:
  void *library_ = nullptr;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  decltype(&eglMakeCurrent) make_current_ = nullptr;
  decltype(&eglDestroyContext) destroy_context_ = nullptr;
  decltype(&eglTerminate) terminate_ = nullptr;
  decltype(&eglGetProcAddress) get_proc_ = nullptr;
};

}  // namespace

std::unique_ptr<Backend> create_egl_backend(std::string &error) {
  auto backend = std::make_unique<EglBackend>();
  if (!backend->open(error)) return nullptr;
  return backend;
}

}  // namespace glide_shim
