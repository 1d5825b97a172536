// The PipelineKey: what about the context's state changes the generated shader's code (the
// combine units' shapes, filters, tests, fog, dither; on the fast paths the compiled-in sources),
// its defines (also the program cache's key), the run-time selectors of a combine unit, and the
// GLIDESHIM_PLAIN_GL fidelity knobs.
#include "gl/shader_source.h"
#include "gl/shader_stages.h"

#include <algorithm>
#include <sstream>

namespace glide_shim {
namespace {

using shader_stages::has_product;

bool factor_reads_texture(GrCombineFactor_t factor) {
  const int source = static_cast<int>(factor) & 0x7;
  return source == GR_COMBINE_FACTOR_TEXTURE_ALPHA || source == GR_COMBINE_FACTOR_TEXTURE_RGB;
}

UnitShape shape(GrCombineFunction_t function, GrCombineFactor_t factor) {
  return {function, has_product(function) ? factor : GR_COMBINE_FACTOR_ZERO};
}

int other_index(GrCombineOther_t other) {  // as unit_uniforms: iterated 0, texture 1, constant 2
  return other == GR_COMBINE_OTHER_TEXTURE ? 1 : other == GR_COMBINE_OTHER_CONSTANT ? 2 : 0;
}

}  // namespace

int parse_fidelity_knobs(const char *list, std::string &unknown) {
  unknown.clear();
  if (list == nullptr) return 0;
  const std::string text = list;
  int knobs = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    const std::string name = text.substr(start, end - start);
    if (name == "write") knobs |= kPlainWrite;
    if (name == "iterators") knobs |= kPlainIterators;
    if (name == "combine") knobs |= kPlainCombine;
    if (name == "bilinear") knobs |= kPlainBilinear;
    if (name == "all") knobs |= kPlainWrite | kPlainIterators | kPlainCombine | kPlainBilinear;
    if (!name.empty() && name != "write" && name != "iterators" && name != "combine" && name != "bilinear" &&
        name != "all") {
      unknown += (unknown.empty() ? "'" : ", '") + name + "'";
    }
    start = end + 1;
  }
  return knobs;
}

UnitUniforms unit_uniforms(const CombineUnit &unit) {
  UnitUniforms u;
  u.select[0] = unit.local == GR_COMBINE_LOCAL_CONSTANT ? 1.0f : 0.0f;
  u.select[1] = unit.invert ? 1.0f : 0.0f;
  const int other = unit.other == GR_COMBINE_OTHER_TEXTURE    ? 1
                    : unit.other == GR_COMBINE_OTHER_CONSTANT ? 2
                                                              : 0;
  u.other[other] = 1.0f;
  return u;
}

bool reads_texture(const ColorPathState &path) {
  return path.color.other == GR_COMBINE_OTHER_TEXTURE ||
         path.alpha.other == GR_COMBINE_OTHER_TEXTURE || factor_reads_texture(path.color.factor) ||
         factor_reads_texture(path.alpha.factor);
}

PipelineKey pipeline_key(const GlideContext &context, bool fast) {
  PipelineKey key;
  const ColorPathState &path = context.color_path;
  key.color = shape(path.color.function, path.color.factor);
  key.alpha_controls_itrgb = path.alpha_controls_itrgb;
  key.alpha = shape(path.alpha.function, path.alpha.factor);
  key.texture = reads_texture(path);
  if (key.texture) {
    const TexCombineUnit &tmu = context.tmu.combine;
    key.tmu_rgb = shape(tmu.rgb_function, tmu.rgb_factor);
    key.tmu_alpha = shape(tmu.alpha_function, tmu.alpha_factor);
    // MAME's and 86Box's TMU: the magnification filter when the clamped LOD equals lodmin,
    // else the minification filter.
    const TmuState &unit = context.tmu;
    key.mag_bilinear = unit.mag_filter == GR_TEXTUREFILTER_BILINEAR;
    key.mipmap = unit.mipmap_mode != GR_MIPMAP_DISABLE && unit.source.valid &&
                 unit.source.small_lod != unit.source.large_lod;
    key.min_bilinear = key.mipmap ? unit.min_filter == GR_TEXTUREFILTER_BILINEAR : key.mag_bilinear;
    key.lod_dither = key.mipmap && unit.lod_dither;
    key.wrap_s = context.tmu.clamp_s == GR_TEXTURECLAMP_WRAP;
    key.wrap_t = context.tmu.clamp_t == GR_TEXTURECLAMP_WRAP;
  }
  key.chroma_key = context.chroma.mode == GR_CHROMAKEY_ENABLE;
  key.alpha_test = context.blend.alpha_test_function;
  key.blending = !(context.blend.rgb_src == GR_BLEND_ONE && context.blend.rgb_dst == GR_BLEND_ZERO);
  key.dither = context.raster.dither;
  key.fog = context.fog.mode & 0xFF;
  key.plain = context.fidelity_knobs;
  if (fast) {
    key.fast = key.sources = true;
    key.texel_fetch = key.texture && context.tmu.source.valid;
    const int height = context.texture_target.active ? context.texture_target.side
                                                     : context.display.height;
    key.rows_mod4 = key.dither != GR_DITHER_DISABLE ? height & 3 : 0;
    key.color_local = path.color.local == GR_COMBINE_LOCAL_CONSTANT ? 1 : 0;
    key.color_other = other_index(path.color.other);
    key.color_invert = path.color.invert;
    key.alpha_local = path.alpha.local == GR_COMBINE_LOCAL_CONSTANT ? 1 : 0;
    key.alpha_other = other_index(path.alpha.other);
    key.alpha_invert = path.alpha.invert;
    if (key.texture) {
      key.tmu_rgb_invert = context.tmu.combine.rgb_invert;
      key.tmu_alpha_invert = context.tmu.combine.alpha_invert;
    }
  }
  return key;
}

PipelineKey PipelineKey::without_sources() const {
  PipelineKey key = *this;
  key.sources = false;
  key.color_local = key.color_other = key.alpha_local = key.alpha_other = 0;
  key.color_invert = key.alpha_invert = key.tmu_rgb_invert = key.tmu_alpha_invert = false;
  key.level_compiled = false;
  key.level_width = key.level_height = key.level_lod = key.lod_min = 0;
  return key;
}

std::string PipelineKey::defines() const {
  std::ostringstream s;
  for (const UnitShape *unit : {&color, &alpha, &tmu_rgb, &tmu_alpha}) {
    s << "unit " << unit->function << '/' << unit->factor << ' ';
  }
  s << "texture " << texture << " filter " << mag_bilinear << min_bilinear << " mipmap " << mipmap
    << lod_dither << " wrap " << wrap_s << wrap_t
    << " itrgb " << alpha_controls_itrgb << " chroma " << chroma_key << " alpha_test " << alpha_test << " blend " << blending
    << " dither " << dither << " fog " << fog;
  if (plain != 0) s << " plain " << plain;
  if (fast) s << " fast " << texel_fetch << rows_mod4 << line_rows;
  if (sources) {
    s << " sources " << color_local << color_other << color_invert
      << alpha_local << alpha_other << alpha_invert << tmu_rgb_invert << tmu_alpha_invert;
  }
  if (level_compiled) {
    s << " level " << level_width << 'x' << level_height << " lod " << level_lod << " lodmin "
      << lod_min;
  }
  return s.str();
}

}  // namespace glide_shim
