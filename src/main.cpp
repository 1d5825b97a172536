// glideshadows: the command-line tool. `demo` renders the fight headless with shadows; `render`
// renders a scene file and optionally its shadow mask. Every subcommand has --help.
#include "fight_scene.h"
#include "figures.h"
#include "ground_truth.h"
#include "metrics.h"
#include "plot.h"
#include "speed_error.h"
#include "projected_shadow.h"
#include "scene.h"
#include "technique.h"

#include <CLI/CLI.hpp>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <glide.h>
#include <glide_shim.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct TechniqueChoice {
  std::string name = "projected";
  bool direct_path = false, point = false, affine = false, auto_size = false;
  std::string alpha = "constant";
  float bias_slope = 1.0f, bias_units = 4.0f;  // depth-map polygon offset
  bool nearest = false;                       // depth-map filtering
  std::string volume = "auto";                // stencil-volume mode
};

void add_technique_options(CLI::App &command, TechniqueChoice &choice, int &shadow_size) {
  command.add_option("--technique", choice.name, "shadow technique")
      ->check(CLI::IsMember(gs::technique_names()))
      ->capture_default_str();
  command.add_option("--shadow-size", shadow_size,
                     "shadow map side in texels; 512 is drawn as four 256x256 textures (a Voodoo 1 limit)")
      ->check(CLI::IsMember({32, 64, 128, 256, 512}))
      ->capture_default_str();
  command.add_flag("--direct-path", choice.direct_path,
                   "step 1 renders straight into texture memory instead of the back buffer + LFB read");
  command.add_flag("--point", choice.point, "point-sample the shadow texture (default bilinear)");
  command.add_flag("--affine", choice.affine,
                   "divide (s,t) per vertex as the article's listing does (default per pixel)");
  command.add_flag("--auto-size", choice.auto_size,
                   "texture size follows the caster's size on screen (the article's LOD idea)");
  command.add_option("--alpha", choice.alpha, "iterated alpha: constant (170) or distance")
      ->check(CLI::IsMember({"constant", "distance"}))
      ->capture_default_str();
  command.add_option("--bias-slope", choice.bias_slope, "depth-map: glPolygonOffset factor")
      ->check(CLI::Range(0.0f, 100.0f))
      ->capture_default_str();
  command.add_option("--bias-units", choice.bias_units, "depth-map: glPolygonOffset units")
      ->check(CLI::Range(0.0f, 10000.0f))
      ->capture_default_str();
  command.add_flag("--nearest", choice.nearest,
                   "depth-map: nearest comparison instead of percentage-closer filtering");
  command.add_option("--volume", choice.volume, "stencil-volume: auto, zpass or zfail")
      ->check(CLI::IsMember({"auto", "zpass", "zfail"}))
      ->capture_default_str();
}

gs::TechniqueOptions technique_options(const TechniqueChoice &choice, int shadow_size) {
  gs::TechniqueOptions all;
  gs::ProjectedShadowOptions &options = all.projected;
  options.size = shadow_size;
  options.auto_size = choice.auto_size;
  options.bilinear = !choice.point;
  options.direct_path = choice.direct_path;
  options.chroma_key = choice.name == "projected-chroma";
  options.projective = !choice.affine;
  options.alpha = choice.alpha == "distance" ? gs::ShadowAlpha::Distance : gs::ShadowAlpha::Constant;
  all.depth_bias_slope = choice.bias_slope;
  all.depth_bias_units = choice.bias_units;
  all.depth_map_linear = !choice.nearest;
  using Mode = gs::TechniqueOptions::VolumeMode;
  all.volume_mode = choice.volume == "zpass"   ? Mode::ZPass
                    : choice.volume == "zfail" ? Mode::ZFail
                                               : Mode::Automatic;
  return all;
}

bool open_window(int width, int height) {
  grGlideInit();
  if (!glideShimSetWindowSize(width, height) ||
      !grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                    GR_ORIGIN_UPPER_LEFT, 2, 1)) {
    std::fprintf(stderr, "glideshadows: cannot open a %dx%d Glide window: %s\n", width, height,
                 glideShimGetLastErrorMessage());
    return false;
  }
  grGammaCorrectionValue(0.8f);  // Listing 4
  return true;
}

