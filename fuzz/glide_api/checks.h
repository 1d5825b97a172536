// The checks every call goes through: `checked` snapshots the context's state, makes the call,
// and aborts (libFuzzer's crash, with the input) when the call broke a rule that must hold
// whatever its arguments: an error without a message or not given to the callback, a refused
// call that changed state, an exception caught, an open window's groups out of range.
#pragma once

#include "context.h"
#include "glide_api/snapshot.h"

#include <glide.h>
#include <glide_shim.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace glide_api_fuzz {

using glide_shim::GlideContext;

[[noreturn]] void violated(const char *call, const char *what);

extern unsigned g_thorough;  // kAll for a thorough input (one in eight), else kSmall

// The error callback (installed at start-up and at every input's start) and what it last saw.
extern std::string g_callback_message;
extern int g_callback_count;
void on_error(const char *message, FxBool fatal);

// What must hold while a window is open, whatever the call before.
void check_open_window(const GlideContext &ctx, const char *call);

// Runs one call: clears the last error, snapshots the state, calls, then checks. `touches`
// says which large groups the call may write (Touches), for the snapshot to hold them too.
extern Snapshot g_before;  // reused, so that its buffers are allocated once

template <typename Call>
void checked(const char *name, unsigned touches, Call &&call) {
  GlideContext &ctx = glide_shim::current();
  glideShimClearError();
  g_callback_count = 0;
  g_before.take(ctx, touches | g_thorough);
  call();
  const GlideShimError error = glideShimGetLastError();
  const std::string message = glideShimGetLastErrorMessage();
  if (error != GLIDESHIM_OK) {
    if (message.empty()) violated(name, "an error was reported without a message");
    if (g_callback_count == 0 || g_callback_message != message)
      violated(name, "the error callback did not get the error's message");
    if (error == GLIDESHIM_ERR_OUT_OF_MEMORY || error == GLIDESHIM_ERR_INTERNAL)
      violated(name, ("an exception was caught: " + message).c_str());
    if (const char *group = g_before.differs(ctx)) {
      std::fprintf(stderr, "glide_api_fuzz: %s was rejected (%s) but changed: %s\n", name,
                   message.c_str(), group);
      std::abort();
    }
  } else if (!message.empty()) {
    violated(name, "a message was left without an error");
  }
  // Getters report no error of their own while a window is open, so these do not disturb
  // the check above for the next call.
  if (ctx.display.open && !ctx.plain_gl) check_open_window(ctx, name);
}

template <typename Call>
void checked(const char *name, Call &&call) {
  checked(name, kSmall, call);
}

}  // namespace glide_api_fuzz
