// Running a command-line program as a user would, for tests of its output and exit status.
#pragma once

#include <string>

struct ToolRun {
  int exit_code = -1;  // -1 when it could not be started or did not exit normally
  std::string output;  // stdout and stderr
};

// `program arguments 2>&1` through the shell.
ToolRun run_tool(const std::string &program, const std::string &arguments);