// "WxH", two decimal integers; a number too long for an int fails like any other bad text.
bool parse_size(const std::string &text, int &width, int &height) {
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string::npos) return false;
  const char *begin = text.data(), *middle = begin + x, *end = begin + text.size();
  const std::from_chars_result w = std::from_chars(begin, middle, width);
  const std::from_chars_result h = std::from_chars(middle + 1, end, height);
  if (w.ec != std::errc() || w.ptr != middle || h.ec != std::errc() || h.ptr != end) return false;
  return width >= 64 && height >= 64 && width <= 2048 && height <= 2048;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

void print_step_table(const std::vector<gs::FrameReport> &reports) {
  std::vector<double> total;
  for (const gs::FrameReport &r : reports) total.push_back(r.total_ms);
  const double frame = median(total);
  std::printf("\nStep timing (median of %zu frames, each step synchronised):\n", reports.size());
  for (std::size_t step = 0; step < reports.front().steps.size(); ++step) {
    std::vector<double> values;
    for (const gs::FrameReport &r : reports) values.push_back(r.steps[step].second);
    const double ms = median(values);
    std::printf("  step %-44s %7.2f ms  %5.1f%%\n", reports.front().steps[step].first.c_str(), ms,
                frame > 0 ? 100.0 * ms / frame : 0.0);
  }
  std::printf("  %-49s %7.2f ms  (%.0f frames/s)\n", "whole frame", frame, frame > 0 ? 1000.0 / frame : 0.0);
}

bool write_contact_sheet(const std::vector<std::string> &frames, const std::string &path) {
  const std::size_t count = std::min<std::size_t>(frames.size(), 16);
  if (count == 0) return true;
  const int columns = 4;
  const int rows = static_cast<int>((count + columns - 1) / columns);
  OIIO::ImageBuf first(frames[0]);
  if (!first.read()) return false;
  const int w = first.spec().width / 2, h = first.spec().height / 2;
  OIIO::ImageBuf sheet(OIIO::ImageSpec(w * columns, h * rows, 3, OIIO::TypeDesc::UINT8));
  OIIO::ImageBufAlgo::zero(sheet);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t index = i * frames.size() / count;  // spread over the whole run
    OIIO::ImageBuf frame(frames[index]);
    OIIO::ImageBuf small = OIIO::ImageBufAlgo::resize(frame, "", 0, OIIO::ROI(0, w, 0, h, 0, 1, 0, 3));
    const int x = static_cast<int>(i % columns) * w, y = static_cast<int>(i / columns) * h;
    OIIO::ImageBufAlgo::paste(sheet, x, y, 0, 0, small);
  }
  return sheet.write(path);
}

bool write_gif(const std::vector<std::string> &frames, const std::string &path, int fps) {
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
  if (!out || !out->supports("multiimage") || frames.empty()) return false;
  std::vector<OIIO::ImageSpec> specs;
  std::vector<OIIO::ImageBuf> images;
  for (const std::string &file : frames) {
    OIIO::ImageBuf frame(file);
    if (!frame.read()) return false;
    OIIO::ImageBuf small = OIIO::ImageBufAlgo::resize(
        frame, "", 0, OIIO::ROI(0, frame.spec().width / 2, 0, frame.spec().height / 2, 0, 1, 0, 3));
    OIIO::ImageSpec spec = small.spec();
    spec.attribute("FramesPerSecond", OIIO::TypeRational, std::vector<int>{fps, 1}.data());
    spec.attribute("oiio:Movie", 1);
    specs.push_back(spec);
    images.push_back(std::move(small));
  }
  if (!out->open(path, static_cast<int>(specs.size()), specs.data())) return false;
  for (std::size_t i = 0; i < images.size(); ++i) {
    if (i > 0 && !out->open(path, specs[i], OIIO::ImageOutput::AppendSubimage)) return false;
    if (!images[i].write(out.get())) return false;
  }
  return out->close();
}

// The demo's spotlight as a projective-texture light (Segal et al. 3.2), from the command line.
struct DemoBeam {
  std::string beam;                 // empty: the plain cone; else a built-in beam pattern
  std::string attenuation = "none"; // none, vertex, exact
};

