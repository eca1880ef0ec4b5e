#ifndef SCOUT_APPS_SCOUT_CLI_TEST_UTIL_H_
#define SCOUT_APPS_SCOUT_CLI_TEST_UTIL_H_

// Test-only: runs the scout binary (SCOUT_BINARY, set by CMake) as a user
// would, capturing its output and exit code.

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace scout::testing {

struct CliResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

// Runs a shell command, stderr into stdout; returns its output and exit code.
inline CliResult RunShell(const std::string& command) {
  CliResult r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  char buffer[4096];
  while (pipe != nullptr && fgets(buffer, sizeof(buffer), pipe) != nullptr) r.output += buffer;
  const int status = pipe != nullptr ? pclose(pipe) : -1;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// Returns a file's whole content ("" if it cannot be read).
inline std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline CliResult RunScout(const std::string& args) {
  return RunShell(std::string(SCOUT_BINARY) + " " + args);
}

// Starts scout with 'args' (which must include --out 'out'), sends it SIGINT
// 'signals' times back to back once 'out' exists (the commands make it after
// installing their handler; gives up waiting after 30 s) and 'delay_s' more
// seconds have passed, and returns its output and exit code.
inline CliResult RunScoutAndInterrupt(const std::string& args, const std::string& out,
                                      int signals = 1, double delay_s = 0.0) {
  std::string kills = delay_s > 0.0 ? "sleep " + std::to_string(delay_s) + "; " : "";
  for (int i = 0; i < signals; ++i) kills += "kill -INT $pid; ";
  const std::string script =
      "sh -c '" + std::string(SCOUT_BINARY) + " " + args + " & pid=$!; n=0; until [ -d " + out +
      " ] || [ $n -ge 300 ]; do sleep 0.1; n=$((n+1)); done; " + kills + "wait $pid; echo exit=$?'";
  CliResult r = RunShell(script);
  // The script's own exit code is wait's echo's; scout's is the one it prints.
  r.exit_code = -1;
  const size_t at = r.output.rfind("exit=");
  if (at != std::string::npos) r.exit_code = std::stoi(r.output.substr(at + 5));
  return r;
}

}  // namespace scout::testing

#endif  // SCOUT_APPS_SCOUT_CLI_TEST_UTIL_H_
