#pragma once
// Number and file-name formatting for input-error messages (internal to the track module).
#include <charconv>
#include <filesystem>
#include <string>
#include <system_error>

namespace rb::track::detail {

// Shortest text that reads back to the same double ("-500", "0.1", "1e-07"): echoes user input.
inline std::string num(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

// A data file's name in messages: relative to the working directory when it lies below it (as the
// scenario file is shown), else as resolved.
inline std::string displayPath(const std::string& path) {
  std::error_code ec;
  const std::filesystem::path rel = std::filesystem::proximate(path, ec);
  if (ec || rel.empty() || rel.is_absolute() || *rel.begin() == "..") return path;
  return rel.string();
}

}  // namespace rb::track::detail
