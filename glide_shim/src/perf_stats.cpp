// grSstPerfStats / grSstResetPerfStats: the FBI's pixel counters (pixels in, failed chroma key,
// failed depth test, failed alpha test, written). Counting starts at the first reset, since it
// draws every primitive separately with occlusion queries (gl/draw_path.cpp); until then the
// counters read zero. grTriStats / grResetTriStats: triangles set up and drawn (draw.cpp).
#include "context.h"

using glide_shim::current;

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

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

void grResetTriStats(void) {
  auto &ctx = current();
  if (!ctx.require_open("grResetTriStats")) return;
  ctx.perf.triangles_processed = ctx.perf.triangles_drawn = 0;
}

void grTriStats(FxU32 *trisProcessed, FxU32 *trisDrawn) {
  auto &ctx = current();
  if (!ctx.require_open("grTriStats")) return;
  if (trisProcessed == nullptr || trisDrawn == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grTriStats: an output pointer is NULL");
    return;
  }
  *trisProcessed = ctx.perf.triangles_processed;
  *trisDrawn = ctx.perf.triangles_drawn;
}

}  // namespace glide_shim_api
