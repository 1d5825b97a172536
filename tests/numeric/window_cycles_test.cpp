// Programs may open and close the window many times in one run: 200 grSstWinOpen / draw /
// grSstWinClose cycles leave the heap's allocated bytes flat (after a warm-up, within a margin far
// below what one leaked window would cost: two 565 buffers, depth and 2 MB of TMU), and the
// resident size within what the allocator's free space can account for.
#include <glide.h>
#include <glide_shim.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <malloc.h>
#include <unistd.h>

// GCC says it builds with AddressSanitizer by __SANITIZE_ADDRESS__, clang 14 by __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define WINDOW_CYCLES_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define WINDOW_CYCLES_UNDER_ASAN 1
#endif
#endif

#if defined(WINDOW_CYCLES_UNDER_ASAN)
// In the sanitizer runtime of GCC and clang; GCC 12's headers do not declare it.
extern "C" int __lsan_do_recoverable_leak_check(void);
#endif

namespace {


long resident_kib() {
  long pages_total = 0, pages_resident = 0;
  std::FILE *statm = std::fopen("/proc/self/statm", "r");
  if (statm == nullptr) return -1;
  const int read = std::fscanf(statm, "%ld %ld", &pages_total, &pages_resident);
  std::fclose(statm);
  return read == 2 ? pages_resident * (sysconf(_SC_PAGESIZE) / 1024) : -1;
}

// Bytes the C heap has handed out and not taken back, in every arena and in blocks it mapped
// alone; freed space the allocator keeps does not count.
long allocated_kib() {
  const struct mallinfo2 heap = mallinfo2();
  return static_cast<long>((heap.uordblks + heap.hblkhd) / 1024);
}

// One open / clear / (draw) / swap / read / close cycle; drawing compiles the shim's shaders for
// the new context, so only every tenth cycle draws, to keep the test short.
void cycle(bool draw) {
  ASSERT_TRUE(grSstWinOpen(0, GR_RESOLUTION_640x480, GR_REFRESH_60Hz, GR_COLORFORMAT_ABGR,
                           GR_ORIGIN_UPPER_LEFT, 2, 1))
      << glideShimGetLastErrorMessage();
  GrVertex v[3];
  std::memset(v, 0, sizeof v);
  v[0].x = 10, v[0].y = 10, v[1].x = 600, v[1].y = 40, v[2].x = 200, v[2].y = 400;
  for (GrVertex &p : v) p.oow = 1, p.r = 200, p.g = 100, p.b = 50;
  grDitherMode(GR_DITHER_DISABLE);
  grBufferClear(0xFF0000FFu, 0, 0);  // ABGR red
  if (draw) grDrawTriangle(&v[0], &v[1], &v[2]);
  grBufferSwap(1);
  FxU16 pixel = 0;
  EXPECT_TRUE(grLfbReadRegion(GR_BUFFER_FRONTBUFFER, 200, 100, 1, 1, 2, &pixel));
  grSstWinClose();
  // Red clear, or the triangle's (200, 100, 50) truncated to 565.
  ASSERT_EQ(pixel, draw ? 0xCB26 : 0xF800) << "each cycle clears and draws";
}

TEST(WindowCycles, TwoHundredOpenCloseCyclesDoNotGrowMemory) {
  grGlideInit();
  for (int i = 0; i < 20; ++i) cycle(i % 10 == 0);  // warm-up: allocator pools and the driver's caches
  const long before = resident_kib();
  const long allocated_before = allocated_kib();
  ASSERT_GT(before, 0);
  for (int i = 0; i < 200; ++i) {
    cycle(i % 10 == 0);
    if (::testing::Test::HasFatalFailure()) break;
  }
  const long after = resident_kib();
  const long allocated_after = allocated_kib();
  grGlideShutdown();
  // One leaked 640x480 window is over 3 MB (buffers and TMU memory); 200 would be 600 MB.
#if defined(WINDOW_CYCLES_UNDER_ASAN)
  // Under AddressSanitizer the resident size is no measure (its quarantine keeps freed blocks,
  // its shadow memory grows with them); LeakSanitizer checks instead that the cycles left no
  // block unreachable. The plain build checks the resident size.
  EXPECT_EQ(__lsan_do_recoverable_leak_check(), 0) << "LeakSanitizer found leaked blocks";
  (void)before, (void)after, (void)allocated_before, (void)allocated_after;
#else
  // Measured at 29d5155 over 200 cycles: 0.1 MB more allocated, 0.4 to 2.7 MB more resident.
  // The allocated bytes level off (0.27 MB over 700 cycles, most of it in the first 100); the
  // resident size rises in steps of about 1 MB when a freed window's buffers leave holes the
  // next window's do not fit, more often when threads are scheduled differently under load. So
  // the tight bound is on allocated bytes (5 KB a cycle), and the resident bound only has to
  // tell steps from a leak the allocator cannot see (a mapping: 80 KB a cycle).
  EXPECT_LT(allocated_after - allocated_before, 1024)
      << "allocated " << allocated_before << " KiB -> " << allocated_after << " KiB";
  EXPECT_LT(after - before, 16 * 1024) << "resident " << before << " KiB -> " << after << " KiB";
#endif
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
}

}  // namespace
