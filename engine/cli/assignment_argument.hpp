#pragma once
// The NAME=VALUE argument of --set and --vary (washout run, washout study, the bench programs):
// split at the first '='; no '=' or an empty name is no assignment.
#include <optional>
#include <string>
#include <utility>

namespace washout::cli {

inline std::optional<std::pair<std::string, std::string>> split_assignment(const std::string& kv) {
  const auto eq = kv.find('=');
  if (eq == std::string::npos || eq == 0) return std::nullopt;
  return std::make_pair(kv.substr(0, eq), kv.substr(eq + 1));
}

}  // namespace washout::cli