void apply_demo_beam(const DemoBeam &choice, gs::SpotLight &light) {
  light.beam = choice.beam;
  // Falls to about half at the far rope (8 m from the light along its axis).
  light.attenuation = {gs::AttenuationMode::None, 1.0f, 0.0f, 0.015f};
  if (choice.attenuation == "vertex") light.attenuation.mode = gs::AttenuationMode::PerVertex;
  if (choice.attenuation == "exact") light.attenuation.mode = gs::AttenuationMode::PerPixel;
}

int run_demo(int frames, const std::string &size_text, int shadow_size, const TechniqueChoice &choice,
             const DemoBeam &beam, const std::string &out_dir, int fps, bool gif, bool sheet) {
  if (beam.attenuation == "exact" && beam.beam.empty()) {
    std::fprintf(stderr, "glideshadows demo: --attenuation exact needs a beam map: give --beam\n");
    return 2;
  }
  int width = 0, height = 0;
  if (!parse_size(size_text, width, height)) {
    std::fprintf(stderr, "glideshadows demo: --size '%s' must be WxH with each side 64..2048\n", size_text.c_str());
    return 2;
  }
  std::error_code error;
  fs::create_directories(out_dir, error);
  if (error) {
    std::fprintf(stderr, "glideshadows demo: cannot create '%s': %s\n", out_dir.c_str(), error.message().c_str());
    return 1;
  }
  std::string problem;
  std::unique_ptr<gs::ShadowTechnique> technique =
      gs::make_technique(choice.name, technique_options(choice, shadow_size), problem);
  if (!technique) {
    std::fprintf(stderr, "glideshadows demo: %s\n", problem.c_str());
    return 2;
  }
  if (!open_window(width, height)) return 1;
  gs::FightScene fight(width, height, shadow_size);
  std::vector<gs::FrameReport> times;
  std::vector<std::string> written;
  std::vector<std::string> warnings;
  const bool tty = isatty(fileno(stderr)) != 0;
  for (int i = 0; i < frames; ++i) {
    const gs::Scene &fight_frame = fight.at(static_cast<float>(i) / static_cast<float>(fps));
    const gs::Scene *scene = &fight_frame;
    gs::Scene beamed;  // a copy only when the spotlight changes
    if (!beam.beam.empty() || beam.attenuation != "none") {
      beamed = fight_frame;
      apply_demo_beam(beam, beamed.lights.front());
      scene = &beamed;
    }
    const gs::FrameReport frame = technique->render(*scene, true);
    if (i > 0) times.push_back(frame);  // frame 0 pays llvmpipe's shader compiles
    for (const std::string &w : frame.warnings) {
      if (std::find(warnings.begin(), warnings.end(), w) == warnings.end()) warnings.push_back(w);
    }
    grBufferSwap(1);
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", i);
    const std::string path = (fs::path(out_dir) / name).string();
    if (!glideShimWritePng(GR_BUFFER_FRONTBUFFER, path.c_str())) {
      std::fprintf(stderr, "\nglideshadows demo: %s\n", glideShimGetLastErrorMessage());
      grGlideShutdown();
      return 1;
    }
    written.push_back(path);
    if (tty) {
      std::fprintf(stderr, "\rframe %d/%d", i + 1, frames);
    } else if ((i + 1) % std::max(1, frames / 10) == 0 || i + 1 == frames) {
      std::fprintf(stderr, "frame %d/%d\n", i + 1, frames);
    }
  }
  if (tty) std::fprintf(stderr, "\n");
  grGlideShutdown();
  for (const std::string &w : warnings) std::fprintf(stderr, "glideshadows demo: warning: %s\n", w.c_str());
  std::printf("glideshadows demo: %d frames %dx%d, technique %s, shadow texture %d, in %s/frame_NNNN.png\n",
              frames, width, height, choice.name.c_str(), shadow_size, out_dir.c_str());
  if (!times.empty()) print_step_table(times);
  if (sheet) {
    const std::string path = (fs::path(out_dir) / "contact_sheet.png").string();
    if (!write_contact_sheet(written, path)) {
      std::fprintf(stderr, "glideshadows demo: cannot write %s: %s\n", path.c_str(), OIIO::geterror().c_str());
      return 1;
    }
    std::printf("contact sheet: %s\n", path.c_str());
  }
  if (gif) {
    const std::string path = (fs::path(out_dir) / "fight.gif").string();
    if (!write_gif(written, path, fps)) {
      std::fprintf(stderr, "glideshadows demo: cannot write %s: %s\n", path.c_str(), OIIO::geterror().c_str());
      return 1;
    }
    std::printf("animated GIF: %s\n", path.c_str());
  }
  return 0;
}

