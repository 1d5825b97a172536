/* article_port: Hubert Nguyen's projected shadow texture ("Casting Shadows on Volumes", Game
 * Developer, 1999) as a plain Glide 2.x program, written in the style of the article's listings:
 * a software scene transformed on the CPU, the five steps in order each frame, and the frame
 * written as PNG. Only the final glideShimWritePng and the error queries are shim-specific.
 * docs/porting.md maps each function here to the article's steps and listings. */
#define _POSIX_C_SOURCE 199309L /* clock_gettime under -std=c99 */

#include <glide.h>
#include <glide_shim.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { kScreenWidth = 640, kScreenHeight = 480 };
enum { kShadowSize = 256 };   /* shadow texture side in texels: Glide's s,t run 0..256 across it */
enum { kShadowMargin = 8 };   /* empty texels kept around the caster (the article asks for >= 2) */
enum { kMaxVertices = 1024, kMaxTriangles = 2048 };

/* Per-vertex flags, one bit per reason a vertex is out of a view. */
enum {
  kClipZ = 0x01,     /* behind the camera's near plane: Glide has no near clipping */
  kOutLeft = 0x02,   /* light screen x < 0 */
  kOutRight = 0x04,  /* light screen x > 256 */
  kOutTop = 0x08,    /* light screen y < 0 */
  kOutBottom = 0x10, /* light screen y > 256 */
  kOutBehind = 0x20, /* behind the light's near plane: no light screen position at all */
  kOutOfLight = kOutLeft | kOutRight | kOutTop | kOutBottom | kOutBehind
};

static const float kCameraNear = 1.0f; /* world units; also keeps oow <= 1 for the W-buffer */
static const float kLightNear = 0.5f;  /* world units */
static const float kAmbient = 0.30f;
static const float kShadowAlpha = 170.0f; /* iterated alpha of the shadow pass, 0..255 */

typedef struct {
  float x, y, z;
} Vec3;

typedef struct {
  Vec3 world;        /* world space, y up */
  Vec3 normal;       /* world space, unit length */
  Vec3 albedo;       /* 0..255 per channel */
  float lx, ly;      /* light screen: texels 0..256, y down (steps 1 and 3) */
  float sx, sy, oow; /* camera screen: pixels, y down; oow = 1/w, w = camera depth (step 4) */
  float r, g, b;     /* lit vertex colour 0..255, for Gouraud shading (step 4) */
  float u, v;        /* shadow texture coordinates: texels 0..256 (step 3) */
  unsigned flags;    /* kClipZ | kOut* */
} Vertex;

typedef struct {
  const char *name;
  int n_vertices, n_triangles;
  Vertex vertex_array[kMaxVertices];
  int triangle_array[3 * kMaxTriangles]; /* counter-clockwise seen from outside */
  unsigned char flag_array[kMaxTriangles]; /* 1 = receives the shadow this frame (step 3) */
} Mesh;

/* A pinhole view: the camera (screen in pixels) or the light (screen in texels). */
typedef struct {
  Vec3 eye, right, up, forward; /* world space; forward is the viewing direction */
  float focal;                  /* screen units per unit of x/w */
  float cx, cy;                 /* screen centre */
} View;

typedef struct {
  double ms[5];
  int shadow_triangles;
} StepTimes;

static Mesh figure_mesh; /* the caster: a crude figure of six boxes */
static Mesh floor_mesh;  /* receiver */
static Mesh box_mesh;    /* receiver: the shadow falls across it */
static FxU16 shadow_bitmap[kShadowSize * kShadowSize]; /* step 2: 565 words read back as 4444 */
static int glide_errors;

/* ---- small vector helpers ---- */

