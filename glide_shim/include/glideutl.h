/*
 * glideutl.h - Glide 2.x utility (gu*) prototypes that the SDK keeps out of
 * glide.h: clipped drawing, combine presets, fog-table generation, endian
 * helpers, RLE encoding and .3df file loading.  The gu texture-manager
 * functions (guTexAllocateMemory etc.) are declared in glide.h, as in the SDK.
 */
#ifndef __GLIDEUTL_H__
#define __GLIDEUTL_H__

/* Needs the Glide types; harmless if glide.h is already being included. */
#include "glide.h"

#ifdef __cplusplus
extern "C" {
#endif

#ifndef FX_GLIDE_NO_FUNC_PROTO

/* ---- drawing with clipping to the current clip window ---- */
FX_ENTRY void FX_CALL guAADrawTriangleWithClip(const GrVertex *a,
                                               const GrVertex *b,
                                               const GrVertex *c);
FX_ENTRY void FX_CALL guDrawTriangleWithClip(const GrVertex *a,
                                             const GrVertex *b,
                                             const GrVertex *c);
FX_ENTRY void FX_CALL guDrawPolygonVertexListWithClip(int nverts,
                                                      const GrVertex vlist[]);

/* ---- combine-unit presets ---- */
FX_ENTRY void FX_CALL guAlphaSource(GrAlphaSource_t mode);
FX_ENTRY void FX_CALL guColorCombineFunction(GrColorCombineFnc_t fnc);

/* ---- miscellaneous ---- */
FX_ENTRY int    FX_CALL guEncodeRLE16(void *dst, void *src,
                                      FxU32 width, FxU32 height);
FX_ENTRY FxU16 * FX_CALL guTexCreateColorMipMap(void);

/* ---- fog tables (GR_FOG_TABLE_SIZE entries) ---- */
FX_ENTRY float FX_CALL guFogTableIndexToW(int i);
FX_ENTRY void  FX_CALL guFogGenerateExp(GrFog_t fogtable[], float density);
FX_ENTRY void  FX_CALL guFogGenerateExp2(GrFog_t fogtable[], float density);
FX_ENTRY void  FX_CALL guFogGenerateLinear(GrFog_t fogtable[],
                                           float nearZ, float farZ);

/* ---- byte/word swapping ---- */
FX_ENTRY FxU32 FX_CALL guEndianSwapWords(FxU32 value);
FX_ENTRY FxU16 FX_CALL guEndianSwapBytes(FxU16 value);

/* ---- multipass texturing: two "virtual TMUs" drawn in two passes on one TMU (gump.h) ---- */
#define GLIDE_NUM_VIRTUAL_TMU 2

typedef FxU32 GrMPTextureCombineFnc_t;
#define GR_MPTEXTURECOMBINE_ADD        0x0
#define GR_MPTEXTURECOMBINE_MULTIPLY   0x1
#define GR_MPTEXTURECOMBINE_DETAIL0    0x2
#define GR_MPTEXTURECOMBINE_DETAIL1    0x3
#define GR_MPTEXTURECOMBINE_TRILINEAR0 0x4
#define GR_MPTEXTURECOMBINE_TRILINEAR1 0x5
#define GR_MPTEXTURECOMBINE_SUBTRACT   0x6

typedef struct {
  GrMipMapId_t            mmid[GLIDE_NUM_VIRTUAL_TMU];
  GrMPTextureCombineFnc_t tc_fnc;
} GrMPState;

FX_ENTRY void FX_CALL guMPInit(void);
FX_ENTRY void FX_CALL guMPTexCombineFunction(GrMPTextureCombineFnc_t tc);
FX_ENTRY void FX_CALL guMPTexSource(GrChipID_t virtual_tmu, GrMipMapId_t mmid);
FX_ENTRY void FX_CALL guMPDrawTriangle(const GrVertex *a, const GrVertex *b,
                                       const GrVertex *c);

/* ---- obsolete entry points the SST-1 driver still exports (gump.c, gmovie.c) ---- */
FX_ENTRY void FX_CALL guFbReadRegion(const int srcX, const int srcY, const int w,
                                     const int h, const void *dst,
                                     const int strideInBytes);
FX_ENTRY void FX_CALL guFbWriteRegion(const int dstX, const int dstY, const int w,
                                      const int h, const void *src,
                                      const int strideInBytes);
FX_ENTRY void FX_CALL guMovieStart(void);
FX_ENTRY void FX_CALL guMovieStop(void);
FX_ENTRY void FX_CALL guMovieSetName(const char *name);

/* ---- .3df texture files ---- */
FX_ENTRY FxBool FX_CALL gu3dfGetInfo(const char *filename, Gu3dfInfo *info);
FX_ENTRY FxBool FX_CALL gu3dfLoad(const char *filename, Gu3dfInfo *data);

#endif /* FX_GLIDE_NO_FUNC_PROTO */

#ifdef __cplusplus
}
#endif

#endif /* __GLIDEUTL_H__ */
