// SDL2 window backend (GLIDESHIM_BACKEND=sdl): a window of the Glide screen's size with an
// OpenGL compatibility context, for interactive programs. Rendering is the headless path
// unchanged (the shim's own 565 framebuffer objects); each grBufferSwap then draws the
// scanned-out front buffer, the very bytes the frame export writes, into the window's default
// framebuffer and swaps it. Keys from the window go into a queue read by glideShimPollKey.
// libSDL2 is loaded at run time, like OSMesa and EGL, so headless programs never load it.
#include "backends/backend.h"

#include "glide_shim.h"

#include <SDL.h>
#include <dlfcn.h>

#include <cerrno>
#include <cstring>
#include <deque>

namespace glide_shim {
namespace {

// X(name) for every SDL function the backend calls.
#define GLIDESHIM_SDL_FUNCTIONS(X)                                                         \
  X(SDL_SetHint) X(SDL_InitSubSystem) X(SDL_QuitSubSystem) X(SDL_GetError)                \
  X(SDL_GetCurrentVideoDriver) X(SDL_GL_SetAttribute) X(SDL_CreateWindow)                  \
  X(SDL_DestroyWindow) X(SDL_GetWindowID) X(SDL_GL_CreateContext) X(SDL_GL_DeleteContext) \
  X(SDL_GL_GetProcAddress) X(SDL_GL_SwapWindow) X(SDL_GL_SetSwapInterval)                  \
  X(SDL_GL_GetDrawableSize) X(SDL_PollEvent)

struct SdlFunctions {
#define GLIDESHIM_DECLARE_SDL(name) decltype(&::name) name = nullptr;
  GLIDESHIM_SDL_FUNCTIONS(GLIDESHIM_DECLARE_SDL)
#undef GLIDESHIM_DECLARE_SDL
};

// libSDL2 is opened once and stays loaded: SDL_QuitSubSystem at each window's close already
// lets go of the display, and the program itself may use SDL as well.
const SdlFunctions *load_sdl(std::string &error) {
  static SdlFunctions functions;
  static std::string load_error = [] {
    void *library = dlopen("libSDL2-2.0.so.0", RTLD_NOW | RTLD_LOCAL);
    if (library == nullptr) {
      return std::string("cannot load libSDL2-2.0.so.0 (install libsdl2-2.0-0): ") + dlerror();
    }
#define GLIDESHIM_LOAD_SDL(name)                                          \
  functions.name = reinterpret_cast<decltype(&::name)>(dlsym(library, #name)); \
  if (functions.name == nullptr) return std::string("libSDL2 has no " #name);
    GLIDESHIM_SDL_FUNCTIONS(GLIDESHIM_LOAD_SDL)
#undef GLIDESHIM_LOAD_SDL
    return std::string();
  }();
  if (!load_error.empty()) {
    error = load_error;
    return nullptr;
  }
  return &functions;
}

// Keys a program cannot read as ASCII text, as GLIDESHIM_KEY_* codes; 0 for other keys.
int special_key(SDL_Keycode key) {
  switch (key) {
    case SDLK_ESCAPE: return GLIDESHIM_KEY_ESCAPE;
    case SDLK_RETURN:
    case SDLK_KP_ENTER: return GLIDESHIM_KEY_ENTER;
    case SDLK_BACKSPACE: return GLIDESHIM_KEY_BACKSPACE;
    case SDLK_TAB: return GLIDESHIM_KEY_TAB;
    case SDLK_DELETE: return GLIDESHIM_KEY_DELETE;
    case SDLK_LEFT: return GLIDESHIM_KEY_LEFT;
    case SDLK_RIGHT: return GLIDESHIM_KEY_RIGHT;
    case SDLK_UP: return GLIDESHIM_KEY_UP;
    case SDLK_DOWN: return GLIDESHIM_KEY_DOWN;
    case SDLK_PAGEUP: return GLIDESHIM_KEY_PAGE_UP;
    case SDLK_PAGEDOWN: return GLIDESHIM_KEY_PAGE_DOWN;
    case SDLK_HOME: return GLIDESHIM_KEY_HOME;
    case SDLK_END: return GLIDESHIM_KEY_END;
    case SDLK_INSERT: return GLIDESHIM_KEY_INSERT;
    default: break;
  }
  if (key >= SDLK_F1 && key <= SDLK_F12) return GLIDESHIM_KEY_F1 + (key - SDLK_F1);
  return 0;
}

class SdlBackend final : public Backend {
 public:
  explicit SdlBackend(const SdlFunctions &sdl) : sdl_(sdl) {}
  ~SdlBackend() override {
    if (context_ != nullptr) sdl_.SDL_GL_DeleteContext(context_);
    if (window_ != nullptr) sdl_.SDL_DestroyWindow(window_);
    if (video_started_) sdl_.SDL_QuitSubSystem(SDL_INIT_VIDEO);
  }
  const char *name() const override { return "sdl"; }
  void *proc_address(const char *function) const override {
    return sdl_.SDL_GL_GetProcAddress(function);
  }

  bool open(int width, int height, std::string &error) {
    // SDL would otherwise turn SIGINT into an SDL_QUIT event that a program which never polls
    // keys would not see, so Ctrl-C could no longer stop it.
    sdl_.SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    if (sdl_.SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
      error = std::string("no display for the SDL window: ") + sdl_.SDL_GetError();
      return false;
    }
    video_started_ = true;
    const char *driver = sdl_.SDL_GetCurrentVideoDriver();
    if (driver == nullptr || std::strcmp(driver, "offscreen") == 0 ||
        std::strcmp(driver, "dummy") == 0) {
      error = std::string("no display for the SDL window (SDL fell back to its '") +
              (driver != nullptr ? driver : "none") +
              "' video driver): set DISPLAY or WAYLAND_DISPLAY, run under xvfb-run, or use a "
              "headless GLIDESHIM_BACKEND";
      return false;
    }
    sdl_.SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_COMPATIBILITY);
    sdl_.SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    // 8 bits per channel: the scanned-out bytes reach the window unchanged.
    sdl_.SDL_GL_SetAttribute(SDL_GL_RED_SIZE, 8);
    sdl_.SDL_GL_SetAttribute(SDL_GL_GREEN_SIZE, 8);
    sdl_.SDL_GL_SetAttribute(SDL_GL_BLUE_SIZE, 8);
    sdl_.SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 0);
    sdl_.SDL_GL_SetAttribute(SDL_GL_STENCIL_SIZE, 0);
    const std::string title = std::string("Glide ") + std::to_string(width) + "x" +
                              std::to_string(height) + " - " + program_invocation_short_name;
    window_ = sdl_.SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                    width, height, SDL_WINDOW_OPENGL | SDL_WINDOW_SHOWN);
    if (window_ == nullptr) {
      error = std::string("SDL_CreateWindow failed: ") + sdl_.SDL_GetError();
      return false;
    }
    window_id_ = sdl_.SDL_GetWindowID(window_);
    context_ = sdl_.SDL_GL_CreateContext(window_);
    if (context_ == nullptr) {
      error = std::string("SDL_GL_CreateContext failed for a compatibility profile: ") +
              sdl_.SDL_GetError();
      return false;
    }
    auto lookup = [&](const char *fn) { return sdl_.SDL_GL_GetProcAddress(fn); };
    std::string missing = gl.load(lookup);
    if (missing.empty()) {
      get_integer_ = reinterpret_cast<decltype(&::glGetIntegerv)>(lookup("glGetIntegerv"));
      if (get_integer_ == nullptr) missing = "glGetIntegerv";
    }
    if (!missing.empty()) {
      error = "the SDL window's GL context has no " + missing;
      return false;
    }
    sdl_.SDL_GL_SetSwapInterval(swap_interval_);
    // Until the first grBufferSwap the window shows black, not whatever the window system had.
    frame_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3, 0);
    frame_width_ = width;
    frame_height_ = height;
    draw_frame();
    return true;
  }

