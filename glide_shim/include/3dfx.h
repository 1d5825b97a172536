/*
 * 3dfx.h - base scalar types, boolean constants and calling-convention
 * macros shared by the Glide 2.x compatibility headers (glide.h, sst1vid.h,
 * glideutl.h).  Names and meanings follow 3dfx's SDK; widths are fixed so
 * that FxU32/FxI32 stay 32-bit on LP64 Linux.
 */
#ifndef __3DFX_H__
#define __3DFX_H__

/* ---- fixed-width scalars ------------------------------------------------ */
typedef unsigned char   FxU8;
typedef signed char     FxI8;
typedef unsigned short  FxU16;
typedef signed short    FxI16;
/* The SDK used long here; that is 64-bit on LP64, so int is used instead. */
typedef signed int      FxI32;
typedef unsigned int    FxU32;
typedef unsigned long   AnyPtr;        /* integer wide enough for a pointer */
typedef int             FxBool;
typedef float           FxFloat;
typedef double          FxDouble;

/* ---- colours ------------------------------------------------------------ */
typedef FxU32 FxColor_t;               /* packed 32-bit colour */
typedef struct {
    float r, g, b, a;
} FxColor4;

/* ---- booleans and helpers ----------------------------------------------- */
#define FXTRUE    1
#define FXFALSE   0

#define FXUNUSED(a)   ((void)(a))
#define FXBIT(i)      (1L << (i))

/* ---- linkage / calling convention --------------------------------------- */
/* An implementation may predefine any of these before including us. */
#ifndef FX_CALL
#  if defined(_WIN32) && (defined(_M_IX86) || defined(__i386__))
#    define FX_CALL __stdcall
#  else
#    define FX_CALL
#  endif
#endif

#ifndef FX_ENTRY
#  define FX_ENTRY extern
#endif

#ifndef FX_EXPORT
#  define FX_EXPORT extern
#endif

#ifndef FX_CSTYLE
#  define FX_CSTYLE
#endif

/* ---- compile-time checks (valid C89 and C++) ---------------------------- */
typedef char fx3dfx_check_FxU32_is_4_bytes[(sizeof(FxU32) == 4) ? 1 : -1];
typedef char fx3dfx_check_FxI32_is_4_bytes[(sizeof(FxI32) == 4) ? 1 : -1];
typedef char fx3dfx_check_FxU16_is_2_bytes[(sizeof(FxU16) == 2) ? 1 : -1];

#endif /* __3DFX_H__ */
