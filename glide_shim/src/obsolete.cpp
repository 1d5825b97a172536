// Entry points the SST-1 Glide 2.x driver still exports but no longer implements, kept so that
// programs linking them find them: guFbReadRegion and guFbWriteRegion (gump.c, empty bodies
// marked "obsolete"), the guMovie* recorder (gmovie.c, which only reports "unsupported on SST
// hardware"), and grSstConfigPipeline (gsst.c), a raw register write the shim has no
// registers for.
#include "context.h"

#include <string>

using glide_shim::current;

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

// The driver's bodies are empty: nothing is read or written, and nothing is reported.
void guFbReadRegion(const int, const int, const int, const int, const void *, const int) {}
void guFbWriteRegion(const int, const int, const int, const int, const void *, const int) {}

void guMovieStart(void) {
  current().report(GLIDESHIM_ERR_UNSUPPORTED, "guMovieStart: unsupported on SST hardware");
}

void guMovieStop(void) {
  current().report(GLIDESHIM_ERR_UNSUPPORTED, "guMovieStop: unsupported on SST hardware");
}

void guMovieSetName(const char *) {
  current().report(GLIDESHIM_ERR_UNSUPPORTED, "guMovieSetName: unsupported on SST hardware");
}

// The driver writes `value` into register `reg` of the FBI or a TMU behind Glide's back. The
// shim keeps Glide state, not registers, so the write is refused rather than silently lost.
void grSstConfigPipeline(GrChipID_t chip, GrSstRegister reg, FxU32 value) {
  auto &ctx = current();
  if (chip != GR_TMU0 && chip != GR_TMU1 && chip != GR_TMU2 && chip != GR_FBI) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grSstConfigPipeline: chip " + std::to_string(chip) +
                                               " is not GR_TMU0..GR_TMU2 or GR_FBI");
    return;
  }
  ctx.report(GLIDESHIM_ERR_UNSUPPORTED,
             "grSstConfigPipeline: raw register writes are not emulated (register " +
                 std::to_string(reg) + ", value " + std::to_string(value) + ")");
}

}  // namespace glide_shim_api
