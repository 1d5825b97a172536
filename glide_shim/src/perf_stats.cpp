// grSstPerfStats / grSstResetPerfStats: the FBI's pixel counters (pixels in, failed chroma key,
// failed depth test, failed alpha test, written). Counting starts at the first reset, since it
// draws every primitive separately with occlusion queries (gl_renderer.cpp); until then the
// counters read zero.
#include "context.h"

using glide_shim::current;

extern "C" {

void grSstResetPerfStats(void) {
  auto &ctx = current();
  if (!ctx.require_open("grSstResetPerfStats")) return;
  ctx.flush();
  ctx.perf.counting = true;
  ctx.perf.counts = GrSstPerfStats_t{};
}

void grSstPerfStats(GrSstPerfStats_t *pStats) {
  auto &ctx = current();
  if (!ctx.require_open("grSstPerfStats")) return;
  if (pStats == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grSstPerfStats: pStats is NULL");
    return;
  }
  ctx.flush();
  *pStats = ctx.perf.counts;
}

}  // extern "C"
