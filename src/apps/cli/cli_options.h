// Parsed command-line options of the subcommands, and the validators they share.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>

#include "apps/cli/backend.h"

namespace candela::cli {

// `candela render`; an absent optional keeps the scene file's value.
struct RenderOptions {
  std::string scene;
  std::string output;  // empty: out/<scene file stem>.png
  std::optional<uint32_t> spp;
  std::optional<uint64_t> seed;
  std::optional<uint32_t> maxDepth;
  int threads = 0;  // 0: all cores
  Backend backend = Backend::Auto;
  bool quiet = false;
};

// `candela info`.
struct InfoOptions {
  std::string scene;
};

// Accepts plain decimal integers only and strips leading zeros, because CLI11 would otherwise
// read "010" as octal, "0x10" as hex and wrap "-1" around for unsigned types.
inline CLI::Validator decimalInteger(bool positive) {
  return CLI::Validator(
      [positive](std::string& text) -> std::string {
        const bool digits =
            !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        if (!digits) return "expected a non-negative whole number, got '" + text + "'";
        const size_t first = text.find_first_not_of('0');
        text = first == std::string::npos ? "0" : text.substr(first);
        if (positive && text == "0") return "expected a positive whole number, got 0";
        return {};
      },
      positive ? "POSITIVE" : "");
}

// Accepts the names of backendFromName.
inline CLI::Validator backendChoice() {
  return CLI::Validator(
      [](std::string& name) -> std::string {
        Backend ignored;
        if (backendFromName(name, &ignored)) return {};
        return "expected auto, cpu or cuda, got '" + name + "'";
      },
      "{auto,cpu,cuda}");
}

}  // namespace candela::cli
