// Error reporting: every rejected call records one error kind with a message naming the problem,
// keeps it as the last error, and hands it once to the program's grErrorSetCallback callback.
#include "context.h"

namespace glide_shim_api {  // exported through entry_points.cpp (exception barrier)

void grErrorSetCallback(GrErrorCallbackFnc_t function) {
  glide_shim::current().errors.callback = function;
}

GlideShimError glideShimGetLastError(void) { return glide_shim::current().errors.last; }

const char *glideShimGetLastErrorMessage(void) {
  return glide_shim::current().errors.message.c_str();
}

void glideShimClearError(void) {
  auto &errors = glide_shim::current().errors;
  errors.last = GLIDESHIM_OK;
  errors.message.clear();
}

const char *glideShimErrorName(GlideShimError error) {
  switch (error) {
    case GLIDESHIM_OK: return "GLIDESHIM_OK";
    case GLIDESHIM_ERR_NOT_INITIALIZED: return "GLIDESHIM_ERR_NOT_INITIALIZED";
    case GLIDESHIM_ERR_INVALID_ENUM: return "GLIDESHIM_ERR_INVALID_ENUM";
    case GLIDESHIM_ERR_NULL_POINTER: return "GLIDESHIM_ERR_NULL_POINTER";
    case GLIDESHIM_ERR_OUT_OF_RANGE: return "GLIDESHIM_ERR_OUT_OF_RANGE";
    case GLIDESHIM_ERR_INVALID_VALUE: return "GLIDESHIM_ERR_INVALID_VALUE";
    case GLIDESHIM_ERR_INCONSISTENT: return "GLIDESHIM_ERR_INCONSISTENT";
    case GLIDESHIM_ERR_UNSUPPORTED: return "GLIDESHIM_ERR_UNSUPPORTED";
    case GLIDESHIM_ERR_BACKEND: return "GLIDESHIM_ERR_BACKEND";
    case GLIDESHIM_ERR_FILE: return "GLIDESHIM_ERR_FILE";
    case GLIDESHIM_ERR_OUT_OF_MEMORY: return "GLIDESHIM_ERR_OUT_OF_MEMORY";
    case GLIDESHIM_ERR_INTERNAL: return "GLIDESHIM_ERR_INTERNAL";
  }
  return "unknown";
}

}  // namespace glide_shim_api

namespace glide_shim {

void GlideContext::report(GlideShimError kind, const std::string &message) {
  errors.last = kind;
  errors.message = message;
  if (errors.callback != nullptr) errors.callback(errors.message.c_str(), FXFALSE);
}

bool GlideContext::require_open(const char *function) {
  if (plain_gl) {
    report(GLIDESHIM_ERR_INCONSISTENT, std::string(function) +
                                           ": Glide calls wait for glideShimEndGL (plain GL is begun)");
    return false;
  }
  if (initialized && display.open) return true;
  report(GLIDESHIM_ERR_NOT_INITIALIZED,
         std::string(function) + ": no window is open (call grGlideInit and grSstWinOpen first)");
  return false;
}

}  // namespace glide_shim
