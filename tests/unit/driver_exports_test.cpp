// Every public entry point of the SST-1 Glide 2.x driver links and is callable: the table takes
// each function's address, so a missing one fails to build rather than to run.
//
// The list is the GR_ENTRY / GR_DIENTRY functions of sezero/glide glide2x/sst1/glide/src/*.c
// (gglide.c, gsst.c, disst.c, diglide.c, glfb.c, gtex.c, gtexdl.c, ditex.c, digutex.c, gu.c,
// guclip.c, gutex.c, gaa.c, gdraw.c, g3df.c, gsplash.c, gerror.c, gump.c, ddgump.c, gmovie.c)
// declared in the public glide.h, glideutl.h and gump.h, plus ConvertAndDownloadRle, which only
// the DOS/Watcom builds of the driver export. Left out: names starting with '_' and the driver's
// internal helpers, the pci*/pio* library, and grSstVidMode (disst.c, which fxglide.h calls an
// "un-documented external for arcade developers" and no public header declares).
#include <glide.h>
#include <glideutl.h>

#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <string>

namespace {

struct EntryPoint {
  const char *name;
  const void *address;
};

#define ENTRY(function) EntryPoint{#function, reinterpret_cast<const void *>(&function)}

const EntryPoint kDriverApi[] = {
    ENTRY(ConvertAndDownloadRle),
    ENTRY(grAADrawLine),
    ENTRY(grAADrawPoint),
    ENTRY(grAADrawPolygon),
    ENTRY(grAADrawPolygonVertexList),
    ENTRY(grAADrawTriangle),
    ENTRY(grAlphaBlendFunction),
    ENTRY(grAlphaCombine),
    ENTRY(grAlphaControlsITRGBLighting),
    ENTRY(grAlphaTestFunction),
    ENTRY(grAlphaTestReferenceValue),
    ENTRY(grBufferClear),
    ENTRY(grBufferNumPending),
    ENTRY(grBufferSwap),
    ENTRY(grCheckForRoom),
    ENTRY(grChromakeyMode),
    ENTRY(grChromakeyValue),
    ENTRY(grClipWindow),
    ENTRY(grColorCombine),
    ENTRY(grColorMask),
    ENTRY(grConstantColorValue),
    ENTRY(grConstantColorValue4),
    ENTRY(grCullMode),
    ENTRY(grDepthBiasLevel),
    ENTRY(grDepthBufferFunction),
    ENTRY(grDepthBufferMode),
    ENTRY(grDepthMask),
    ENTRY(grDisableAllEffects),
    ENTRY(grDitherMode),
    ENTRY(grDrawLine),
    ENTRY(grDrawPlanarPolygon),
    ENTRY(grDrawPlanarPolygonVertexList),
    ENTRY(grDrawPoint),
    ENTRY(grDrawPolygon),
    ENTRY(grDrawPolygonVertexList),
    ENTRY(grDrawTriangle),
    ENTRY(grErrorSetCallback),
    ENTRY(grFogColorValue),
    ENTRY(grFogMode),
    ENTRY(grFogTable),
    ENTRY(grGammaCorrectionValue),
    ENTRY(grGlideGetState),
    ENTRY(grGlideGetVersion),
    ENTRY(grGlideInit),
    ENTRY(grGlideSetState),
    ENTRY(grGlideShamelessPlug),
    ENTRY(grGlideShutdown),
    ENTRY(grHints),
    ENTRY(grLfbConstantAlpha),
    ENTRY(grLfbConstantDepth),
    ENTRY(grLfbLock),
    ENTRY(grLfbReadRegion),
    ENTRY(grLfbUnlock),
    ENTRY(grLfbWriteColorFormat),
    ENTRY(grLfbWriteColorSwizzle),
    ENTRY(grLfbWriteRegion),
    ENTRY(grRenderBuffer),
    ENTRY(grResetTriStats),
    ENTRY(grSplash),
    ENTRY(grSstConfigPipeline),
    ENTRY(grSstControl),
    ENTRY(grSstIdle),
    ENTRY(grSstIsBusy),
    ENTRY(grSstOrigin),
    ENTRY(grSstPerfStats),
    ENTRY(grSstQueryBoards),
    ENTRY(grSstQueryHardware),
    ENTRY(grSstResetPerfStats),
    ENTRY(grSstScreenHeight),
    ENTRY(grSstScreenWidth),
    ENTRY(grSstSelect),
    ENTRY(grSstStatus),
    ENTRY(grSstVideoLine),
    ENTRY(grSstVRetraceOn),
    ENTRY(grSstWinClose),
    ENTRY(grSstWinOpen),
    ENTRY(grTexCalcMemRequired),
    ENTRY(grTexClampMode),
    ENTRY(grTexCombine),
    ENTRY(grTexCombineFunction),
    ENTRY(grTexDetailControl),
    ENTRY(grTexDownloadMipMap),
    ENTRY(grTexDownloadMipMapLevel),
    ENTRY(grTexDownloadMipMapLevelPartial),
    ENTRY(grTexDownloadTable),
    ENTRY(grTexDownloadTablePartial),
    ENTRY(grTexFilterMode),
    ENTRY(grTexLodBiasValue),
    ENTRY(grTexMaxAddress),
    ENTRY(grTexMinAddress),
    ENTRY(grTexMipMapMode),
    ENTRY(grTexMultibase),
    ENTRY(grTexMultibaseAddress),
    ENTRY(grTexNCCTable),
    ENTRY(grTexSource),
    ENTRY(grTexTextureMemRequired),
    ENTRY(grTriStats),
    ENTRY(gu3dfGetInfo),
    ENTRY(gu3dfLoad),
    ENTRY(guAADrawTriangleWithClip),
    ENTRY(guAlphaSource),
    ENTRY(guColorCombineFunction),
    ENTRY(guDrawPolygonVertexListWithClip),
    ENTRY(guDrawTriangleWithClip),
    ENTRY(guEncodeRLE16),
    ENTRY(guEndianSwapBytes),
    ENTRY(guEndianSwapWords),
    ENTRY(guFbReadRegion),
    ENTRY(guFbWriteRegion),
    ENTRY(guFogGenerateExp),
    ENTRY(guFogGenerateExp2),
    ENTRY(guFogGenerateLinear),
    ENTRY(guFogTableIndexToW),
    ENTRY(guMovieSetName),
    ENTRY(guMovieStart),
    ENTRY(guMovieStop),
    ENTRY(guMPDrawTriangle),
    ENTRY(guMPInit),
    ENTRY(guMPTexCombineFunction),
    ENTRY(guMPTexSource),
    ENTRY(guTexAllocateMemory),
    ENTRY(guTexChangeAttributes),
    ENTRY(guTexCombineFunction),
    ENTRY(guTexCreateColorMipMap),
    ENTRY(guTexDownloadMipMap),
    ENTRY(guTexDownloadMipMapLevel),
    ENTRY(guTexGetCurrentMipMap),
    ENTRY(guTexGetMipMapInfo),
    ENTRY(guTexMemQueryAvail),
    ENTRY(guTexMemReset),
    ENTRY(guTexSource),
};

#undef ENTRY

TEST(DriverExports, EveryPublicEntryPointOfTheSst1DriverLinks) {
  std::set<std::string> names;
  for (const EntryPoint &entry : kDriverApi) {
    EXPECT_NE(entry.address, nullptr) << entry.name;
    EXPECT_TRUE(names.insert(entry.name).second) << entry.name << " listed twice";
  }
  EXPECT_EQ(names.size(), 131u);
}

}  // namespace
