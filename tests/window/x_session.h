// Helpers for the window tests, which run under Xvfb: X screenshots read from xwd files, the
// X tools (xdotool, xwd) run as commands, and a Glide program started as a child process whose
// standard output the test reads line by line.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace window_test {

// 8-bit RGB pixels, rows from the top, as the frame export writes them.
struct RgbImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

// Reads an xwd dump of a TrueColor window (ZPixmap, 24 or 32 bits per pixel, either byte
// order); false with `error` set for anything else.
bool read_xwd(const std::string &path, RgbImage &image, std::string &error);
// Reads a PNG through OpenImageIO as 8-bit RGB.
bool read_png(const std::string &path, RgbImage &image, std::string &error);

// Runs a shell command; returns its exit status (-1 if it did not exit) and its stdout.
int run_command(const std::string &command, std::string *output = nullptr);

// The visible X window of process `pid` (by its _NET_WM_PID), waiting up to 10 s for it to
// appear when `wait`; "" if there is none.
std::string window_of_process(pid_t pid, bool wait = true);
// Screenshot of window `id` from the X server: what is on the display there, not what the
// program thinks it drew.
bool screenshot(const std::string &window_id, const std::string &xwd_path, RgbImage &image,
                std::string &error);

// A child process with its standard output on a pipe and extra environment variables.
class ChildProcess {
 public:
  ChildProcess(const std::vector<std::string> &argv, const std::vector<std::string> &environment);
  ~ChildProcess();  // kills the child if it still runs
  ChildProcess(const ChildProcess &) = delete;
  ChildProcess &operator=(const ChildProcess &) = delete;

  pid_t pid() const { return pid_; }
  // Reads output until a line containing `text` arrives (true) or `seconds` pass or the
  // output ends (false).
  bool wait_for_line(const std::string &text, double seconds);
  // Waits up to `seconds` for the exit; the exit status, or -1 on a timeout (child killed)
  // or a signal.
  int wait_for_exit(double seconds);
  const std::string &output() const { return output_; }  // everything read so far

 private:
  bool read_some(double seconds);  // false at end of output or timeout
  pid_t pid_ = -1;
  int out_fd_ = -1;
  std::string output_;
};

}  // namespace window_test