static Vec3 vec3(float x, float y, float z) {
  Vec3 v;
  v.x = x;
  v.y = y;
  v.z = z;
  return v;
}
static Vec3 add(Vec3 a, Vec3 b) { return vec3(a.x + b.x, a.y + b.y, a.z + b.z); }
static Vec3 sub(Vec3 a, Vec3 b) { return vec3(a.x - b.x, a.y - b.y, a.z - b.z); }
static Vec3 scale(Vec3 a, float s) { return vec3(a.x * s, a.y * s, a.z * s); }
static float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static Vec3 cross(Vec3 a, Vec3 b) {
  return vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static Vec3 normalize(Vec3 a) { return scale(a, 1.0f / sqrtf(dot(a, a))); }
static Vec3 rotate_y(Vec3 a, float radians) {
  const float c = cosf(radians), s = sinf(radians);
  return vec3(c * a.x + s * a.z, a.y, -s * a.x + c * a.z);
}

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec * 1000.0 + (double)t.tv_nsec / 1.0e6;
}

/* ---- the scene, built once ---- */

/* A grid of ns x nt quads from `corner` along edge_s and edge_t; edge_s x edge_t points along
 * `normal`, so the triangles wind counter-clockwise seen from the front. */
static void add_patch(Mesh *m, Vec3 corner, Vec3 edge_s, Vec3 edge_t, Vec3 normal, Vec3 albedo,
                      int ns, int nt) {
  const int first = m->n_vertices;
  int i, j;
  if (m->n_vertices + (ns + 1) * (nt + 1) > kMaxVertices ||
      m->n_triangles + 2 * ns * nt > kMaxTriangles) {
    fprintf(stderr, "article_port: mesh %s is too large\n", m->name);
    exit(1);
  }
  for (j = 0; j <= nt; ++j) {
    for (i = 0; i <= ns; ++i) {
      Vertex *v = &m->vertex_array[m->n_vertices++];
      const Vec3 along_s = scale(edge_s, (float)i / (float)ns);
      const Vec3 along_t = scale(edge_t, (float)j / (float)nt);
      memset(v, 0, sizeof *v);
      v->world = add(corner, add(along_s, along_t));
      v->normal = normal;
      v->albedo = albedo;
    }
  }
  for (j = 0; j < nt; ++j) {
    for (i = 0; i < ns; ++i) {
      const int a = first + j * (ns + 1) + i, b = a + 1, c = b + ns + 1, d = a + ns + 1;
      int *t = &m->triangle_array[3 * m->n_triangles];
      t[0] = a, t[1] = b, t[2] = c;
      t[3] = a, t[4] = c, t[5] = d;
      m->n_triangles += 2;
    }
  }
}

/* A box with half-sizes `half`, turned by `yaw` about the vertical through `center` and then
 * moved by `offset` (world space); each face cut into n x n quads. */
static void add_box(Mesh *m, Vec3 center, Vec3 half, float yaw, Vec3 offset, Vec3 albedo, int n) {
  /* Face normal and two tangents with s x t = normal. */
  static const float kFaces[6][3][3] = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},
  };
  int f;
  for (f = 0; f < 6; ++f) {
    const Vec3 nrm = vec3(kFaces[f][0][0], kFaces[f][0][1], kFaces[f][0][2]);
    const Vec3 s = vec3(kFaces[f][1][0], kFaces[f][1][1], kFaces[f][1][2]);
    const Vec3 t = vec3(kFaces[f][2][0], kFaces[f][2][1], kFaces[f][2][2]);
    const float hn = fabsf(dot(nrm, half)), hs = fabsf(dot(s, half)), ht = fabsf(dot(t, half));
    const Vec3 corner = sub(sub(add(center, scale(nrm, hn)), scale(s, hs)), scale(t, ht));
    add_patch(m, add(rotate_y(corner, yaw), offset), rotate_y(scale(s, 2.0f * hs), yaw),
              rotate_y(scale(t, 2.0f * ht), yaw), rotate_y(nrm, yaw), albedo, n, n);
  }
}

