// The speed-against-error scatter plot: the Pareto front, axis scaling, and the drawing with
// OpenImageIO's ImageBufAlgo, through the image files module (media/image_files.h). Text uses a
// built-in 3x5 bitmap font (upper case, digits, a few signs) because render_text's default font
// is missing on our machines ("Could not set default font face") and a system font would make
// the PNG bytes depend on the machine.
#include "measure/plot.h"

#include "media/image_files.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace gs {
namespace {

// Image layout, in pixels: plot.h; below, where the legend and marks go.
using namespace plot_layout;
constexpr int kLegendX = 715;
constexpr int kTickLength = 5;
constexpr int kPointHalf = 3;     // points are 7x7 squares
constexpr int kFrontRadius = 7;   // the ring drawn around front points
constexpr int kTextScale = 2;     // font pixels per glyph pixel for ticks, legend and axis names
constexpr int kTitleScale = 3;
constexpr int kTargetTicks = 5;

struct Colour {
  float v[3];
};

// The image being drawn, in image pixels (x right, y down), and the module that draws on it.
struct Painter {
  media::RgbCanvas canvas;
  const media::ImageFiles &files;
  void box(int x1, int y1, int x2, int y2, const Colour &c) {
    files.draw_box(canvas, x1, y1, x2, y2, c.v);
  }
  void line(int x1, int y1, int x2, int y2, const Colour &c) {
    files.draw_line(canvas, x1, y1, x2, y2, c.v);
  }
  void point(int x, int y, const Colour &c) { files.draw_point(canvas, x, y, c.v); }
};

constexpr Colour kWhite{{1.0f, 1.0f, 1.0f}};
constexpr Colour kBlack{{0.0f, 0.0f, 0.0f}};
constexpr Colour kGrid{{0.9f, 0.9f, 0.9f}};
constexpr Colour kFront{{0.15f, 0.15f, 0.15f}};

// Distinct, colour-blind-friendlier hues (Tableau 10); labels past the tenth reuse them in order.
constexpr Colour kPalette[] = {
    {{0.122f, 0.467f, 0.706f}}, {{1.000f, 0.498f, 0.055f}}, {{0.173f, 0.627f, 0.173f}},
    {{0.839f, 0.153f, 0.157f}}, {{0.580f, 0.404f, 0.741f}}, {{0.549f, 0.337f, 0.294f}},
    {{0.890f, 0.467f, 0.761f}}, {{0.498f, 0.498f, 0.498f}}, {{0.737f, 0.741f, 0.133f}},
    {{0.090f, 0.745f, 0.812f}},
};
constexpr std::size_t kPaletteSize = sizeof(kPalette) / sizeof(kPalette[0]);

// ---- the bitmap font ---------------------------------------------------------------------------

// Each row is 3 bits, 0b100 the leftmost pixel; rows run top to bottom.
struct Glyph {
  char c;
  std::uint8_t rows[5];
};

constexpr Glyph kFont[] = {
    {' ', {0, 0, 0, 0, 0}},      {'0', {7, 5, 5, 5, 7}},      {'1', {2, 6, 2, 2, 7}},
    {'2', {7, 1, 7, 4, 7}},      {'3', {7, 1, 7, 1, 7}},      {'4', {5, 5, 7, 1, 1}},
    {'5', {7, 4, 7, 1, 7}},      {'6', {7, 4, 7, 5, 7}},      {'7', {7, 1, 1, 2, 2}},
    {'8', {7, 5, 7, 5, 7}},      {'9', {7, 5, 7, 1, 7}},      {'A', {2, 5, 7, 5, 5}},
    {'B', {6, 5, 6, 5, 6}},      {'C', {3, 4, 4, 4, 3}},      {'D', {6, 5, 5, 5, 6}},
    {'E', {7, 4, 6, 4, 7}},      {'F', {7, 4, 6, 4, 4}},      {'G', {3, 4, 5, 5, 3}},
    {'H', {5, 5, 7, 5, 5}},      {'I', {7, 2, 2, 2, 7}},      {'J', {1, 1, 1, 5, 2}},
    {'K', {5, 5, 6, 5, 5}},      {'L', {4, 4, 4, 4, 7}},      {'M', {5, 7, 7, 5, 5}},
    {'N', {6, 5, 5, 5, 5}},      {'O', {2, 5, 5, 5, 2}},      {'P', {6, 5, 6, 4, 4}},
    {'Q', {2, 5, 5, 6, 3}},      {'R', {6, 5, 6, 5, 5}},      {'S', {3, 4, 2, 1, 6}},
    {'T', {7, 2, 2, 2, 2}},      {'U', {5, 5, 5, 5, 7}},      {'V', {5, 5, 5, 5, 2}},
    {'W', {5, 5, 7, 7, 5}},      {'X', {5, 5, 2, 5, 5}},      {'Y', {5, 5, 2, 2, 2}},
    {'Z', {7, 1, 2, 4, 7}},      {'.', {0, 0, 0, 0, 2}},      {',', {0, 0, 0, 2, 4}},
    {'-', {0, 0, 7, 0, 0}},      {'+', {0, 2, 7, 2, 0}},      {'=', {0, 7, 0, 7, 0}},
    {'%', {4, 1, 2, 4, 1}},      {'(', {1, 2, 2, 2, 1}},      {')', {4, 2, 2, 2, 4}},
    {':', {0, 2, 0, 2, 0}},      {'/', {1, 1, 2, 4, 4}},      {'_', {0, 0, 0, 0, 7}},
    {'?', {7, 1, 2, 0, 2}},
};

const Glyph &glyph_for(char c) {
  const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const Glyph &g : kFont)
    if (g.c == upper) return g;
  return kFont[sizeof(kFont) / sizeof(kFont[0]) - 1];  // '?' marks what the font lacks
}

