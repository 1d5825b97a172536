/* glide_shim.h: what the glideshadows shim adds to the Glide 2.x API. Nothing here exists on a
 * real Voodoo; ported programs need none of it. Errors, backend choice and frame export live
 * here so that glide.h stays exactly the SDK's. */
#ifndef GLIDE_SHIM_H
#define GLIDE_SHIM_H

#include <glide.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(GLIDESHIM_BUILDING)
#define GLIDESHIM_API __attribute__((visibility("default")))
#else
#define GLIDESHIM_API
#endif

/* Every kind of error an entry point can report. A call that reports one has changed nothing,
 * with these exceptions: GLIDESHIM_ERR_BACKEND may come from work the call finished regardless
 * (writing a GLIDESHIM_DUMP_DIR frame after a swap, compiling a shader for queued triangles);
 * GLIDESHIM_ERR_OUT_OF_MEMORY and GLIDESHIM_ERR_INTERNAL stop a call wherever the exception was
 * thrown, so the call returned its failure value but may have done part of its work. No C++
 * exception ever leaves a call into the shim. Each error goes to the grErrorSetCallback callback;
 * with none installed, each distinct message is printed once to stderr unless the environment
 * sets GLIDESHIM_QUIET=1. */
typedef enum {
  GLIDESHIM_OK = 0,
  GLIDESHIM_ERR_NOT_INITIALIZED, /* a call before grGlideInit, or one needing a window with none open */
  GLIDESHIM_ERR_INVALID_ENUM,    /* an enum value Glide 2.x does not define for that argument */
  GLIDESHIM_ERR_NULL_POINTER,    /* a required pointer is NULL */
  GLIDESHIM_ERR_OUT_OF_RANGE,    /* a number, region or address outside what the hardware has */
  GLIDESHIM_ERR_INVALID_VALUE,   /* NaN, infinity or an absurd coordinate in a vertex */
  GLIDESHIM_ERR_INCONSISTENT,    /* arguments that contradict each other (LOD order, lock state) */
  GLIDESHIM_ERR_UNSUPPORTED,     /* valid Glide 2.x, but not implemented by this shim yet */
  GLIDESHIM_ERR_BACKEND,         /* the OpenGL backend failed (context, shader, file output) */
  GLIDESHIM_ERR_FILE,            /* a file to read is missing, truncated or not in its format (.3df) */
  GLIDESHIM_ERR_OUT_OF_MEMORY,   /* memory ran out inside the call (std::bad_alloc) */
  GLIDESHIM_ERR_INTERNAL         /* any other C++ exception inside the call: a shim bug */
} GlideShimError;

/* The last error reported since the previous clear, and its message ("" when none). */
GLIDESHIM_API GlideShimError glideShimGetLastError(void);
GLIDESHIM_API const char *glideShimGetLastErrorMessage(void);
GLIDESHIM_API void glideShimClearError(void);
/* "GLIDESHIM_ERR_INVALID_ENUM" and so on; "unknown" for values outside the enum. */
GLIDESHIM_API const char *glideShimErrorName(GlideShimError error);

/* The backend that made the current context: "osmesa", "egl" or "sdl" (a window); "" with no
 * window open. Chosen at grSstWinOpen from GLIDESHIM_BACKEND (osmesa by default). */
GLIDESHIM_API const char *glideShimBackendName(void);

/* Keyboard input for interactive programs. Glide 2.x has none: DOS programs read the keyboard
 * themselves (the SDK's tlib through tlKbHit/tlGetCH). With GLIDESHIM_BACKEND=sdl the window's
 * keys are queued (up to 64; further keys are dropped until the program reads some) and
 * glideShimPollKey returns the oldest, without waiting: a printable key as its ASCII character
 * (Shift and the keyboard layout applied; non-ASCII characters are not passed on), the keys
 * below as their codes, 0 when the queue is empty. Headless backends, and no open window,
 * always give 0. The queue is filled at every grBufferSwap and every glideShimPollKey or
 * glideShimWindowClosed call. */
