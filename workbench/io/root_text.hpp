#pragma once
// One text attribute on the root group of an existing, closed HDF5 file: studies stamp each case
// result with the hash of its inputs after the run, and read it back to decide whether the result
// is still valid for the current inputs.
#include <optional>
#include <string>

namespace rb::io {

// The attribute's text; nullopt when the path is not a regular file, is not a readable HDF5 file,
// or has no such text attribute on "/".
std::optional<std::string> readRootText(const std::string& path, const std::string& name);

// Opens the file read-write, sets (or replaces) the attribute, flushes and closes it. False on any
// failure; the caller must then not trust the file.
bool writeRootText(const std::string& path, const std::string& name, const std::string& value);

}  // namespace rb::io
