// The exception barrier of the C API (glide_shim/src/exception_barrier.h, entry_points_*.cpp):
// an exception thrown inside a call never reaches the caller. This binary replaces the global
// operator new so that a test can make one allocation fail inside a shim call (the shim is a
// shared library, so its allocations come here too): the call must return its failure value,
// report GLIDESHIM_ERR_OUT_OF_MEMORY through the error callback, and leave the state as it was.
// Any other exception (here: one thrown by a C++ program's error callback) is reported as
// GLIDESHIM_ERR_INTERNAL. Last, every function the public headers declare is exported, which
// with every definition in namespace glide_shim_api means every one goes through the barrier.
#include "context.h"
#include "glide_window.h"

#include <dlfcn.h>
#include <glide.h>
#include <glide_shim.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

// -1: no allocation fails; n >= 0: the allocation after n more succeed throws std::bad_alloc.
std::atomic<long> g_fail_after{-1};
std::atomic<int> g_failed{0};  // allocations made to fail so far

void *allocate(std::size_t size) {
  long n = g_fail_after.load();
  while (n >= 0) {
    if (g_fail_after.compare_exchange_weak(n, n - 1)) {
      if (n == 0) {
        ++g_failed;
        throw std::bad_alloc();
      }
      break;
    }
  }
  if (void *p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}

}  // namespace

// The replaced allocation functions (with their matching deallocations, all through malloc and
// free, so that AddressSanitizer sees matching pairs). The aligned forms keep the runtime's.
void *operator new(std::size_t size) { return allocate(size); }
void *operator new[](std::size_t size) { return allocate(size); }
void *operator new(std::size_t size, const std::nothrow_t &) noexcept {
  try {
    return allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void *operator new[](std::size_t size, const std::nothrow_t &) noexcept {
  try {
    return allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void operator delete(void *p) noexcept { std::free(p); }
void operator delete[](void *p) noexcept { std::free(p); }
void operator delete(void *p, std::size_t) noexcept { std::free(p); }
void operator delete[](void *p, std::size_t) noexcept { std::free(p); }
void operator delete(void *p, const std::nothrow_t &) noexcept { std::free(p); }
void operator delete[](void *p, const std::nothrow_t &) noexcept { std::free(p); }

namespace {

std::vector<std::string> g_messages;
bool g_throw_from_callback = false;

void record_error(const char *message, FxBool) {
  if (g_throw_from_callback) {
    g_throw_from_callback = false;
    throw std::runtime_error("the program's callback threw");
  }
  g_messages.emplace_back(message);
}

class ExceptionBarrierTest : public GlideWindowTest {
 protected:
  void SetUp() override {
    GlideWindowTest::SetUp();
    g_messages.clear();
    grErrorSetCallback(record_error);
    glideShimClearError();
  }
  void TearDown() override {
    g_fail_after = -1;
    g_throw_from_callback = false;
    grErrorSetCallback(nullptr);
    GlideWindowTest::TearDown();
  }
};

// A read lock copies the whole screen into a new buffer: with that allocation failing, the lock
// is refused as out of memory, no lock is held, and the program is told once.
TEST_F(ExceptionBarrierTest, AFailedAllocationIsReportedAndTheCallReturnsFalse) {
  grSstIdle();  // nothing queued: the lock's own allocations come first
  const int failed_before = g_failed;
  GrLfbInfo_t info{};
  info.size = sizeof info;
  g_fail_after = 0;
  const FxBool locked = grLfbLock(GR_LFB_READ_ONLY, GR_BUFFER_FRONTBUFFER, GR_LFBWRITEMODE_ANY,
                                  GR_ORIGIN_UPPER_LEFT, FXFALSE, &info);
  g_fail_after = -1;
  ASSERT_EQ(g_failed, failed_before + 1) << "grLfbLock allocated nothing";
  EXPECT_EQ(locked, FXFALSE);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_MEMORY);
  EXPECT_STREQ(glideShimErrorName(GLIDESHIM_ERR_OUT_OF_MEMORY), "GLIDESHIM_ERR_OUT_OF_MEMORY");
  ASSERT_EQ(g_messages.size(), 1u);
  EXPECT_EQ(g_messages[0], "grLfbLock: out of memory");
  EXPECT_EQ(g_messages[0], glideShimGetLastErrorMessage());
  EXPECT_FALSE(glide_shim::current().lfb.read_locked);
  // With memory again the same lock works, and unlocks.
  glideShimClearError();
  ASSERT_EQ(grLfbLock(GR_LFB_READ_ONLY, GR_BUFFER_FRONTBUFFER, GR_LFBWRITEMODE_ANY,
                      GR_ORIGIN_UPPER_LEFT, FXFALSE, &info),
            FXTRUE);
  EXPECT_EQ(grLfbUnlock(GR_LFB_READ_ONLY, GR_BUFFER_FRONTBUFFER), FXTRUE);
  expect_no_error();
}

void unlock_if_locked() {
  if (glide_shim::current().lfb.write_locked) grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER);
}

// Every allocation of a write lock and of a region write, failed one at a time: each time the
// call returns FXFALSE with OUT_OF_MEMORY and holds no lock; past the last one it succeeds.
TEST_F(ExceptionBarrierTest, EachAllocationOfACallCanFail) {
  GrLfbInfo_t info{};
  info.size = sizeof info;
  std::vector<FxU16> region(16 * 16, 0x1234);
  struct Call {
    const char *name;
    FxBool (*run)(GrLfbInfo_t &, std::vector<FxU16> &);
  };
  const Call calls[] = {
      {"grLfbLock",
       [](GrLfbInfo_t &i, std::vector<FxU16> &) {
         return grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_565,
                          GR_ORIGIN_UPPER_LEFT, FXTRUE, &i);
       }},
      {"grLfbWriteRegion",
       [](GrLfbInfo_t &, std::vector<FxU16> &r) {
         return grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 4, 4, GR_LFB_SRC_FMT_565, 16, 16, 32, r.data());
       }},
  };
  for (const Call &call : calls) {
    // Once without failures first, so that the GL stack has compiled what the call draws with:
    // the allocations made to fail are then the shim's, not those of llvmpipe's compiler (not
    // ours, and not written to survive an exception).
    ASSERT_EQ(call.run(info, region), FXTRUE) << call.name;
    unlock_if_locked();
    int failures = 0;
    for (long n = 0; n < 10000; ++n) {
      grSstIdle();
      glideShimClearError();
      g_messages.clear();
      const int failed_before = g_failed;
      g_fail_after = n;
      const FxBool ok = call.run(info, region);
      g_fail_after = -1;
      const bool held = glide_shim::current().lfb.write_locked;
      unlock_if_locked();
      if (g_failed == failed_before) {  // no allocation left to fail: the call went through
        EXPECT_EQ(ok, FXTRUE) << call.name;
        expect_no_error();
        break;
      }
      ++failures;
      EXPECT_EQ(ok, FXFALSE) << call.name << " with allocation " << n << " failing";
      EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_MEMORY) << call.name;
      ASSERT_EQ(g_messages.size(), 1u) << call.name;
      EXPECT_EQ(g_messages[0], std::string(call.name) + ": out of memory");
      EXPECT_FALSE(held) << call.name;
    }
    EXPECT_GT(failures, 0) << call.name << " allocated nothing";
  }
}

