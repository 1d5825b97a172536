// X screenshots, X tools and child processes for the window tests.
#include "x_session.h"

#include <OpenImageIO/imageio.h>

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>

namespace window_test {
namespace {

// The xwd file header (X11/XWDFile.h): 25 big-endian 32-bit fields, then the window name.
enum XwdField {
  kHeaderSize = 0, kFileVersion = 1, kPixmapFormat = 2, kPixmapWidth = 4, kPixmapHeight = 5,
  kByteOrder = 7, kBitsPerPixel = 11, kBytesPerLine = 12, kVisualClass = 13, kRedMask = 14,
  kGreenMask = 15, kBlueMask = 16, kColorCount = 19, kFieldCount = 25
};
constexpr std::uint32_t kZPixmap = 2, kTrueColor = 4, kDirectColor = 5, kXwdVersion = 7;
constexpr std::size_t kXwdColorBytes = 12;  // one XWDColor entry

std::uint32_t big_endian_32(const std::string &bytes, std::size_t offset) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    value = (value << 8) | static_cast<unsigned char>(bytes[offset + i]);
  }
  return value;
}

// The 8-bit channel under `mask` (8 contiguous bits in the visuals Xvfb offers).
std::uint8_t channel(std::uint32_t pixel, std::uint32_t mask) {
  int shift = 0;
  while (shift < 32 && ((mask >> shift) & 1u) == 0) ++shift;
  return static_cast<std::uint8_t>((pixel & mask) >> shift);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

bool read_xwd(const std::string &path, RgbImage &image, std::string &error) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < kFieldCount * 4) {
    error = path + " is not an xwd file (too short)";
    return false;
  }
  std::array<std::uint32_t, kFieldCount> header{};
  for (std::size_t i = 0; i < header.size(); ++i) header[i] = big_endian_32(bytes, 4 * i);
  const std::uint32_t bits = header[kBitsPerPixel];
  if (header[kFileVersion] != kXwdVersion || header[kPixmapFormat] != kZPixmap ||
      (header[kVisualClass] != kTrueColor && header[kVisualClass] != kDirectColor) ||
      (bits != 24 && bits != 32)) {
    error = path + ": only version-7 ZPixmap TrueColor dumps of 24 or 32 bits are read";
    return false;
  }
  image.width = static_cast<int>(header[kPixmapWidth]);
  image.height = static_cast<int>(header[kPixmapHeight]);
  const std::size_t stride = header[kBytesPerLine];
  const std::size_t data = header[kHeaderSize] + header[kColorCount] * kXwdColorBytes;
  if (bytes.size() < data + stride * static_cast<std::size_t>(image.height)) {
    error = path + " is truncated";
    return false;
  }
  const bool lsb_first = header[kByteOrder] == 0;
  const std::size_t pixel_bytes = bits / 8;
  image.rgb.resize(static_cast<std::size_t>(image.width) * image.height * 3);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::size_t at = data + y * stride + x * pixel_bytes;
      std::uint32_t pixel = 0;
      for (std::size_t b = 0; b < pixel_bytes; ++b) {
        const std::uint32_t byte = static_cast<unsigned char>(bytes[at + b]);
        pixel |= lsb_first ? byte << (8 * b) : byte << (8 * (pixel_bytes - 1 - b));
      }
      std::uint8_t *out = &image.rgb[(static_cast<std::size_t>(y) * image.width + x) * 3];
      out[0] = channel(pixel, header[kRedMask]);
      out[1] = channel(pixel, header[kGreenMask]);
      out[2] = channel(pixel, header[kBlueMask]);
    }
  }
  return true;
}

bool read_png(const std::string &path, RgbImage &image, std::string &error) {
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
  if (!in) {
    error = "cannot read " + path + ": " + OIIO::geterror();
    return false;
  }
  const OIIO::ImageSpec &spec = in->spec();
  image.width = spec.width;
  image.height = spec.height;
  std::vector<std::uint8_t> all(static_cast<std::size_t>(spec.width) * spec.height *
                                static_cast<std::size_t>(spec.nchannels));
  if (spec.nchannels < 3 || !in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8,
                                            all.data())) {
    error = "cannot read RGB pixels from " + path;
    return false;
  }
  image.rgb.resize(static_cast<std::size_t>(spec.width) * spec.height * 3);
  for (std::size_t i = 0; i < image.rgb.size() / 3; ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      image.rgb[3 * i + c] = all[i * static_cast<std::size_t>(spec.nchannels) + c];
    }
  }
  return true;
}

int run_command(const std::string &command, std::string *output) {
  FILE *pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return -1;
  std::string text;
  char buffer[512];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) text.append(buffer, n);
  const int status = pclose(pipe);
  if (output != nullptr) *output = text;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string window_of_process(pid_t pid, bool wait) {
  std::string output;
  const std::string command = std::string(wait ? "timeout 10 xdotool search --sync" : "xdotool search") +
                              " --onlyvisible --pid " + std::to_string(pid);
  if (run_command(command, &output) != 0) return "";
  return output.substr(0, output.find('\n'));
}

bool screenshot(const std::string &window_id, const std::string &xwd_path, RgbImage &image,
                std::string &error) {
  const std::string command = "xwd -silent -id " + window_id + " -out " + xwd_path;
  if (run_command(command) != 0) {
    error = "'" + command + "' failed (is xwd from x11-apps installed?)";
    return false;
  }
  return read_xwd(xwd_path, image, error);
}

ChildProcess::ChildProcess(const std::vector<std::string> &argv,
                           const std::vector<std::string> &environment) {
  int fds[2];
  if (pipe(fds) != 0) return;
  pid_ = fork();
  if (pid_ == 0) {
    dup2(fds[1], STDOUT_FILENO);
    close(fds[0]);
    close(fds[1]);
    for (const std::string &assignment : environment) putenv(const_cast<char *>(assignment.c_str()));
    std::vector<char *> args;
    for (const std::string &arg : argv) args.push_back(const_cast<char *>(arg.c_str()));
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
  }
  close(fds[1]);
  out_fd_ = fds[0];
}

ChildProcess::~ChildProcess() {
  if (pid_ > 0) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  if (out_fd_ >= 0) close(out_fd_);
}

bool ChildProcess::read_some(double seconds) {
  if (out_fd_ < 0) return false;
  pollfd fd{out_fd_, POLLIN, 0};
  if (poll(&fd, 1, static_cast<int>(seconds * 1000)) <= 0) return false;
  char buffer[512];
  const ssize_t n = read(out_fd_, buffer, sizeof buffer);
  if (n <= 0) return false;
  output_.append(buffer, static_cast<std::size_t>(n));
  return true;
}

bool ChildProcess::wait_for_line(const std::string &text, double seconds) {
  const auto start = std::chrono::steady_clock::now();
  while (true) {
    const std::size_t found = output_.find(text);
    if (found != std::string::npos && output_.find('\n', found) != std::string::npos) return true;
    const double left = seconds - seconds_since(start);
    if (left <= 0 || !read_some(left)) return false;
  }
}

int ChildProcess::wait_for_exit(double seconds) {
  if (pid_ <= 0) return -1;
  const auto start = std::chrono::steady_clock::now();
  while (seconds_since(start) < seconds) {
    // Keeps the pipe drained so the child never blocks on a full pipe.
    if (!read_some(0.05)) usleep(10000);
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      while (read_some(0.0)) {
      }
      return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
  }
  return -1;  // the destructor kills it
}

}  // namespace window_test
