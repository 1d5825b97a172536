/*
 * sst1vid.h - video mode enumerations of the Glide 2.x API: the screen
 * refresh rates and screen resolutions passed to grSstWinOpen().  The
 * numeric codes are the ones 3dfx's SST-1 SDK uses.
 */
#ifndef __SST1VID_H__
#define __SST1VID_H__

#include "3dfx.h"

/* Vertical refresh rate */
typedef FxI32 GrScreenRefresh_t;
#define GR_REFRESH_60Hz          0x0
#define GR_REFRESH_70Hz          0x1
#define GR_REFRESH_72Hz          0x2
#define GR_REFRESH_75Hz          0x3
#define GR_REFRESH_80Hz          0x4
#define GR_REFRESH_90Hz          0x5
#define GR_REFRESH_100Hz         0x6
#define GR_REFRESH_85Hz          0x7
#define GR_REFRESH_120Hz         0x8
#define GR_REFRESH_NONE          0xff

/* Screen resolution */
typedef FxI32 GrScreenResolution_t;
#define GR_RESOLUTION_320x200    0x0
#define GR_RESOLUTION_320x240    0x1
#define GR_RESOLUTION_400x256    0x2
#define GR_RESOLUTION_512x384    0x3
#define GR_RESOLUTION_640x200    0x4
#define GR_RESOLUTION_640x350    0x5
#define GR_RESOLUTION_640x400    0x6
#define GR_RESOLUTION_640x480    0x7
#define GR_RESOLUTION_800x600    0x8
#define GR_RESOLUTION_960x720    0x9
#define GR_RESOLUTION_856x480    0xa
#define GR_RESOLUTION_512x256    0xb
#define GR_RESOLUTION_1024x768   0xc
#define GR_RESOLUTION_1280x1024  0xd
#define GR_RESOLUTION_1600x1200  0xe
#define GR_RESOLUTION_400x300    0xf
#define GR_RESOLUTION_NONE       0xff

/* Range bounds; as in the SDK, MAX stops at 1600x1200 (400x300 came later). */
#undef  GR_RESOLUTION_MIN
#undef  GR_RESOLUTION_MAX
#define GR_RESOLUTION_MIN        GR_RESOLUTION_320x200
#define GR_RESOLUTION_MAX        GR_RESOLUTION_1600x1200

#endif /* __SST1VID_H__ */
