// Writing what the tools show people: PNG images and masks, a numbered PNG sequence in a
// directory it owns, an animated GIF and a contact sheet of such a sequence. The encoding is
// OpenImageIO's, in the image files module (image_files.h); every function returns false with
// `error` saying why rather than stopping the program.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace gs::media {

// 8-bit RGB rows, top row first.
bool write_rgb_png(const std::string &path, int width, int height,
                   const std::vector<std::uint8_t> &rgb, std::string &error);
// A mask (non-zero: set) as a black and white PNG.
bool write_mask_png(const std::string &path, int width, int height,
                    const std::vector<std::uint8_t> &mask, std::string &error);

// The files `frame_NNNN.png` of a run in `directory`: created if missing, and cleared of the
// frame_NNNN.png files an earlier run left, so a shorter run never mixes with a longer one.
// Only files of exactly that pattern are removed.
bool prepare_frame_directory(const std::string &directory, std::string &error);
std::string frame_path(const std::string &directory, int index);  // DIR/frame_NNNN.png

// Up to 16 frames spread over the whole sequence, at half size, four to a row.
bool write_contact_sheet(const std::vector<std::string> &frames, const std::string &path,
                         std::string &error);
// Every frame at half size, `fps` frames per second.
bool write_gif(const std::vector<std::string> &frames, const std::string &path, int fps,
               std::string &error);

}  // namespace gs::media
