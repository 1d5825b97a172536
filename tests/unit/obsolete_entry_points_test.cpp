// The obsolete entry points the SST-1 driver still exports (obsolete.cpp): guFbReadRegion and
// guFbWriteRegion do nothing, as the driver's empty bodies; guMovie* report "unsupported", as
// gmovie.c does; grSstConfigPipeline refuses the raw register write. None changes the frame
// buffer or the Glide state.
#include "glide_window.h"

#include <cstring>
#include <vector>

namespace {

class ObsoleteEntryPointsTest : public GlideWindowTest {
 protected:
  void SetUp() override {
    GlideWindowTest::SetUp();
    grBufferClear(0x00336699, 0, 0);
    before_ = read_buffer();
    grGlideGetState(&state_before_);
  }
  void expect_nothing_changed() {
    EXPECT_EQ(read_buffer(), before_);
    GrState after;
    grGlideGetState(&after);
    EXPECT_EQ(std::memcmp(&after, &state_before_, sizeof after), 0);
  }
  static void expect_refused(GlideShimError kind, const char *function) {
    EXPECT_EQ(glideShimGetLastError(), kind) << glideShimGetLastErrorMessage();
    EXPECT_NE(std::strstr(glideShimGetLastErrorMessage(), function), nullptr)
        << glideShimGetLastErrorMessage();
    glideShimClearError();
  }
  std::vector<FxU16> before_;
  GrState state_before_;
};

TEST_F(ObsoleteEntryPointsTest, FrameBufferRegionStubsReadAndWriteNothing) {
  std::vector<FxU16> memory(16 * 16, 0xABCD);
  guFbReadRegion(0, 0, 16, 16, memory.data(), 32);
  EXPECT_EQ(memory, std::vector<FxU16>(16 * 16, 0xABCD)) << "guFbReadRegion wrote memory";
  guFbWriteRegion(0, 0, 16, 16, memory.data(), 32);
  expect_no_error();
  expect_nothing_changed();
}

TEST_F(ObsoleteEntryPointsTest, MovieRecorderReportsUnsupported) {
  guMovieSetName("frames");
  expect_refused(GLIDESHIM_ERR_UNSUPPORTED, "guMovieSetName");
  guMovieStart();
  expect_refused(GLIDESHIM_ERR_UNSUPPORTED, "guMovieStart");
  guMovieStop();
  expect_refused(GLIDESHIM_ERR_UNSUPPORTED, "guMovieStop");
  expect_nothing_changed();
}

TEST_F(ObsoleteEntryPointsTest, ConfigPipelineRefusesRawRegisterWrites) {
  grSstConfigPipeline(GR_FBI, 0x52, 0x10);  // alphaMode
  expect_refused(GLIDESHIM_ERR_UNSUPPORTED, "grSstConfigPipeline");
  grSstConfigPipeline(7, 0x52, 0x10);
  expect_refused(GLIDESHIM_ERR_INVALID_ENUM, "grSstConfigPipeline");
  expect_nothing_changed();
}

}  // namespace
