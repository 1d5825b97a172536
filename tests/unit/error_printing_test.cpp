// Errors a program sees without installing grErrorSetCallback (docs/porting.md#errors): the shim
// prints each distinct message once to stderr, at most 64 of them, GLIDESHIM_QUIET silences it,
// and with a callback nothing is printed; a missing GLIDESHIM_DUMP_DIR is one such error. Runs
// error_printing_program, whose own output is only its callback's "callback: " lines.
#include "tool_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#ifndef ERROR_PRINTING_PROGRAM
#error "ERROR_PRINTING_PROGRAM must name error_printing_program"
#endif

namespace {

namespace fs = std::filesystem;

// Runs the program with `environment` (NAME=value words, or empty) before it.
ToolRun run_program(const std::string &environment, const std::string &arguments) {
  return run_tool("env -u GLIDESHIM_QUIET -u GLIDESHIM_DUMP_DIR " + environment + " " +
                      ERROR_PRINTING_PROGRAM,
                  arguments);
}

std::vector<std::string> lines_of(const std::string &text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

std::size_t count_containing(const std::vector<std::string> &lines, const std::string &part) {
  return static_cast<std::size_t>(std::count_if(lines.begin(), lines.end(), [&](const std::string &l) {
    return l.find(part) != std::string::npos;
  }));
}

TEST(ErrorPrinting, EachDistinctErrorIsPrintedOnceWithoutACallback) {
  const ToolRun run = run_program("", "no-callback repeated");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::vector<std::string> lines = lines_of(run.output);
  ASSERT_EQ(lines.size(), 2u) << run.output;  // three clip errors and two blend errors
  EXPECT_EQ(count_containing(lines, "glide_shim: grClipWindow: (0,0)-(5000,10) is not inside"), 1u)
      << run.output;
  EXPECT_EQ(count_containing(lines, "[GLIDESHIM_ERR_OUT_OF_RANGE]"), 1u) << run.output;
  EXPECT_EQ(count_containing(lines, "glide_shim: grAlphaBlendFunction: "), 1u) << run.output;
  EXPECT_EQ(count_containing(lines, "[GLIDESHIM_ERR_INVALID_ENUM]"), 1u) << run.output;
}

TEST(ErrorPrinting, DistinctMessagesStopAtTheBoundAndSaySo) {
  const ToolRun run = run_program("", "no-callback many");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::vector<std::string> lines = lines_of(run.output);
  ASSERT_EQ(lines.size(), 65u) << run.output;  // 64 of the 100 messages, then the notice
  EXPECT_EQ(count_containing(lines, "glide_shim: grClipWindow: (0,0)-("), 64u);
  EXPECT_NE(lines.front().find("(0,0)-(1000,10)"), std::string::npos) << lines.front();
  EXPECT_EQ(lines.back(), "glide_shim: 64 different errors printed; further ones are not");
}

TEST(ErrorPrinting, QuietVariableSilencesIt) {
  for (const char *quiet : {"GLIDESHIM_QUIET=1", "GLIDESHIM_QUIET=yes"}) {
    const ToolRun run = run_program(quiet, "no-callback repeated");
    EXPECT_EQ(run.exit_code, 0) << quiet;
    EXPECT_EQ(run.output, "") << quiet;
  }
  // "0" and an empty value leave printing on.
  for (const char *loud : {"GLIDESHIM_QUIET=0", "GLIDESHIM_QUIET="}) {
    const ToolRun run = run_program(loud, "no-callback repeated");
    EXPECT_EQ(run.exit_code, 0) << loud;
    EXPECT_EQ(lines_of(run.output).size(), 2u) << loud << ": " << run.output;
  }
}

TEST(ErrorPrinting, WithACallbackNothingIsPrinted) {
  const ToolRun repeated = run_program("", "callback repeated");
  EXPECT_EQ(repeated.exit_code, 0);
  const std::vector<std::string> lines = lines_of(repeated.output);
  EXPECT_EQ(lines.size(), 5u) << repeated.output;  // every error, repeated ones too
  EXPECT_EQ(count_containing(lines, "callback: grClipWindow: (0,0)-(5000,10)"), 3u);
  EXPECT_EQ(count_containing(lines, "callback: grAlphaBlendFunction: "), 2u);
  EXPECT_EQ(count_containing(lines, "glide_shim:"), 0u) << repeated.output;

  const ToolRun many = run_program("", "callback many");
  EXPECT_EQ(many.exit_code, 0);
  EXPECT_EQ(lines_of(many.output).size(), 100u);
  EXPECT_EQ(count_containing(lines_of(many.output), "callback: grClipWindow: "), 100u);
}

TEST(ErrorPrinting, ACleanRunPrintsNothing) {
  const ToolRun run = run_program("", "no-callback swaps");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.output, "");
}

std::string scratch_dir(const std::string &name) {
  const fs::path path = fs::path(::testing::TempDir()) / ("error_printing_" + name);
  fs::remove_all(path);
  return path.string();
}

TEST(DumpDirectory, AMissingDirectoryIsReportedOnceNamingIt) {
  const std::string missing = scratch_dir("missing");  // removed, not created
  const std::string environment = "GLIDESHIM_DUMP_DIR=" + missing;
  const std::string expected =
      "grBufferSwap: GLIDESHIM_DUMP_DIR '" + missing + "' is not an existing directory";

  const ToolRun printed = run_program(environment, "no-callback swaps");  // two swaps
  EXPECT_EQ(printed.exit_code, 0);
  const std::vector<std::string> lines = lines_of(printed.output);
  ASSERT_EQ(lines.size(), 1u) << printed.output;
  EXPECT_EQ(lines[0].rfind("glide_shim: " + expected, 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find("[GLIDESHIM_ERR_BACKEND]"), std::string::npos) << lines[0];

  const ToolRun called = run_program(environment, "callback swaps");
  EXPECT_EQ(called.exit_code, 0);
  ASSERT_EQ(lines_of(called.output).size(), 1u) << called.output;
  EXPECT_EQ(called.output.rfind("callback: " + expected, 0), 0u) << called.output;
  EXPECT_FALSE(fs::exists(missing));
}

TEST(DumpDirectory, AnExistingDirectoryGetsEveryFrameAndNoError) {
  const std::string dir = scratch_dir("present");
  fs::create_directories(dir);
  const ToolRun run = run_program("GLIDESHIM_DUMP_DIR=" + dir, "callback swaps");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.output, "");
  EXPECT_TRUE(fs::is_regular_file(fs::path(dir) / "frame_00000.png"));
  EXPECT_TRUE(fs::is_regular_file(fs::path(dir) / "frame_00001.png"));
}

}  // namespace