static void build_scene(void) {
  const Vec3 skin = vec3(230, 190, 150), shirt = vec3(60, 110, 210), trousers = vec3(70, 70, 90);
  const Vec3 at = vec3(0.0f, 0.0f, 0.0f);
  const float yaw = 0.35f;

  figure_mesh.name = "figure";
  add_box(&figure_mesh, vec3(-0.25f, 0.80f, 0), vec3(0.17f, 0.80f, 0.17f), yaw, at, trousers, 1);
  add_box(&figure_mesh, vec3(0.25f, 0.80f, 0), vec3(0.17f, 0.80f, 0.17f), yaw, at, trousers, 1);
  add_box(&figure_mesh, vec3(0.0f, 2.30f, 0), vec3(0.50f, 0.70f, 0.25f), yaw, at, shirt, 1);
  add_box(&figure_mesh, vec3(0.0f, 3.30f, 0), vec3(0.25f, 0.28f, 0.25f), yaw, at, skin, 1);
  add_box(&figure_mesh, vec3(-0.66f, 2.25f, 0), vec3(0.14f, 0.65f, 0.14f), yaw, at, shirt, 1);
  add_box(&figure_mesh, vec3(1.10f, 2.86f, 0), vec3(0.60f, 0.13f, 0.13f), yaw, at, skin, 1);

  floor_mesh.name = "floor";
  add_patch(&floor_mesh, vec3(-9.0f, 0.0f, 9.0f), vec3(18.0f, 0, 0), vec3(0, 0, -18.0f),
            vec3(0, 1, 0), vec3(200, 200, 185), 24, 24);

  box_mesh.name = "box";
  add_box(&box_mesh, vec3(0, 0.55f, 0), vec3(0.90f, 0.55f, 0.90f), 0.2f, vec3(2.3f, 0, -2.0f),
          vec3(210, 120, 60), 6);
}

/* ---- views and CPU transforms ---- */

static View make_view(Vec3 eye, Vec3 target, float focal, float cx, float cy) {
  View view;
  view.eye = eye;
  view.forward = normalize(sub(target, eye));
  view.right = normalize(cross(view.forward, vec3(0, 1, 0)));
  view.up = cross(view.right, view.forward);
  view.focal = focal;
  view.cx = cx;
  view.cy = cy;
  return view;
}

/* View space of a world point: x right, y up, w = depth along the view direction. */
static void to_view(const View *view, Vec3 p, float *x, float *y, float *w) {
  const Vec3 d = sub(p, view->eye);
  *x = dot(d, view->right);
  *y = dot(d, view->up);
  *w = dot(d, view->forward);
}

/* The light is aimed at the caster; its lens is chosen so the caster fills the shadow texture
 * but keeps kShadowMargin empty texels on every side (the article's "clean borders"). */
static void fit_light_lens(View *light, const Mesh *caster) {
  float widest = 1e-6f, x, y, w;
  int i;
  for (i = 0; i < caster->n_vertices; ++i) {
    to_view(light, caster->vertex_array[i].world, &x, &y, &w);
    if (w > kLightNear) {
      widest = fmaxf(widest, fmaxf(fabsf(x / w), fabsf(y / w)));
    }
  }
  light->focal = (0.5f * kShadowSize - kShadowMargin) / widest;
}

/* Light screen position of every vertex (texels, y down) and its outside-the-light flags. */
static void transform_to_light(Mesh *m, const View *light) {
  int i;
  for (i = 0; i < m->n_vertices; ++i) {
    Vertex *v = &m->vertex_array[i];
    float x, y, w;
    to_view(light, v->world, &x, &y, &w);
    v->flags &= ~(unsigned)kOutOfLight;
    if (w < kLightNear) {
      v->lx = v->ly = 0.0f;
      v->flags |= kOutBehind;
      continue;
    }
    v->lx = light->cx + light->focal * x / w;
    v->ly = light->cy - light->focal * y / w;
    if (v->lx < 0.0f) v->flags |= kOutLeft;
    if (v->lx > (float)kShadowSize) v->flags |= kOutRight;
    if (v->ly < 0.0f) v->flags |= kOutTop;
    if (v->ly > (float)kShadowSize) v->flags |= kOutBottom;
  }
}

