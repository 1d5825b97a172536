// The PNG writer module (libglide2x_png.so): 8-bit RGB rows to a PNG through OpenImageIO. It is
// a separate module so that libglide2x itself does not depend on OpenImageIO; frame_export.cpp
// loads it the first time a frame is written.
#include <OpenImageIO/imageio.h>

#include <cstring>
#include <memory>
#include <string>

extern "C" __attribute__((visibility("default"))) int glideshim_write_png(
    const char *path, int width, int height, const unsigned char *rgb, char *error,
    unsigned error_size) {
  auto fail = [&](const std::string &message) {
    std::strncpy(error, message.c_str(), error_size - 1);
    error[error_size - 1] = '\0';
    return 0;
  };
  // PNG whatever the name says: OpenImageIO would choose the format by the extension, and a path
  // without one (/dev/stdout, /dev/null, a name a script chose) would have no writer.
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create("png");
  if (!out) return fail(std::string("cannot write '") + path + "': " + OIIO::geterror());
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  // Level 6 keeps files small without making a frame dump the slowest part of a frame.
  spec.attribute("png:compressionLevel", 6);
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::UINT8, rgb) || !out->close()) {
    return fail(std::string("cannot write '") + path + "': " + out->geterror());
  }
  return 1;
}
