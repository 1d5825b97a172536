// Error reporting: every rejected call records one error kind with a message naming the problem,
// keeps it as the last error, and hands it once to the program's grErrorSetCallback callback;
// without a callback, each distinct message is printed once to stderr (GLIDESHIM_QUIET silences).
#include "context.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

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

bool errors_quiet() {
  const char *quiet = std::getenv("GLIDESHIM_QUIET");
  return quiet != nullptr && *quiet != '\0' && std::strcmp(quiet, "0") != 0;
}

void GlideContext::report(GlideShimError kind, const std::string &message) {
  errors.last = kind;
  errors.message = message;
  if (errors.callback != nullptr) {
    errors.callback(errors.message.c_str(), FXFALSE);
    return;
  }
  if (errors_quiet() || errors.printed.count(message) != 0) return;
  if (errors.printed.size() >= kMaxPrintedErrors) {
    if (!errors.print_limit_reached) {
      std::fprintf(stderr, "glide_shim: %zu different errors printed; further ones are not\n",
                   kMaxPrintedErrors);
      errors.print_limit_reached = true;
    }
    return;
  }
  errors.printed.insert(message);
  std::fprintf(stderr, "glide_shim: %s [%s]\n", message.c_str(),
               glide_shim_api::glideShimErrorName(kind));
}

bool GlideContext::refuse_closed(const char *function) {
  if (plain_gl) {
    report(GLIDESHIM_ERR_INCONSISTENT, std::string(function) +
                                           ": Glide calls wait for glideShimEndGL (plain GL is begun)");
    return false;
  }
  report(GLIDESHIM_ERR_NOT_INITIALIZED,
         std::string(function) + ": no window is open (call grGlideInit and grSstWinOpen first)");
  return false;
}

}  // namespace glide_shim
