// The figure table, the selection, the driver and the index page.
#include "figures/figures.h"

#include "figures/figures_kit.h"
#include "media/media.h"

#include <glide.h>
#include <glide_shim.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace gs {

const std::vector<FigureEntry> &figure_table() {
  static const std::vector<FigureEntry> table = {
      {"nguyen-1", "Nguyen 1999, Figure 1",
       "A screenshot of the article's sample program: projected shadow textures on a fighter.",
       figure_nguyen_1},
      {"nguyen-2", "Nguyen 1999, Figure 2",
       "Planar shadows: the caster's polygons projected onto the receivers' planes.", figure_nguyen_2},
      {"nguyen-3", "Nguyen 1999, Figure 3",
       "Planar shadows keep sharp edges even when the shadow is stretched.", figure_nguyen_3},
      {"nguyen-4", "Nguyen 1999, Figure 4",
       "The effect to reach: the man's shadow thrown across the scene.", figure_nguyen_4},
      {"nguyen-5", "Nguyen 1999, Figure 5",
       "The scene from the light: the figure hides exactly the shadow it casts.", figure_nguyen_5},
      {"nguyen-6", "Nguyen 1999, Figure 6",
       "The objects that receive the shadow, from the light: where (s, t) come from.",
       figure_nguyen_6},
      {"nguyen-7", "Nguyen 1999, Figure 7",
       "The shadow texture: only the caster, rendered from the light.", figure_nguyen_7},
      {"nguyen-8", "Nguyen 1999, Figure 8",
       "The receivers and the shadow texture superimposed in the light's view.", figure_nguyen_8},
      {"nguyen-9", "Nguyen 1999, Figure 9",
       "The scene drawn with the shadow texture projected onto it.", figure_nguyen_9},
      {"nguyen-10", "Nguyen 1999, Figure 10",
       "A square with texture coordinates beyond [0, 1] in clamp mode.", figure_nguyen_10},
      {"nguyen-11", "Nguyen 1999, Figure 11",
       "The same square with tiling: the texture repeats.", figure_nguyen_11},
      {"nguyen-12", "Nguyen 1999, Figure 12",
       "The clamp-mode bug: a shadow smeared outside where it belongs.", figure_nguyen_12},
      {"nguyen-13", "Nguyen 1999, Figure 13",
       "The bug's cause: the character clipped by the shadow texture's border.", figure_nguyen_13},
      {"nguyen-14", "Nguyen 1999, Figure 14",
       "The triangles seen by the light, drawn a second time in flat colours.", figure_nguyen_14},
      {"nguyen-15", "Nguyen 1999, Figure 15",
       "Bilinear filtering of the alpha mask smooths the shadow's edge; a chroma key cannot.",
       figure_nguyen_15},
      {"nguyen-16", "Nguyen 1999, Figure 16", "The bits of a 16-bit RGB 565 pixel.",
       figure_nguyen_16},
      {"nguyen-17", "Nguyen 1999, Figure 17", "The bits of a 16-bit ARGB 4444 pixel.",
       figure_nguyen_17},
      {"sgi-3", "Segal et al. 1992, Figure 3",
       "A slide projector: the slide (left) and the scene lit by it and an ambient light (right).",
       figure_sgi_3},
      {"sgi-4", "Segal et al. 1992, Figure 4",
       "A spotlight with a shadow: the shadow map (left), the spotlight's intensity map (centre), "
       "and the scene lit with both (right).",
       figure_sgi_4},
      {"everitt-2", "Everitt et al. 2001, Figure 2",
       "A shadow-mapped scene from the eye, the scene from the light, and the light's depth map.",
       figure_everitt_2},
      {"everitt-4", "Everitt et al. 2001, Figure 4",
       "The shadowed scene, each sample's distance from the light, and the depth map projected "
       "onto the scene.",
       figure_everitt_4},
      {"everitt-5", "Everitt et al. 2001, Figure 5",
       "A very low resolution shadow map, nearest (left) against linear (right) filtering.",
       figure_everitt_5},
  };
  return table;
}

bool select_figures(const std::string &only, std::vector<const FigureEntry *> &selected,
                    std::string &error) {
  std::vector<const FigureEntry *> chosen;
  if (only.empty()) {
    for (const FigureEntry &entry : figure_table()) chosen.push_back(&entry);
    selected = chosen;
    return true;
  }
  std::stringstream list(only);
  std::string item;
  while (std::getline(list, item, ',')) {
    const bool number = !item.empty() && item.find_first_not_of("0123456789") == std::string::npos;
    const std::string name = number ? "nguyen-" + item : item;
    const FigureEntry *found = nullptr;
    for (const FigureEntry &entry : figure_table()) {
      if (name == entry.name) found = &entry;
    }
    if (found == nullptr) {
      std::string names;
      for (const FigureEntry &entry : figure_table()) names += std::string(names.empty() ? "" : ", ") + entry.name;
      error = "no figure '" + item + "' (known: " + names + "; a bare number is Nguyen's figure)";
      return false;
    }
    chosen.push_back(found);
  }
  selected = chosen;
  return true;
}

