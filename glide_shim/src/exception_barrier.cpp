// The reporting half of the exception barrier (exception_barrier.h).
#include "exception_barrier.h"

#include <string>

namespace glide_shim {

void report_exception(const char *function, GlideShimError kind, const char *what) noexcept {
  ErrorState &errors = current().errors;
  try {
    current().report(kind, std::string(function) + ": " + (what != nullptr ? what : "exception"));
    return;
  } catch (...) {
    // No memory for the message (or the program's callback threw): record the kind with a
    // message short enough for std::string's inline buffer, so that nothing is allocated.
  }
  errors.last = kind;
  errors.message.clear();
  errors.message.append(kind == GLIDESHIM_ERR_OUT_OF_MEMORY ? "out of memory" : "exception");
  if (errors.callback != nullptr) {
    try {
      errors.callback(errors.message.c_str(), FXFALSE);
    } catch (...) {
      // A C++ program's callback threw: the error stays recorded for glideShimGetLastError.
    }
  }
}

}  // namespace glide_shim
