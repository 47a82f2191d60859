// Starts the `candela` executable (CANDELA_BINARY) as a child process, for the tests that watch
// it while it runs (a signal, its threads' CPU time).
#pragma once

#include <fcntl.h>
#include <spawn.h>
#include <sys/types.h>

#include <string>
#include <vector>

extern char** environ;  // for posix_spawn

namespace candela::test {

// Runs CANDELA_BINARY with `args` (those after its name), standard input from /dev/null and
// standard output and error into the files named (an empty name: the test's own); the child's
// pid, or -1 where it could not start.
inline pid_t spawnCandela(std::vector<std::string> args, const std::string& stdoutFile,
                          const std::string& stderrFile) {
  std::string binary = CANDELA_BINARY;
  std::vector<char*> argv = {binary.data()};
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  if (!stdoutFile.empty())
    posix_spawn_file_actions_addopen(&actions, 1, stdoutFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
  if (!stderrFile.empty())
    posix_spawn_file_actions_addopen(&actions, 2, stderrFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return spawned == 0 ? pid : -1;
}

}  // namespace candela::test
