// Loading the image files module (image_files.h) on first use, once per process.
#include "media/image_files.h"

#include <dlfcn.h>

#include <cstdlib>

namespace gs::media {

const ImageFiles *image_files(std::string &error) {
  static std::string load_error;
  static const ImageFiles *const files = []() -> const ImageFiles * {
    const char *chosen = std::getenv("GLIDESHADOWS_IMAGE_FILES");
    const std::string path =
        chosen != nullptr && *chosen != '\0' ? chosen : GLIDESHADOWS_IMAGE_FILES_MODULE;
    void *module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (module == nullptr) {
      const char *why = dlerror();
      load_error = "cannot load the image files module " + path + " (" +
                   (why != nullptr ? why : "no reason given") + ")";
      return nullptr;
    }
    using Entry = const ImageFiles *(*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(module, "glideshadows_image_files"));
    if (entry == nullptr) {
      load_error = "the image files module " + path + " has no glideshadows_image_files";
      return nullptr;
    }
    return entry();
  }();
  if (files == nullptr) error = load_error;
  return files;
}

}  // namespace gs::media