/* Camera screen position (pixels, y down) and 1/w of every vertex, and its CLIPZ flag. */
static void transform_to_camera(Mesh *m, const View *camera) {
  int i;
  for (i = 0; i < m->n_vertices; ++i) {
    Vertex *v = &m->vertex_array[i];
    float x, y, w;
    to_view(camera, v->world, &x, &y, &w);
    v->flags &= ~(unsigned)kClipZ;
    if (w < kCameraNear) {
      v->flags |= kClipZ;
      continue;
    }
    v->oow = 1.0f / w;
    v->sx = camera->cx + camera->focal * x * v->oow;
    v->sy = camera->cy - camera->focal * y * v->oow;
  }
}

/* Gouraud colours: ambient plus a diffuse spotlight with a soft cone (world space). */
static void light_vertices(Mesh *m, const View *light) {
  const float cos_inner = 0.96f, cos_outer = 0.84f;
  int i;
  for (i = 0; i < m->n_vertices; ++i) {
    Vertex *v = &m->vertex_array[i];
    const Vec3 to_light = normalize(sub(light->eye, v->world));
    const float cone = -dot(to_light, light->forward);
    const float spot = fminf(1.0f, fmaxf(0.0f, (cone - cos_outer) / (cos_inner - cos_outer)));
    const float k = kAmbient + (1.0f - kAmbient) * spot * fmaxf(0.0f, dot(v->normal, to_light));
    v->r = v->albedo.x * k;
    v->g = v->albedo.y * k;
    v->b = v->albedo.z * k;
  }
}

/* ---- Listing 4: the settings made once at start-up ---- */

static void glide_settings(void) {
  grCullMode(GR_CULL_POSITIVE); /* front faces are counter-clockwise on the y-down screen */
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthBufferFunction(GR_CMP_LEQUAL); /* step 5 redraws step 4's triangles at equal depth */
  grDepthMask(FXTRUE);
  grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR);
  grGammaCorrectionValue(0.8f);
  grDitherMode(GR_DITHER_DISABLE); /* red 240 must land in the frame buffer as exactly 11110b */
}

/* ---- Step 1: the caster, flat, from the light, into a 256x256 corner of the back buffer ---- */

static void render_caster_from_light(Mesh *caster, const View *light) {
  GrVertex a, b, c;
  int i;
  transform_to_light(caster, light);
  grClipWindow(0, 0, kShadowSize, kShadowSize);
  grDepthBufferMode(GR_DEPTHBUFFER_DISABLE); /* only the silhouette matters */
  grCullMode(GR_CULL_POSITIVE);
  grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                 GR_COMBINE_OTHER_NONE, FXFALSE);
  grConstantColorValue(0x00F00000); /* ARGB: red 240 = 565 word 0xF000 = ARGB_4444 black, A 15 */
  grBufferClear(0x00000000, 0, GR_WDEPTHVALUE_FARTHEST);
  memset(&a, 0, sizeof a);
  memset(&b, 0, sizeof b);
  memset(&c, 0, sizeof c);
  for (i = 0; i < caster->n_triangles; ++i) {
    const Vertex *v1 = &caster->vertex_array[caster->triangle_array[3 * i + 0]];
    const Vertex *v2 = &caster->vertex_array[caster->triangle_array[3 * i + 1]];
    const Vertex *v3 = &caster->vertex_array[caster->triangle_array[3 * i + 2]];
    if ((v1->flags | v2->flags | v3->flags) & kOutBehind) continue;
    a.x = v1->lx, a.y = v1->ly; /* light screen, texels */
    b.x = v2->lx, b.y = v2->ly;
    c.x = v3->lx, c.y = v3->ly;
    grDrawTriangle(&a, &b, &c);
  }
}

/* ---- Step 2 (Listing 5): read the silhouette back and download it as an ARGB_4444 texture ---- */