  bool shows_window() const override { return true; }

  void present(const std::vector<std::uint8_t> &rgb, int width, int height) override {
    frame_ = rgb;
    frame_width_ = width;
    frame_height_ = height;
    draw_frame();
    pump_events();
  }

  void set_swap_interval(int interval) override {
    if (interval == swap_interval_) return;
    // Waiting for more than one retrace needs GLX_EXT_swap_control; where the driver refuses
    // an interval the swap simply does not wait.
    sdl_.SDL_GL_SetSwapInterval(interval);
    swap_interval_ = interval;
  }

  void pump_events() override {
    SDL_Event event;
    bool exposed = false;
    while (sdl_.SDL_PollEvent(&event) != 0) {
      switch (event.type) {
        case SDL_QUIT: close_requested_ = true; break;
        case SDL_WINDOWEVENT:
          if (event.window.windowID != window_id_) break;
          if (event.window.event == SDL_WINDOWEVENT_CLOSE) close_requested_ = true;
          if (event.window.event == SDL_WINDOWEVENT_EXPOSED) exposed = true;
          break;
        case SDL_KEYDOWN:
          if (event.key.windowID == window_id_) queue_key(special_key(event.key.keysym.sym));
          break;
        case SDL_TEXTINPUT:
          // Printable keys arrive as text, so Shift and the keyboard layout are applied; only
          // ASCII characters are passed on.
          if (event.text.windowID != window_id_) break;
          for (const char *c = event.text.text; *c != '\0'; ++c) {
            const auto byte = static_cast<unsigned char>(*c);
            if (byte >= 0x20 && byte < 0x7F) queue_key(byte);
          }
          break;
        default: break;
      }
    }
    if (exposed) draw_frame();
  }