int run_render(const std::string &scene_path, const TechniqueChoice &choice, int shadow_size,
               const std::string &out, const std::string &mask) {
  gs::Scene scene;
  std::string error;
  if (!gs::load_scene(scene_path, scene, error)) {
    std::fprintf(stderr, "glideshadows render: %s\n", error.c_str());
    return 1;
  }
  std::unique_ptr<gs::ShadowTechnique> technique =
      gs::make_technique(choice.name, technique_options(choice, shadow_size), error);
  if (!technique) {
    std::fprintf(stderr, "glideshadows render: %s\n", error.c_str());
    return 2;
  }
  if (!open_window(scene.width, scene.height)) return 1;
  const gs::FrameReport frame = technique->render(scene, false);
  for (const std::string &w : frame.warnings) std::fprintf(stderr, "glideshadows render: warning: %s\n", w.c_str());
  bool ok = glideShimWritePng(GR_BUFFER_BACKBUFFER, out.c_str());
  if (ok) std::printf("image: %s\n", out.c_str());
  if (ok && !mask.empty()) {
    const float gamma = 1.0f;  // the mask is data, not a picture: no gamma
    grGammaCorrectionValue(gamma);
    technique->render_mask(scene);
    ok = glideShimWritePng(GR_BUFFER_BACKBUFFER, mask.c_str());
    if (ok) std::printf("mask: %s (white: pixels the technique darkened)\n", mask.c_str());
  }
  if (!ok) std::fprintf(stderr, "glideshadows render: %s\n", glideShimGetLastErrorMessage());
  grGlideShutdown();
  return ok ? 0 : 1;
}

bool write_rgb_png(const std::string &path, int width, int height, const std::vector<std::uint8_t> &rgb) {
  OIIO::ImageBuf image(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8), const_cast<std::uint8_t *>(rgb.data()));
  return image.write(path);
}

bool write_mask_png(const std::string &path, int width, int height, const std::vector<std::uint8_t> &mask) {
  std::vector<std::uint8_t> rgb;
  rgb.reserve(mask.size() * 3);
  for (std::uint8_t m : mask) rgb.insert(rgb.end(), 3, m != 0 ? 255 : 0);
  return write_rgb_png(path, width, height, rgb);
}

int run_truth(const std::string &scene_path, const std::string &mask, const std::string &image) {
  gs::Scene scene;
  std::string error;
  if (!gs::load_scene(scene_path, scene, error)) {
    std::fprintf(stderr, "glideshadows truth: %s\n", error.c_str());
    return 1;
  }
  gs::GroundTruth truth;
  if (!gs::compute_ground_truth(scene, truth, error)) {
    std::fprintf(stderr, "glideshadows truth: %s\n", error.c_str());
    return 1;
  }
  if (!write_mask_png(mask, truth.width, truth.height, truth.shadow)) {
    std::fprintf(stderr, "glideshadows truth: cannot write %s: %s\n", mask.c_str(), OIIO::geterror().c_str());
    return 1;
  }
  std::printf("mask: %s (white: a light blocked by another object)\n", mask.c_str());
  if (!image.empty()) {
    if (!write_rgb_png(image, truth.width, truth.height, truth.rgb)) {
      std::fprintf(stderr, "glideshadows truth: cannot write %s: %s\n", image.c_str(), OIIO::geterror().c_str());
      return 1;
    }
    std::printf("image: %s (exact visibility, per-pixel lighting)\n", image.c_str());
  }
  return 0;
}

