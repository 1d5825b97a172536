#include "tool_run.h"

#include <cstdio>
#include <sys/wait.h>

ToolRun run_tool(const std::string &program, const std::string &arguments) {
  const std::string command = program + " " + arguments + " 2>&1";
  ToolRun run;
  std::FILE *pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return run;
  char buffer[4096];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) run.output.append(buffer, got);
  const int status = ::pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}