#define GLIDESHIM_KEY_NONE 0
#define GLIDESHIM_KEY_BACKSPACE 8
#define GLIDESHIM_KEY_TAB 9
#define GLIDESHIM_KEY_ENTER 13 /* Return and keypad Enter */
#define GLIDESHIM_KEY_ESCAPE 27
#define GLIDESHIM_KEY_DELETE 127
#define GLIDESHIM_KEY_LEFT 0x100
#define GLIDESHIM_KEY_RIGHT 0x101
#define GLIDESHIM_KEY_UP 0x102
#define GLIDESHIM_KEY_DOWN 0x103
#define GLIDESHIM_KEY_PAGE_UP 0x104
#define GLIDESHIM_KEY_PAGE_DOWN 0x105
#define GLIDESHIM_KEY_HOME 0x106
#define GLIDESHIM_KEY_END 0x107
#define GLIDESHIM_KEY_INSERT 0x108
#define GLIDESHIM_KEY_F1 0x110 /* F1..F12 are GLIDESHIM_KEY_F1 + 0..11 */
GLIDESHIM_API int glideShimPollKey(void);
/* FXTRUE once the user has asked to close the window (its close button); the window stays
 * open until grSstWinClose, so the program decides when to stop. FXFALSE headless. */
GLIDESHIM_API FxBool glideShimWindowClosed(void);

/* The size grSstWinOpen(..., GR_RESOLUTION_NONE, ...) opens, for sizes the Voodoo's resolution
 * list lacks (default 640x480). Each side 1..2048; FXFALSE and nothing changed otherwise. */
GLIDESHIM_API FxBool glideShimSetWindowSize(int width, int height);

/* Rendering into texture memory, as a Voodoo Banshee could (the article's faster step 2): until
 * glideShimRenderToFrameBuffer, draws and clears go to a square of `lod`'s size stored at
 * `startAddress` of TMU memory, in the frame buffer's 565 words, with the clip window set to the
 * square. The words are in TMU memory when glideShimRenderToFrameBuffer returns; grTexSource
 * then reads them in any 16-bit format. FXFALSE (nothing changed) for a bad TMU, LOD or address,
 * or when already rendering to a texture. */
GLIDESHIM_API FxBool glideShimRenderToTexture(GrChipID_t tmu, FxU32 startAddress, GrLOD_t lod);
GLIDESHIM_API void glideShimRenderToFrameBuffer(void);

/* Hands every pending Glide primitive to the renderer and starts it drawing (glFlush) without
 * waiting for it, so that the renderer works while the program goes on: llvmpipe rasterises on
 * its own threads from a flush, where a later read (grLfbReadRegion) or grSstIdle would only
 * start it and then wait. Changes no state and no pixel; harmless with nothing pending. */
GLIDESHIM_API void glideShimFlush(void);

/* Plain OpenGL between Glide calls, for techniques Glide never had (depth maps, stencil volumes).
 * glideShimBeginGL draws every pending Glide primitive, saves the GL state, and leaves current:
 *   - the framebuffer holding Glide's render buffer (colour attachment drawn to) and its
 *     24-bit depth and 8-bit stencil buffer, with the viewport and scissor set to the screen;
 *   - no program, no textures bound, depth test, blending, culling and stencil off, and GL's
 *     default clear values (colour 0, depth 1, stencil 0).
 * Glide's depth values are GL window depth 1/w in W-buffer mode (larger is nearer: compare with
 * GL_GEQUAL / GL_GREATER) and ooz/65535 in Z-buffer mode; a GL pass that must meet Glide's depth
 * uses the same mapping. Until glideShimEndGL, every Glide call is refused (INCONSISTENT).
 * glideShimEndGL restores the state (the pixels drawn stay). FXFALSE with
 * an error when no window is open or GL is already begun. Use glideShimGetProcAddress for the
 * gl* entry points of the shim's context (NULL for unknown names). */
GLIDESHIM_API FxBool glideShimBeginGL(void);
GLIDESHIM_API void glideShimEndGL(void);
GLIDESHIM_API void *glideShimGetProcAddress(const char *name);

/* Writes a colour buffer (GR_BUFFER_FRONTBUFFER or GR_BUFFER_BACKBUFFER) as an 8-bit RGB PNG
 * through the Voodoo's gamma table, as the monitor would show it. FXFALSE (with an error
 * reported) if the buffer or path is bad. */
GLIDESHIM_API FxBool glideShimWritePng(GrBuffer_t buffer, const char *path);

/* Number of pixels that passed every test and were written by draw calls since the last reset:
 * a direct count (GL occlusion query), used by tests of depth invariance. Counting starts at the
 * first glideShimResetPixelsWritten (0 before it) and makes every flush wait for its result. */
GLIDESHIM_API FxU32 glideShimPixelsWritten(void);
GLIDESHIM_API void glideShimResetPixelsWritten(void);

#ifdef __cplusplus
}
#endif

#endif /* GLIDE_SHIM_H */
