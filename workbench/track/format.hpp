#pragma once
// File-name formatting for input-error messages (internal to the track module; numbers:
// core/strings.hpp formatNumberExact).
#include <filesystem>
#include <string>
#include <system_error>

namespace rb::track::detail {

// A data file's name in messages: relative to the working directory when it lies below it (as the
// scenario file is shown), else as resolved.
inline std::string displayPath(const std::string& path) {
  std::error_code ec;
  const std::filesystem::path rel = std::filesystem::proximate(path, ec);
  if (ec || rel.empty() || rel.is_absolute() || *rel.begin() == "..") return path;
  return rel.string();
}

}  // namespace rb::track::detail
