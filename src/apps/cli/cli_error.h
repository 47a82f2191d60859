// Exit codes of the candela CLI and the error type that carries one.
#pragma once

#include <stdexcept>
#include <string>

namespace candela::cli {

enum ExitCode : int {
  kExitOk = 0,
  kExitFailure = 1,       // render or I/O failure
  kExitUsage = 2,         // bad command line or bad scene
  kExitInterrupted = 130  // SIGINT, as shells report 128 + signal number
};

// A failure with a user-facing one-line message and the exit code it should end with.
class CliError : public std::runtime_error {
 public:
  CliError(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

}  // namespace candela::cli