  int next_key() override {
    if (keys_.empty()) return 0;
    const int key = keys_.front();
    keys_.pop_front();
    return key;
  }

  bool close_requested() const override { return close_requested_; }

 private:
  // Like a PC keyboard buffer, a full queue drops new keys rather than old ones.
  static constexpr std::size_t kKeyQueueSize = 64;

  void queue_key(int key) {
    if (key != 0 && keys_.size() < kKeyQueueSize) keys_.push_back(key);
  }

  // Draws frame_ into the window's back buffer at its upper-left corner and swaps. Every GL
  // setting touched is put back, so the shim's renderer finds its state as it left it.
  void draw_frame() {
    GLint draw_framebuffer = 0, read_framebuffer = 0, program = 0, unpack_buffer = 0;
    get_integer_(GL_DRAW_FRAMEBUFFER_BINDING, &draw_framebuffer);
    get_integer_(GL_READ_FRAMEBUFFER_BINDING, &read_framebuffer);
    get_integer_(GL_CURRENT_PROGRAM, &program);
    get_integer_(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpack_buffer);
    gl.glPushAttrib(GL_COLOR_BUFFER_BIT | GL_ENABLE_BIT | GL_SCISSOR_BIT | GL_CURRENT_BIT |
                    GL_PIXEL_MODE_BIT | GL_VIEWPORT_BIT);
    gl.glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
    gl.glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl.glDrawBuffer(GL_BACK);
    gl.glUseProgram(0);
    for (GLenum cap : {GL_SCISSOR_TEST, GL_DEPTH_TEST, GL_STENCIL_TEST, GL_BLEND, GL_ALPHA_TEST,
                       GL_TEXTURE_2D, GL_FOG, GL_DITHER, GL_COLOR_LOGIC_OP}) {
      gl.glDisable(cap);
    }
    gl.glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl.glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);

    int drawable_width = 0, drawable_height = 0;
    sdl_.SDL_GL_GetDrawableSize(window_, &drawable_width, &drawable_height);
    if (drawable_width != frame_width_ || drawable_height != frame_height_) {
      gl.glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
      gl.glClear(GL_COLOR_BUFFER_BIT);
    }
    // GL's window rows count from the bottom; frame_ rows from the top.
    const std::size_t row_bytes = static_cast<std::size_t>(frame_width_) * 3;
    flipped_.resize(frame_.size());
    for (int row = 0; row < frame_height_; ++row) {
      std::memcpy(flipped_.data() + static_cast<std::size_t>(frame_height_ - 1 - row) * row_bytes,
                  frame_.data() + static_cast<std::size_t>(row) * row_bytes, row_bytes);
    }
    gl.glWindowPos2i(0, drawable_height - frame_height_);
    gl.glDrawPixels(frame_width_, frame_height_, GL_RGB, GL_UNSIGNED_BYTE, flipped_.data());
    sdl_.SDL_GL_SwapWindow(window_);

    gl.glPopClientAttrib();
    gl.glPopAttrib();  // while framebuffer 0 is bound: its draw buffer is part of what returns
    gl.glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_framebuffer));
    gl.glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_framebuffer));
    gl.glUseProgram(static_cast<GLuint>(program));
    gl.glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpack_buffer));
  }

  const SdlFunctions &sdl_;
  bool video_started_ = false;
  SDL_Window *window_ = nullptr;
  std::uint32_t window_id_ = 0;
  SDL_GLContext context_ = nullptr;
  decltype(&::glGetIntegerv) get_integer_ = nullptr;
  int swap_interval_ = 1;  // a Voodoo swap waits for one vertical retrace unless told 0
  std::vector<std::uint8_t> frame_, flipped_;  // the frame shown, 8-bit RGB, rows from the top
  int frame_width_ = 0, frame_height_ = 0;
  std::deque<int> keys_;
  bool close_requested_ = false;
};

}  // namespace

std::unique_ptr<Backend> create_sdl_backend(int width, int height, std::string &error) {
  const SdlFunctions *sdl = load_sdl(error);
  if (sdl == nullptr) return nullptr;
  auto backend = std::make_unique<SdlBackend>(*sdl);
  if (!backend->open(width, height, error)) return nullptr;
  return backend;
}

}  // namespace glide_shim
