/* A Glide program that returns from main with its window still open, as DOS-era programs often
 * do: it must exit. (The shim closes the window from an exit handler that runs before Mesa's,
 * which stops llvmpipe's threads; destroying the GL context after that waited forever.) */
#include <glide.h>
#include <glide_shim.h>

int main(void) {
  GrVertex a = {0}, b = {0}, c = {0};
  grGlideInit();
  glideShimSetWindowSize(64, 64);
  if (!grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                    GR_ORIGIN_UPPER_LEFT, 2, 1))
    return 1;
  a.x = 1.0f, a.y = 1.0f, b.x = 60.0f, b.y = 5.0f, c.x = 30.0f, c.y = 60.0f;
  a.oow = b.oow = c.oow = 1.0f;
  a.r = b.g = c.b = 255.0f;
  grBufferClear(0, 0, 0);
  grDrawTriangle(&a, &b, &c);
  grBufferSwap(1);
  return 0; /* no grSstWinClose, no grGlideShutdown */
}