bool make_figure(const FigureEntry &entry, Figure &figure, std::string &error, FigureFault fault) {
  figure = Figure{};
  grSstWinClose();  // the previous figure's, if any
  if (!glideShimSetWindowSize(kFigureWindowWidth, kFigureWindowHeight) ||
      !grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                    GR_ORIGIN_UPPER_LEFT, 2, 1)) {
    error = std::string("cannot open the figures' Glide window: ") + glideShimGetLastErrorMessage();
    return false;
  }
  glideShimClearError();
  entry.make(figure, fault);
  if (fault == FigureFault::InvalidGlideCall) grDepthBufferFunction(static_cast<GrCmpFnc_t>(99));
  const GlideShimError reported = glideShimGetLastError();
  figure.checks.push_back(figures::check(
      "Glide reported no error while the figure rendered", reported == GLIDESHIM_OK,
      reported == GLIDESHIM_OK ? "no error" : glideShimGetLastErrorMessage()));
  return true;
}

bool write_figure_png(const FigureImage &image, const std::string &path, std::string &error) {
  std::string why;
  if (!media::write_rgb_png(path, image.width, image.height, image.rgb, why)) {
    error = "cannot write " + path + ": " + why;
    return false;
  }
  return true;
}

namespace {

std::string html_escaped(const std::string &text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

bool all_passed(const Figure &figure) {
  for (const FigureCheck &c : figure.checks) {
    if (!c.passed) return false;
  }
  return true;
}

}  // namespace

bool write_figure_index(const std::string &path, const std::vector<const FigureEntry *> &entries,
                        const std::vector<Figure> &figures, const std::vector<std::string> &images,
                        std::string &error) {
  std::ofstream out(path);
  if (!out) {
    error = "cannot write " + path;
    return false;
  }
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
         "<title>glideshadows: the articles' figures</title>\n<style>\n"
         "body{font-family:sans-serif;background:#f4f4f4;margin:1em}\n"
         ".grid{display:flex;flex-wrap:wrap;gap:1em}\n"
         ".fig{background:#fff;padding:.8em;border:1px solid #ccc;flex:0 1 640px}\n"
         ".fig img{width:100%;image-rendering:pixelated}\n"
         ".pass{color:#176317}.fail{color:#b00;font-weight:bold}\n"
         "li{margin:.2em 0}\n</style></head><body>\n"
         "<h1>The articles' figures, rendered by glideshadows</h1>\n"
         "<p>Each figure is rendered by this project's own code (the Glide shim and the shadow "
         "techniques) and carries checks of what the article says it shows, measured on our "
         "pixels. The captions paraphrase the articles.</p>\n<div class=\"grid\">\n";
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const FigureEntry &entry = *entries[i];
    const Figure &figure = figures[i];
    out << "<div class=\"fig\" id=\"" << entry.name << "\">\n<h2>" << html_escaped(entry.source)
        << " <small>(" << entry.name << ")</small></h2>\n<img src=\"" << html_escaped(images[i])
        << "\" alt=\"" << html_escaped(entry.source) << "\">\n<p><b>The article:</b> "
        << html_escaped(entry.caption) << "</p>\n<p><b>Ours:</b> " << html_escaped(figure.shows)
        << "</p>\n<p><b>Checks:</b> <span class=\"" << (all_passed(figure) ? "pass\">all pass" : "fail\">FAILED")
        << "</span></p>\n<ul>\n";
    for (const FigureCheck &c : figure.checks) {
      out << "<li><span class=\"" << (c.passed ? "pass\">pass" : "fail\">FAIL") << "</span> "
          << html_escaped(c.claim) << " <i>(" << html_escaped(c.measured) << ")</i></li>\n";
    }
    out << "</ul></div>\n";
  }
  out << "</div></body></html>\n";
  if (!out) {
    error = "cannot write " + path;
    return false;
  }
  return true;
}

int run_figures(const std::string &out_dir, const std::string &only, std::FILE *out) {
  std::vector<const FigureEntry *> entries;
  std::string error;
  if (!select_figures(only, entries, error)) {
    std::fprintf(stderr, "glideshadows figures: %s\n", error.c_str());
    return 2;
  }
  std::error_code made;
  fs::create_directories(out_dir, made);
  if (made) {
    std::fprintf(stderr, "glideshadows figures: cannot create '%s': %s\n", out_dir.c_str(),
                 made.message().c_str());
    return 1;
  }
  grGlideInit();
  std::vector<Figure> figures(entries.size());
  std::vector<std::string> images;
  int failed_checks = 0;
  bool written = true;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const FigureEntry &entry = *entries[i];
    std::fprintf(out, "[%zu/%zu] %s (%s)\n", i + 1, entries.size(), entry.source, entry.name);
    std::fflush(out);
    if (!make_figure(entry, figures[i], error)) {
      std::fprintf(stderr, "glideshadows figures: %s\n", error.c_str());
      grGlideShutdown();
      return 1;
    }
    images.push_back(std::string(entry.name) + ".png");
    if (!write_figure_png(figures[i].image, (fs::path(out_dir) / images.back()).string(), error)) {
      std::fprintf(stderr, "glideshadows figures: %s\n", error.c_str());
      written = false;
    }
    for (const FigureCheck &c : figures[i].checks) {
      std::fprintf(out, "    %s  %s (%s)\n", c.passed ? "pass" : "FAIL", c.claim.c_str(),
                   c.measured.c_str());
      failed_checks += c.passed ? 0 : 1;
    }
  }
  grGlideShutdown();
  const std::string index = (fs::path(out_dir) / "index.html").string();
  if (!write_figure_index(index, entries, figures, images, error)) {
    std::fprintf(stderr, "glideshadows figures: %s\n", error.c_str());
    written = false;
  }
  std::fprintf(out, "%zu figures in %s, index %s; %d check%s failed\n", entries.size(),
               out_dir.c_str(), index.c_str(), failed_checks, failed_checks == 1 ? "" : "s");
  return failed_checks == 0 && written ? 0 : 1;
}

}  // namespace gs