int run_compare(const std::string &a, const std::string &b, const std::string &diff) {
  gs::ImageErrors errors;
  std::string error;
  if (!gs::compare_images(a, b, diff, errors, error)) {
    std::fprintf(stderr, "glideshadows compare: %s\n", error.c_str());
    return 1;
  }
  std::printf("mean error %.6f, max error %.6f, PSNR %.2f dB, %ld pixels differ by more than 1/255\n",
              errors.mean, errors.max, errors.psnr, errors.pixels_over_threshold);
  // Two masks (black and white) are also compared as shadow masks, B being the truth.
  std::vector<std::uint8_t> ma, mb;
  int wa = 0, ha = 0, wb = 0, hb = 0;
  if (gs::read_mask(a, ma, wa, ha, error) && gs::read_mask(b, mb, wb, hb, error) && wa == wb && ha == hb) {
    const std::vector<std::uint8_t> all(ma.size(), 1);
    const gs::MaskErrors m = gs::compare_masks(ma, mb, all, wa, ha);
    std::printf("as masks (B the truth): %.3f%% misclassified: false shadow %.3f%% band + %.3f%% interior, "
                "false light %.3f%% band + %.3f%% interior; farthest wrong pixel %.1f px from the true edge\n",
                100 * m.misclassified, 100 * m.false_shadow_band, 100 * m.false_shadow_interior,
                100 * m.false_light_band, 100 * m.false_light_interior, m.max_distance_px);
  }
  if (!diff.empty()) std::printf("heat map: %s\n", diff.c_str());
  return 0;
}