// An exception that is not std::bad_alloc, here from a C++ program's callback while a call
// reports a bad argument: reported as GLIDESHIM_ERR_INTERNAL with its what(), nothing escapes.
TEST_F(ExceptionBarrierTest, AnyOtherExceptionIsAnInternalError) {
  const GrCmpFnc_t before = glide_shim::current().blend.alpha_test_function;
  g_throw_from_callback = true;
  grAlphaTestFunction(99);  // an unknown compare function: reported, and the callback throws
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INTERNAL);
  EXPECT_STREQ(glideShimErrorName(GLIDESHIM_ERR_INTERNAL), "GLIDESHIM_ERR_INTERNAL");
  ASSERT_EQ(g_messages.size(), 1u);
  EXPECT_EQ(g_messages[0], "grAlphaTestFunction: the program's callback threw");
  EXPECT_EQ(glide_shim::current().blend.alpha_test_function, before);
  // A call with a return value returns its failure value.
  g_messages.clear();
  g_throw_from_callback = true;
  EXPECT_EQ(grSstControl(0xFFFF), FXFALSE);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INTERNAL);
  ASSERT_EQ(g_messages.size(), 1u);
}

// Every function glide.h, glideutl.h and glide_shim.h declare is exported by libglide2x. The
// shim's sources define them in namespace glide_shim_api, so each exported one is the
// generated wrapper with the barrier (glide_shim/make_entry_points.py writes them).
TEST(EntryPoints, EveryDeclaredFunctionIsExported) {
  std::string text;
  for (const char *header : {"glide.h", "glideutl.h", "glide_shim.h"}) {
    std::ifstream file(std::string(GLIDESHIM_INCLUDE_DIR) + "/" + header);
    ASSERT_TRUE(file) << header;
    std::string line;
    while (std::getline(file, line)) {
      const auto first = line.find_first_not_of(" \t");
      if (first != std::string::npos && line[first] == '#') continue;  // preprocessor lines
      text += line + "\n";
    }
  }
  // Drop comments, then take the name before the '(' that follows each FX_ENTRY or
  // GLIDESHIM_API.
  std::string code;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 2, "/*") == 0) {
      const std::size_t end = text.find("*/", i + 2);
      i = end == std::string::npos ? text.size() : end + 1;
      code += ' ';
    } else {
      code += text[i];
    }
  }
  void *library = dlopen(GLIDESHIM_LIBRARY, RTLD_NOW | RTLD_NOLOAD);
  if (library == nullptr) library = dlopen(GLIDESHIM_LIBRARY, RTLD_NOW);
  ASSERT_NE(library, nullptr) << dlerror();
  int count = 0;
  for (const std::string marker : {"FX_ENTRY", "GLIDESHIM_API"}) {
    for (std::size_t at = code.find(marker); at != std::string::npos;
         at = code.find(marker, at + 1)) {
      std::size_t end = code.find('(', at);
      ASSERT_NE(end, std::string::npos);
      while (end > at && code[end - 1] == ' ') --end;
      std::size_t begin = end;
      while (begin > at && (std::isalnum(static_cast<unsigned char>(code[begin - 1])) != 0 ||
                            code[begin - 1] == '_'))
        --begin;
      const std::string name = code.substr(begin, end - begin);
      EXPECT_NE(dlsym(library, name.c_str()), nullptr) << name << " is declared but not exported";
      ++count;
    }
  }
  EXPECT_GE(count, 147);
  dlclose(library);
}

}  // namespace