static void load_texture_on_voodoo(void) {
  GrTexInfo info;
  info.smallLod = GR_LOD_256;
  info.largeLod = GR_LOD_256;
  info.aspectRatio = GR_ASPECT_1x1;
  info.format = GR_TEXFMT_ARGB_4444; /* same 16 bits as 565: 0xF000 reads as A=15, RGB=0 */
  info.data = shadow_bitmap;
  grTexDownloadMipMap(GR_TMU0, grTexMinAddress(GR_TMU0), GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, grTexMinAddress(GR_TMU0), GR_MIPMAPLEVELMASK_BOTH, &info);
}

static void make_shadow_texture(void) {
  if (!grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, kShadowSize, kShadowSize,
                       kShadowSize * sizeof shadow_bitmap[0], shadow_bitmap)) {
    return; /* reported through the error callback */
  }
  load_texture_on_voodoo();
}

/* ---- Step 3 (Listing 2): texture coordinates on a receiver, and which triangles get them ---- */

static int cast_on_mesh(Mesh *m, const View *light) {
  int i, flagged = 0;
  transform_to_light(m, light);
  for (i = 0; i < m->n_triangles; ++i) {
    Vertex *v1 = &m->vertex_array[m->triangle_array[3 * i + 0]];
    Vertex *v2 = &m->vertex_array[m->triangle_array[3 * i + 1]];
    Vertex *v3 = &m->vertex_array[m->triangle_array[3 * i + 2]];
    /* Signed area on the light's y-down screen; > 0 means the triangle faces away. */
    const float area =
        (v2->lx - v1->lx) * (v3->ly - v1->ly) - (v3->lx - v1->lx) * (v2->ly - v1->ly);
    m->flag_array[i] = 0;
    if (area > 0.0f) continue;
    if ((v1->flags & v2->flags & v3->flags & kOutOfLight) != 0) continue; /* wholly outside */
    /* The light screen is the 256x256 texture: s,t in Glide's 0..256 texel units are x,y. */
    v1->u = v1->lx, v1->v = v1->ly;
    v2->u = v2->lx, v2->v = v2->ly;
    v3->u = v3->lx, v3->v = v3->ly;
    m->flag_array[i] = 1;
    ++flagged;
  }
  return flagged;
}

/* ---- Step 4: the scene from the camera, Gouraud-shaded and W-buffered ---- */

static void draw_mesh_gouraud(const Mesh *m) {
  GrVertex a, b, c;
  GrVertex *out[3];
  int i, k;
  out[0] = &a, out[1] = &b, out[2] = &c;
  memset(&a, 0, sizeof a);
  memset(&b, 0, sizeof b);
  memset(&c, 0, sizeof c);
  for (i = 0; i < m->n_triangles; ++i) {
    const Vertex *in[3];
    for (k = 0; k < 3; ++k) in[k] = &m->vertex_array[m->triangle_array[3 * i + k]];
    if ((in[0]->flags | in[1]->flags | in[2]->flags) & kClipZ) continue;
    for (k = 0; k < 3; ++k) {
      out[k]->x = in[k]->sx; /* camera screen, pixels */
      out[k]->y = in[k]->sy;
      out[k]->oow = in[k]->oow;
      out[k]->r = in[k]->r;
      out[k]->g = in[k]->g;
      out[k]->b = in[k]->b;
    }
    guDrawTriangleWithClip(&a, &b, &c);
  }
}

static void render_scene(const View *camera, const View *light) {
  Mesh *meshes[3];
  int i;
  meshes[0] = &floor_mesh, meshes[1] = &box_mesh, meshes[2] = &figure_mesh;
  for (i = 0; i < 3; ++i) {
    transform_to_camera(meshes[i], camera);
    light_vertices(meshes[i], light);
  }
  grClipWindow(0, 0, kScreenWidth, kScreenHeight);
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER); /* back on after step 1 */
  grDepthBufferFunction(GR_CMP_LEQUAL);
  grDepthMask(FXTRUE);
  guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
  grBufferClear(0x00283040, 0, GR_WDEPTHVALUE_FARTHEST);
  for (i = 0; i < 3; ++i) draw_mesh_gouraud(meshes[i]);
}