// Glyphs are 3 pixels wide plus one of spacing, times the scale.
int text_width(const std::string &text, int scale) {
  return static_cast<int>(text.size()) * 4 * scale - scale;
}

// (x, y) is the top-left corner of the first glyph, in image pixels.
void draw_text(Painter &img, int x, int y, const std::string &text, int scale,
               const Colour &colour) {
  for (char c : text) {
    const Glyph &g = glyph_for(c);
    for (int row = 0; row < 5; ++row)
      for (int col = 0; col < 3; ++col)
        if (g.rows[row] & (4 >> col))
          img.box(x + col * scale, y + row * scale, x + (col + 1) * scale - 1,
                          y + (row + 1) * scale - 1, colour);
    x += 4 * scale;
  }
}

// ---- axes --------------------------------------------------------------------------------------

// A linear axis from 0 to `top` with ticks every `step`, both "round" numbers (1, 2 or 5 times a
// power of ten) so the tick labels read cleanly.
struct Axis {
  double top;
  double step;
  int decimals;  // digits after the point that tick labels need to show `step`
};

Axis make_axis(double max_value) {
  // An all-zero (or empty) range still gets a 0..1 axis, so the points sit on a visible scale.
  if (!(max_value > 0.0)) return {1.0, 0.2, 1};
  const double raw = max_value / kTargetTicks;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double norm = raw / magnitude;
  const double nice = norm <= 1.0 ? 1.0 : norm <= 2.0 ? 2.0 : norm <= 5.0 ? 5.0 : 10.0;
  const double step = nice * magnitude;
  // The tolerance keeps a maximum that is already a multiple of the step from gaining a tick.
  const double top = std::ceil(max_value / step - 1e-9) * step;
  const int decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  return {top, step, decimals};
}

std::string format_tick(double value, int decimals) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
  return buffer;
}

int to_px(double v) { return static_cast<int>(std::lround(v)); }

// Data (time in ms, error in percent) to image pixels.
struct Mapping {
  Axis x;
  Axis y;
  int px(double time_ms) const {
    return to_px(kPlotLeft + time_ms / x.top * (kPlotRight - kPlotLeft));
  }
  int py(double error_percent) const {
    return to_px(kPlotBottom - error_percent / y.top * (kPlotBottom - kPlotTop));
  }
};

