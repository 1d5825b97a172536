// OSMesa backend: loads libOSMesa at run time and makes a 1x1 compatibility context current.
// The window surface is never drawn to; the shim renders into its own 565 framebuffer objects.
#include "backends/backend.h"

#include <GL/osmesa.h>
#include <dlfcn.h>

namespace glide_shim {
namespace {

class OSMesaBackend final : public Backend {
 public:
  ~OSMesaBackend() override {
    if (context_ != nullptr) destroy_(context_);
    if (library_ != nullptr) dlclose(library_);
  }
  const char *name() const override { return "osmesa"; }
  void *proc_address(const char *function) const override {
    return reinterpret_cast<void *>(get_proc_(function));
  }

  bool open(std::string &error) {
    // RTLD_NODELETE: the driver (Mesa and its LLVM) stays mapped after dlclose, so reopening a
    // window does not load it again, and LeakSanitizer can still name the allocations the
    // driver keeps (cmake/lsan.supp) instead of reporting frames in an unloaded module.
    library_ = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    if (library_ == nullptr) {
      error = std::string("cannot load libOSMesa.so.8 (install libosmesa6): ") + dlerror();
      return false;
    }
    auto create = reinterpret_cast<decltype(&OSMesaCreateContextExt)>(
        dlsym(library_, "OSMesaCreateContextExt"));
    auto make_current =
        reinterpret_cast<decltype(&OSMesaMakeCurrent)>(dlsym(library_, "OSMesaMakeCurrent"));
    destroy_ = reinterpret_cast<decltype(&OSMesaDestroyContext)>(
        dlsym(library_, "OSMesaDestroyContext"));
    get_proc_ = reinterpret_cast<decltype(&OSMesaGetProcAddress)>(
        dlsym(library_, "OSMesaGetProcAddress"));
    auto get_proc = get_proc_;
    if (create == nullptr || make_current == nullptr || destroy_ == nullptr ||
        get_proc == nullptr) {
      error = "libOSMesa.so.8 lacks the OSMesa entry points";
      return false;
    }
    context_ = create(OSMESA_RGBA, 0, 0, 0, nullptr);
    if (context_ == nullptr) {
      error = "OSMesaCreateContextExt failed";
      return false;
    }
    if (!make_current(context_, surface_, GL_UNSIGNED_BYTE, 1, 1)) {
      error = "OSMesaMakeCurrent failed";
      return false;
    }
    std::string missing = gl.load([&](const char *fn) {
      return reinterpret_cast<void *>(get_proc(fn));
    });
    if (!missing.empty()) {
      error = "OSMesa has no " + missing;
      return false;
    }
    return true;
  }

 private:
  void *library_ = nullptr;
  OSMesaContext context_ = nullptr;
  decltype(&OSMesaDestroyContext) destroy_ = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc_ = nullptr;
  unsigned char surface_[4] = {};
};

}  // namespace

std::unique_ptr<Backend> create_osmesa_backend(std::string &error) {
  auto backend = std::make_unique<OSMesaBackend>();
  if (!backend->open(error)) return nullptr;
  return backend;
}

}  // namespace glide_shim
