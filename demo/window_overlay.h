// What the demo's window draws over a rendered frame, through Glide's linear frame buffer (as a
// Glide game drew its HUD): panels of text in the plot's bitmap font, and pictures (the light's
// view, the shadow texture) copied into a corner. Screen pixels, y down, in the back buffer.
#pragma once

#include <glide.h>

#include <string>
#include <vector>

namespace gs::demo {

// 565 words of a width x height region, rows from the top.
struct Picture {
  int width = 0, height = 0;
  std::vector<FxU16> words;
};

// The top-left width x height of the back buffer.
Picture read_back_buffer(int width, int height);
// `picture` scaled (nearest) to fit `side` x `side`, with a one-pixel frame, at (x, y).
void draw_picture(const Picture &picture, int x, int y, int side);
// The alpha nibble of ARGB_4444 words (the shadow texture as step 5 reads it): white where
// it is 1111b, black where 0000b, grey between.
Picture alpha_nibble_picture(const Picture &words);
// Lines of text on a darkened panel whose top-left corner is at (x, y); `scale` screen pixels
// per font pixel, in `colour` (8-bit RGB; null: the overlay's pale yellow). Clipped to the screen.
void draw_text_panel(const std::vector<std::string> &lines, int x, int y, int scale,
                     int screen_width, int screen_height, const unsigned char *colour = nullptr);
// The height in screen pixels of such a panel of `lines` lines.
int text_panel_height(int lines, int scale);
// `text` broken at spaces into lines that, on such a panel, fit `width` screen pixels (a word
// wider than that gets a line of its own, clipped); lines after the first begin with `indent`.
std::vector<std::string> wrap_for_panel(const std::string &text, int width, int scale,
                                        const std::string &indent = "  ");

}  // namespace gs::demo