void draw_axes(Painter &img, const Mapping &m) {
  const int x_ticks = to_px(m.x.top / m.x.step);
  for (int i = 0; i <= x_ticks; ++i) {
    const double value = i * m.x.step;
    const int x = m.px(value);
    if (i > 0) img.line(x, kPlotTop, x, kPlotBottom - 1, kGrid);
    img.line(x, kPlotBottom, x, kPlotBottom + kTickLength, kBlack);
    const std::string label = format_tick(value, m.x.decimals);
    draw_text(img, x - text_width(label, kTextScale) / 2, kPlotBottom + kTickLength + 4, label,
              kTextScale, kBlack);
  }
  const int y_ticks = to_px(m.y.top / m.y.step);
  for (int i = 0; i <= y_ticks; ++i) {
    const double value = i * m.y.step;
    const int y = m.py(value);
    if (i > 0) img.line(kPlotLeft + 1, y, kPlotRight, y, kGrid);
    img.line(kPlotLeft - kTickLength, y, kPlotLeft, y, kBlack);
    const std::string label = format_tick(value, m.y.decimals);
    draw_text(img, kPlotLeft - kTickLength - 4 - text_width(label, kTextScale), y - kTextScale * 5 / 2,
              label, kTextScale, kBlack);
  }
  img.line(kPlotLeft, kPlotBottom, kPlotRight, kPlotBottom, kBlack);
  img.line(kPlotLeft, kPlotTop, kPlotLeft, kPlotBottom, kBlack);

  const std::string x_name = "time (ms)";
  draw_text(img, (kPlotLeft + kPlotRight - text_width(x_name, kTextScale)) / 2, kPlotBottom + 35,
            x_name, kTextScale, kBlack);
  // No rotated text in a bitmap font: the y name sits above its axis instead.
  draw_text(img, kPlotLeft - 40, kPlotTop - 22, "error (%)", kTextScale, kBlack);
}

// ---- marks -------------------------------------------------------------------------------------

void draw_square(Painter &img, int x, int y, const Colour &colour) {
  img.box(x - kPointHalf, y - kPointHalf, x + kPointHalf, y + kPointHalf, colour);
}

// A two-pixel-thick ring; a fixed list of integer offsets keeps the pixels deterministic.
void draw_ring(Painter &img, int cx, int cy, const Colour &colour) {
  for (int dy = -kFrontRadius - 1; dy <= kFrontRadius + 1; ++dy)
    for (int dx = -kFrontRadius - 1; dx <= kFrontRadius + 1; ++dx) {
      const int d2 = dx * dx + dy * dy;
      if (d2 >= (kFrontRadius - 1) * (kFrontRadius - 1) && d2 <= kFrontRadius * kFrontRadius + kFrontRadius)
        img.point(cx + dx, cy + dy, colour);
    }
}

// Two adjacent lines, so the front reads as heavier than the grid and the axes.
void draw_thick_line(Painter &img, int x1, int y1, int x2, int y2, const Colour &colour) {
  img.line(x1, y1, x2, y2, colour);
  if (std::abs(x2 - x1) >= std::abs(y2 - y1))
    img.line(x1, y1 + 1, x2, y2 + 1, colour);
  else
    img.line(x1 + 1, y1, x2 + 1, y2, colour);
}

// Clips a label to the space left of the image's right edge, so long names stay legible.
std::string fit(const std::string &text, int x) {
  const auto max_chars = static_cast<std::size_t>(std::max(0, (kWidth - 4 - x) / (4 * kTextScale)));
  return text.size() <= max_chars ? text : text.substr(0, max_chars);
}

bool finite_point(const PlotPoint &p) {
  return std::isfinite(p.time_ms) && std::isfinite(p.error);
}

}  // namespace

// Non-finite points are left off the front: they cannot be placed on an axis.
// O(n^2), which is fine for the few dozen configurations a benchmark plots.
void draw_bitmap_text(std::vector<unsigned char> &rgb, int width, int height, int x, int y,
                      const std::string &text, int scale, const unsigned char colour[3]) {
  for (char c : text) {
    const Glyph &g = glyph_for(c);
    for (int row = 0; row < 5 * scale; ++row) {
      for (int col = 0; col < 3 * scale; ++col) {
        const int px = x + col, py = y + row;
        if (px < 0 || py < 0 || px >= width || py >= height) continue;
        if ((g.rows[row / scale] & (4 >> (col / scale))) == 0) continue;
        const auto at = static_cast<std::size_t>(py * width + px) * 3;
        for (int channel = 0; channel < 3; ++channel) rgb[at + channel] = colour[channel];
      }
    }
    x += 4 * scale;
  }
}

int bitmap_text_width(const std::string &text, int scale) { return text_width(text, scale); }

