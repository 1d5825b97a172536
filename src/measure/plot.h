// A scatter plot of error against time as a PNG (OpenImageIO's drawing), with the Pareto front
// (the configurations no other is both faster and more accurate than) joined and marked, for
// the speed-against-error benchmark.
#pragma once

#include <string>
#include <vector>

namespace gs {

struct PlotPoint {
  double time_ms = 0.0;  // x
  double error = 0.0;    // y, a fraction (0.01 = 1%)
  std::string label;     // technique name; points sharing it share a colour
};

// The plot image's layout, in image pixels (origin top left): its size and the plot area the
// axes frame; the right margin holds the legend. Public so that a test can find where a point
// of known time and error must be drawn.
namespace plot_layout {
constexpr int kWidth = 900;
constexpr int kHeight = 600;
constexpr int kPlotLeft = 70;
constexpr int kPlotRight = 700;
constexpr int kPlotTop = 50;
constexpr int kPlotBottom = 540;
}  // namespace plot_layout

// Indices of the points on the Pareto front, ordered by time.
std::vector<std::size_t> pareto_front(const std::vector<PlotPoint> &points);

// Writes the plot (about 900x600): axes with ticks and values, one colour per label with a
// legend, the front joined by a line. False with `error` naming the problem.
bool write_plot(const std::vector<PlotPoint> &points, const std::string &title,
                const std::string &path, std::string &error);

// The plot's 3x5 bitmap font (upper case, digits, a few signs; '?' for the rest) for other
// images: `text` with its top-left corner at (x, y), `scale` image pixels per font pixel, into
// an 8-bit RGB image (rows from the top), clipped to its edges.
void draw_bitmap_text(std::vector<unsigned char> &rgb, int width, int height, int x, int y,
                      const std::string &text, int scale, const unsigned char colour[3]);
int bitmap_text_width(const std::string &text, int scale);

}  // namespace gs