/* ---- Step 5 (Listing 3): the flagged triangles again, darkened through the shadow texture ---- */

static void render_shadow_on_mesh(const Mesh *m) {
  GrVertex v1, v2, v3;
  GrVertex *out[3];
  int i, k;

  /* The half of Listing 3 the magazine did not print: our own combine set-up. */
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL); /* TMU output = texel (default: 0) */
  grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_NONE,
                 GR_COMBINE_OTHER_TEXTURE, FXFALSE); /* colour = texel RGB: black */
  grAlphaCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_LOCAL,
                 GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE,
                 FXFALSE); /* alpha = texel alpha * iterated alpha */
  grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE,
                       GR_BLEND_ZERO);
  grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP); /* no tiled copies */

  out[0] = &v1, out[1] = &v2, out[2] = &v3;
  memset(&v1, 0, sizeof v1);
  memset(&v2, 0, sizeof v2);
  memset(&v3, 0, sizeof v3);
  for (i = 0; i < m->n_triangles; ++i) {
    const Vertex *in[3];
    if (m->flag_array[i] == 0) continue;
    for (k = 0; k < 3; ++k) in[k] = &m->vertex_array[m->triangle_array[3 * i + k]];
    if ((in[0]->flags | in[1]->flags | in[2]->flags) & kClipZ) continue;
    for (k = 0; k < 3; ++k) {
      out[k]->x = in[k]->sx; /* camera screen, pixels: the same vertices as step 4 */
      out[k]->y = in[k]->sy;
      out[k]->oow = in[k]->oow;
      out[k]->tmuvtx[0].sow = in[k]->u * in[k]->oow; /* texels 0..256, times 1/w */
      out[k]->tmuvtx[0].tow = in[k]->v * in[k]->oow;
      out[k]->r = out[k]->g = out[k]->b = 255.0f;
      out[k]->a = kShadowAlpha; /* the shadow's strength */
    }
    guDrawTriangleWithClip(&v1, &v2, &v3);
  }

  /* As Listing 3 ends: texturing and blending off again. */
  grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                 GR_COMBINE_OTHER_NONE, FXFALSE);
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
}

/* ---- one frame: the five steps, timed ---- */

/* grSstIdle ends each step that hands work to the chip, so that each time includes its own
 * rendering rather than the next step's wait for it. */
static StepTimes render_frame(const View *camera, View *light) {
  StepTimes times;
  double t = now_ms(), t0;

  fit_light_lens(light, &figure_mesh);
  render_caster_from_light(&figure_mesh, light); /* step 1 */
  grSstIdle();
  t0 = t, t = now_ms(), times.ms[0] = t - t0;

  make_shadow_texture(); /* step 2 */
  grSstIdle();
  t0 = t, t = now_ms(), times.ms[1] = t - t0;

  times.shadow_triangles = cast_on_mesh(&floor_mesh, light); /* step 3 */
  times.shadow_triangles += cast_on_mesh(&box_mesh, light);
  t0 = t, t = now_ms(), times.ms[2] = t - t0;

  render_scene(camera, light); /* step 4 */
  grSstIdle();
  t0 = t, t = now_ms(), times.ms[3] = t - t0;

  render_shadow_on_mesh(&floor_mesh); /* step 5 */
  render_shadow_on_mesh(&box_mesh);
  grSstIdle();
  t0 = t, t = now_ms(), times.ms[4] = t - t0;
  return times;
}

/* ---- start-up, the frame loop, output ---- */

static void on_glide_error(const char *message, FxBool fatal) {
  fprintf(stderr, "article_port: glide error%s: %s\n", fatal ? " (fatal)" : "", message);
  ++glide_errors;
}