int run_bench(std::vector<std::string> scene_files, bool quick, int repeats, const std::string &csv,
              const std::string &plot, double budget) {
  std::vector<gs::BenchFrame> frames;
  gs::FightScene fight(640, 480, 256);
  for (float time : quick ? std::vector<float>{2.1f} : std::vector<float>{0.5f, 2.1f, 5.3f}) {
    char name[32];
    std::snprintf(name, sizeof name, "fight t=%.1f", static_cast<double>(time));
    frames.push_back({name, fight.at(time)});
  }
  if (scene_files.empty() && !quick && fs::is_directory("scenes")) {
    for (const auto &entry : fs::directory_iterator("scenes")) {
      if (entry.path().extension() == ".json") scene_files.push_back(entry.path().string());
    }
    std::sort(scene_files.begin(), scene_files.end());
  }
  for (const std::string &file : scene_files) {
    gs::Scene scene;
    std::string error;
    if (!gs::load_scene(file, scene, error)) {
      std::fprintf(stderr, "glideshadows bench: %s\n", error.c_str());
      return 1;
    }
    frames.push_back({fs::path(file).stem().string(), std::move(scene)});
  }
  const std::vector<gs::BenchConfiguration> configurations = gs::bench_configurations(quick);
  const bool tty = isatty(fileno(stderr)) != 0;
  std::vector<gs::BenchRow> rows;
  std::string error;
  const bool ok = gs::run_bench(frames, configurations, repeats,
      [&](int done, int total, const std::string &what) {
        if (tty) std::fprintf(stderr, "\r[%d/%d] %-60.60s", done, total, what.c_str());
        else if (done % 10 == 1 || done == total) std::fprintf(stderr, "[%d/%d] %s\n", done, total, what.c_str());
      },
      rows, error);
  if (tty) std::fprintf(stderr, "\n");
  if (!ok) {
    std::fprintf(stderr, "glideshadows bench: %s\n", error.c_str());
    return 1;
  }
  std::printf("%-16s %-16s %-38s %8s %6s %8s %8s %8s %6s %7s %6s\n", "frame", "technique",
              "settings", "ms", "x none", "wrong%", "band%", "inner%", "maxpx", "img err", "PSNR");
  for (const gs::BenchRow &r : rows) {
    const double band = r.errors.false_shadow_band + r.errors.false_light_band;
    const double inner = r.errors.false_shadow_interior + r.errors.false_light_interior;
    std::printf("%-16s %-16s %-38s %8.2f %6.2f %8.3f %8.3f %8.3f %6.1f %7.2f %6.1f\n",
                r.frame.c_str(), r.technique.c_str(), r.settings.c_str(), r.frame_ms,
                r.ratio_to_none, 100 * r.errors.misclassified, 100 * band, 100 * inner,
                r.errors.max_distance_px, 255 * r.image.mean, r.image.psnr);
  }
  std::printf("(wrong%%: receiver pixels misclassified; img err: mean absolute error of the whole "
              "frame against the truth's exactly lit image, in 8-bit steps)\n\n");
  for (const std::string &line : gs::article_step_comparison(rows)) std::printf("%s\n", line.c_str());
  if (!csv.empty()) {
    std::FILE *out = std::fopen(csv.c_str(), "w");
    if (out == nullptr) {
      std::fprintf(stderr, "glideshadows bench: cannot write %s\n", csv.c_str());
      return 1;
    }
    std::fprintf(out, "frame,technique,settings,frame_ms,ratio_to_none,misclassified,false_shadow_band,"
                      "false_shadow_interior,false_light_band,false_light_interior,max_distance_px,"
                      "self_shadow,image_mean_error,image_psnr,steps\n");
    for (const gs::BenchRow &r : rows) {
      std::string steps;
      for (const auto &s : r.steps) steps += (steps.empty() ? "" : ";") + s.first + "=" + std::to_string(s.second);
      std::fprintf(out, "%s,%s,%s,%.4f,%.4f,%.6f,%.6f,%.6f,%.6f,%.6f,%.2f,%.6f,%.6f,%.2f,\"%s\"\n",
                   r.frame.c_str(), r.technique.c_str(), r.settings.c_str(), r.frame_ms, r.ratio_to_none,
                   r.errors.misclassified, r.errors.false_shadow_band, r.errors.false_shadow_interior,
                   r.errors.false_light_band, r.errors.false_light_interior, r.errors.max_distance_px,
                   r.self_shadow, r.image.mean, r.image.psnr, steps.c_str());
    }
    std::fclose(out);
    std::printf("CSV: %s\n", csv.c_str());
  }
  if (!plot.empty()) {
    // One point per configuration measured on every frame: its mean time and mean error. (The
    // attenuation settings apply to the spotlight scenes only, so they are left out.)
    std::vector<gs::PlotPoint> points;
    for (std::size_t c = 0; c < configurations.size(); ++c) {
      double time = 0, wrong = 0;
      std::size_t n = 0;
      for (const gs::BenchRow &r : rows) {
        if (r.configuration != c) continue;
        time += r.frame_ms, wrong += r.errors.misclassified, ++n;
      }
      if (n == frames.size() && n > 0)
        points.push_back({time / static_cast<double>(n), wrong / static_cast<double>(n),
                          configurations[c].technique});
    }
    if (!gs::write_plot(points, "error against frame time (mean over frames)", plot, error)) {
      std::fprintf(stderr, "glideshadows bench: %s\n", error.c_str());
      return 1;
    }
    std::printf("plot: %s\n", plot.c_str());
  }
  if (budget >= 0.0) {
    for (const gs::BenchFrame &frame : frames) {
      const gs::BenchRow *best = nullptr;
      for (const gs::BenchRow &r : rows) {
        if (r.frame != frame.name || r.technique == "none" || r.errors.misclassified > budget) continue;
        if (best == nullptr || r.frame_ms < best->frame_ms) best = &r;
      }
      if (best == nullptr) {
        std::printf("budget %.4f, %s: no configuration is that accurate\n", budget, frame.name.c_str());
      } else {
        std::printf("budget %.4f, %s: %s %s (%.2f ms, %.3f%% wrong)\n", budget, frame.name.c_str(),
                    best->technique.c_str(), best->settings.c_str(), best->frame_ms,
                    100 * best->errors.misclassified);
      }
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char **argv) {
  CLI::App app{"glideshadows: Glide-era projected shadow textures on a Glide 2.x shim, headless"};
  app.require_subcommand(1);

  CLI::App *demo = app.add_subcommand("demo", "render the fighting-game demo to PNG frames and print the step timing");
  int frames = 48, fps = 30, shadow_size = 256;
  std::string size = "640x480", out_dir = "out/demo";
  bool gif = false, sheet = false;
  TechniqueChoice demo_choice;
  demo->add_option("--frames", frames, "number of frames")->check(CLI::Range(1, 100000))->capture_default_str();
  demo->add_option("--size", size, "screen size WxH")->capture_default_str();
  demo->add_option("--out", out_dir, "directory for frame_NNNN.png")->capture_default_str();
  demo->add_option("--fps", fps, "animation frames per second of fight time")->check(CLI::Range(1, 240))->capture_default_str();
  demo->add_flag("--gif", gif, "also write an animated GIF (half size) of the frames");
  demo->add_flag("--contact-sheet", sheet, "also write a 4x4 contact sheet of frames from the run");
  add_technique_options(*demo, demo_choice, shadow_size);
  DemoBeam demo_beam;
  demo->add_option("--beam", demo_beam.beam,
                   "give the spotlight a projected beam map: round, square, gobo or lens")
      ->check(CLI::IsMember({"round", "square", "gobo", "lens"}));
  demo->add_option("--attenuation", demo_beam.attenuation,
                   "the spotlight's attenuation with distance: none, vertex or exact (needs --beam)")
      ->check(CLI::IsMember({"none", "vertex", "exact"}))
      ->capture_default_str();

  CLI::App *render = app.add_subcommand("render", "render a scene file (JSON, docs/scene_format.md)");
  std::string scene_path, out = "render.png", mask;
  int render_shadow_size = 0;
  TechniqueChoice render_choice;
  render->add_option("scene", scene_path, "scene file")->required()->check(CLI::ExistingFile);
  render->add_option("--out", out, "output PNG")->capture_default_str();
  render->add_option("--mask", mask, "also write the shadow mask PNG (white: darkened by the technique)");
  add_technique_options(*render, render_choice, render_shadow_size);
  render->get_option("--shadow-size")->description("shadow texture side (default: each light's shadow_size)");
  render->get_option("--shadow-size")->check(CLI::IsMember({0, 32, 64, 128, 256, 512}));

  CLI::App *truth = app.add_subcommand("truth", "ray-cast the exact shadow mask (and image) of a scene file");
  std::string truth_scene, truth_mask, truth_image;
  truth->add_option("scene", truth_scene, "scene file")->required()->check(CLI::ExistingFile);
  truth->add_option("--mask", truth_mask, "output: white where another object blocks a light")->required();
  truth->add_option("--image", truth_image, "output: the scene lit with exact visibility");

  CLI::App *compare = app.add_subcommand("compare", "compare two images (and, for masks, shadow errors)");
  std::string compare_a, compare_b, compare_diff;
  compare->add_option("a", compare_a, "an image, or a technique's mask")->required()->check(CLI::ExistingFile);
  compare->add_option("b", compare_b, "the reference image, or the true mask")->required()->check(CLI::ExistingFile);
  compare->add_option("--diff", compare_diff, "write a heat map of the difference (PNG)");

  CLI::App *bench = app.add_subcommand("bench", "speed against error of every technique and setting");
  std::vector<std::string> bench_scenes;
  bool bench_quick = false;
  int bench_repeats = 5;
  std::string bench_csv, bench_plot;
  double bench_budget = -1.0;
  bench->add_option("scenes", bench_scenes, "scene files (default: fight frames and scenes/*.json)")
      ->check(CLI::ExistingFile);
  bench->add_flag("--quick", bench_quick, "a few configurations on one fight frame (under a minute)");
  bench->add_option("--repeats", bench_repeats, "timed repeats per configuration (median)")
      ->check(CLI::Range(1, 100))->capture_default_str();
  bench->add_option("--csv", bench_csv, "write one row per frame and configuration");
  bench->add_option("--plot", bench_plot, "write error against time as a PNG with the Pareto front");
  bench->add_option("--budget", bench_budget, "name the cheapest configuration with at most this error (fraction)")
      ->check(CLI::Range(0.0, 1.0));

  CLI::App *figures = app.add_subcommand("figures", "reproduce the articles' figures as PNGs with checks and an index page");
  std::string figures_out = "out/figures", figures_only;
  figures->add_option("--out", figures_out, "directory for the PNGs and index.html")->capture_default_str();
  figures->add_option("--only", figures_only,
                      "comma-separated figures: names such as nguyen-7, sgi-3, everitt-5, or bare numbers for Nguyen's");

  CLI11_PARSE(app, argc, argv);
  if (figures->parsed()) return gs::run_figures(figures_out, figures_only, stdout);
  if (bench->parsed()) {
    return run_bench(bench_scenes, bench_quick, bench_repeats, bench_csv, bench_plot, bench_budget);
  }
  if (truth->parsed()) return run_truth(truth_scene, truth_mask, truth_image);
  if (compare->parsed()) return run_compare(compare_a, compare_b, compare_diff);
  if (demo->parsed()) {
    return run_demo(frames, size, shadow_size, demo_choice, demo_beam, out_dir, fps, gif, sheet);
  }
  return run_render(scene_path, render_choice, render_shadow_size, out, mask);
}
