#pragma once
// Reading user input files (scenarios, modules, profiles, irregularity CSVs, cached tables) safely:
// only regular files are opened (a FIFO, device or socket would block or never end), with a size
// bound so that a huge file is a clear error instead of an exhausted memory.
#include <sys/types.h>

#include <cstddef>
#include <optional>
#include <string>

namespace rb {

// Default bound for text inputs (scenario modules, profiles, CSV tables) [bytes]. Large enough for
// a 1 km measured track at 1 mm spacing; override per call where more is legitimate.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{256} << 20;  // 256 MiB

// The whole content of `path`, or std::nullopt with `why` set ("no such file", "not a regular
// file (a FIFO)", "larger than 256 MiB", "cannot be read: ...") when it cannot be used.
std::optional<std::string> readRegularFile(const std::string& path, std::string& why,
                                           std::size_t max_bytes = kMaxInputFileBytes);

// What a file of st_mode `m` is when it is not a regular file: "a folder", "a FIFO", "a device",
// "a socket" or "not a regular file".
std::string fileKindName(mode_t m);

// True if `path` names an existing regular file (symlinks followed).
bool isRegularFile(const std::string& path);

}  // namespace rb