std::vector<std::size_t> pareto_front(const std::vector<PlotPoint> &points) {
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const PlotPoint &p = points[i];
    if (!finite_point(p)) continue;
    bool dominated = false;
    for (std::size_t j = 0; j < points.size() && !dominated; ++j) {
      const PlotPoint &q = points[j];
      dominated = j != i && finite_point(q) && q.time_ms <= p.time_ms && q.error <= p.error &&
                  (q.time_ms < p.time_ms || q.error < p.error);
    }
    if (!dominated) front.push_back(i);
  }
  // Exact duplicates do not dominate each other, so both stay; the index breaks the tie.
  std::sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) {
    if (points[a].time_ms != points[b].time_ms) return points[a].time_ms < points[b].time_ms;
    if (points[a].error != points[b].error) return points[a].error < points[b].error;
    return a < b;
  });
  return front;
}

bool write_plot(const std::vector<PlotPoint> &points, const std::string &title,
                const std::string &path, std::string &error) {
  if (points.empty()) {
    error = "write_plot: no points to plot for '" + path + "'";
    return false;
  }
  double max_time = 0.0;
  double max_error = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const PlotPoint &p = points[i];
    if (!finite_point(p) || p.time_ms < 0.0 || p.error < 0.0) {
      error = "write_plot: point " + std::to_string(i) + " ('" + p.label +
              "') has a negative or non-finite time or error; not writing '" + path + "'";
      return false;
    }
    max_time = std::max(max_time, p.time_ms);
    max_error = std::max(max_error, p.error * 100.0);
  }
  const Mapping m{make_axis(max_time), make_axis(max_error)};

  const media::ImageFiles *files = media::image_files(error);
  if (files == nullptr) {
    error = "write_plot: cannot write '" + path + "': " + error;
    return false;
  }
  Painter img{{kWidth, kHeight, std::vector<std::uint8_t>(std::size_t(kWidth) * kHeight * 3)},
              *files};
  files->fill(img.canvas, kWhite.v);

  const int title_scale = text_width(title, kTitleScale) <= kWidth - 20 ? kTitleScale : kTextScale;
  draw_text(img, std::max(4, (kWidth - text_width(title, title_scale)) / 2), 10, title,
            title_scale, kBlack);
  draw_axes(img, m);

  // Labels take palette colours in order of first appearance.
  std::vector<std::string> labels;
  std::vector<std::size_t> colour_of(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto it = std::find(labels.begin(), labels.end(), points[i].label);
    colour_of[i] = static_cast<std::size_t>(it - labels.begin()) % kPaletteSize;
    if (it == labels.end()) labels.push_back(points[i].label);
  }

  // The front goes under the points so every point's colour stays visible.
  const std::vector<std::size_t> front = pareto_front(points);
  for (std::size_t k = 1; k < front.size(); ++k) {
    const PlotPoint &a = points[front[k - 1]];
    const PlotPoint &b = points[front[k]];
    draw_thick_line(img, m.px(a.time_ms), m.py(a.error * 100.0), m.px(b.time_ms),
                    m.py(b.error * 100.0), kFront);
  }
  for (std::size_t i : front)
    draw_ring(img, m.px(points[i].time_ms), m.py(points[i].error * 100.0), kFront);
  for (std::size_t i = 0; i < points.size(); ++i)
    draw_square(img, m.px(points[i].time_ms), m.py(points[i].error * 100.0),
                kPalette[colour_of[i]]);

  int y = kPlotTop + 5;
  for (std::size_t l = 0; l < labels.size(); ++l) {
    draw_square(img, kLegendX + kPointHalf, y + 5, kPalette[l % kPaletteSize]);
    draw_text(img, kLegendX + 18, y, fit(labels[l], kLegendX + 18), kTextScale, kBlack);
    y += 20;
  }
  draw_thick_line(img, kLegendX - 4, y + 5, kLegendX + 10, y + 5, kFront);
  draw_ring(img, kLegendX + kPointHalf, y + 5, kFront);
  draw_text(img, kLegendX + 18, y, "pareto front", kTextScale, kBlack);

  // The format is named so the file is a PNG whatever the path's extension says.
  std::string write_error;
  if (!files->write_rgb(path, "png", kWidth, kHeight, img.canvas.rgb.data(), write_error)) {
    error = "write_plot: cannot write '" + path + "': " + write_error;
    return false;
  }
  return true;
}

}  // namespace gs