static void usage(FILE *to) {
  fprintf(to,
          "usage: article_port [-n FRAMES] [OUT.png]\n"
          "Renders Hubert Nguyen's projected shadow texture (Game Developer, 1999) with\n"
          "Glide 2.x: a figure casting its shadow on a floor and across a box. Each frame runs\n"
          "the article's five steps and prints their times in milliseconds; the light swings a\n"
          "little from frame to frame. The last frame is written as PNG (default\n"
          "article_port.png).\n"
          "  -n FRAMES  number of frames to render (default 1)\n"
          "  -h, --help this text\n");
}

int main(int argc, char **argv) {
  const char *out = "article_port.png";
  int frames = 1, frame, i;
  GrHwConfiguration hw;
  View camera, light;
  const Vec3 light_start = vec3(-7.0f, 9.0f, 6.0f); /* world space */
  const Vec3 light_target = vec3(0.0f, 1.8f, 0.0f); /* the figure's middle: the light follows it */

  for (i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "-h") == 0 || strcmp(argv[i], "--help") == 0) {
      usage(stdout);
      return 0;
    } else if (strcmp(argv[i], "-n") == 0 && i + 1 < argc) {
      char *end;
      const long n = strtol(argv[++i], &end, 10);
      if (*end != '\0' || n < 1 || n > 100000) {
        fprintf(stderr, "article_port: -n wants a frame count from 1 to 100000\n");
        return 2;
      }
      frames = (int)n;
    } else if (argv[i][0] == '-') {
      usage(stderr);
      return 2;
    } else {
      out = argv[i];
    }
  }

  build_scene();
  grGlideInit();
  grErrorSetCallback(on_glide_error);
  if (!grSstQueryHardware(&hw)) {
    fprintf(stderr, "article_port: no Voodoo found\n");
    return 1;
  }
  grSstSelect(0);
  if (!grSstWinOpen(0, GR_RESOLUTION_640x480, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                    GR_ORIGIN_UPPER_LEFT, 2, 1)) {
    fprintf(stderr, "article_port: grSstWinOpen failed\n");
    grGlideShutdown();
    return 1;
  }
  glide_settings();

  camera = make_view(vec3(2.5f, 5.5f, 8.5f), vec3(1.3f, 1.0f, -1.4f), 560.0f,
                     0.5f * kScreenWidth, 0.5f * kScreenHeight);
  printf("article_port: %d frame(s), %d+%d receiver triangles, %d caster triangles\n", frames,
         floor_mesh.n_triangles, box_mesh.n_triangles, figure_mesh.n_triangles);
  printf("steps: 1 caster from the light, 2 LFB read + texture download, 3 CastOnMesh,"
         " 4 scene, 5 shadow pass\n");
  for (frame = 0; frame < frames; ++frame) {
    StepTimes t;
    double total = 0.0;
    int s;
    const float swing = 0.35f * sinf(0.15f * (float)frame); /* radians about the vertical */
    light = make_view(rotate_y(light_start, swing), light_target, 1.0f,
                      0.5f * kShadowSize, 0.5f * kShadowSize);
    t = render_frame(&camera, &light);
    grBufferSwap(1);
    for (s = 0; s < 5; ++s) total += t.ms[s];
    printf("frame %d: step1 %.3f ms  step2 %.3f ms  step3 %.3f ms  step4 %.3f ms  step5 %.3f ms"
           "  total %.3f ms  (%d shadow triangles)\n",
           frame, t.ms[0], t.ms[1], t.ms[2], t.ms[3], t.ms[4], total, t.shadow_triangles);
  }

  if (!glideShimWritePng(GR_BUFFER_FRONTBUFFER, out)) {
    grGlideShutdown();
    return 1;
  }
  printf("article_port: wrote %s (640x480, backend %s)\n", out, glideShimBackendName());
  if (glide_errors > 0) {
    fprintf(stderr, "article_port: %d Glide error(s), the last %s: %s\n", glide_errors,
            glideShimErrorName(glideShimGetLastError()), glideShimGetLastErrorMessage());
  }
  grGlideShutdown();
  return glide_errors > 0 ? 1 : 0;
}
