#pragma once
// On-disk cache of the contact tables (LUT, KEC), keyed by configHash(config), so a parameter
// sweep whose cases run as separate processes builds each distinct table once.
//
// File format (version kTableFormatVersion), every number as the machine stores it in memory
// (little-endian IEEE doubles and uint64 on the platforms we build for). Cache files are
// MACHINE-LOCAL: do not ship them between machines; a file written with another byte order is
// rejected by the byte-order marker and rebuilt.
//   char[16] magic "railbench-lut" / "railbench-kec", zero padded
//   u64      byte-order marker 0x0102030405060708
//   u64      format version
//   u64      config hash
//   u64      payload size in bytes
//   ...      payload: channel count, grids, sizes, every member the evaluation reads (raw doubles),
//            jumps / two-point contacts / transitions, build statistics (warnings, notes)
//   u64      checksum (FNV-1a 64, word-wise) of everything before it
// The KEC equivalent-profile splines are not stored: they are rebuilt from the stored node values
// with the builder's own code (KecTable::makeFSpline), which reproduces the coefficients bit for
// bit. Loaded tables evaluate bit-identically to the built ones and keep their build statistics
// (stats().build_seconds is the time of the original build).
//
// Writes go to a unique "<path>.tmp.<random>" file that is then renamed over <path> (atomic on
// POSIX file systems), so readers never see a partial file and two processes racing to write the
// same table (identical content) are harmless.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "workbench/contact/config.hpp"
#include "workbench/contact/kec.hpp"
#include "workbench/contact/lut.hpp"

namespace rb::contact {

inline constexpr std::uint64_t kTableFormatVersion = 1;

// Write the table to `path` (atomically, see above). Throws std::runtime_error naming the path on
// any I/O error.
void saveTable(const LutTable& table, const std::string& path);
void saveTable(const KecTable& table, const std::string& path);

// The table stored in `path` if the file is a complete, uncorrupted table file of this format
// version whose config hash is `expected_hash`; std::nullopt otherwise (missing, truncated,
// corrupt, other magic / version / byte order / hash). Never throws for a bad file.
std::optional<LutTable> loadLut(const std::string& path, std::uint64_t expected_hash);
std::optional<KecTable> loadKec(const std::string& path, std::uint64_t expected_hash);

// "0123456789abcdef": the 16 lowercase hex digits of a config hash (cache file stem).
std::string hashHex(std::uint64_t hash);

// A directory of cached tables: <dir>/<configHash as 16 hex>.lut and .kec. Each call loads the
// file when it is valid for the config, otherwise builds the table (buildLut / buildKec, which
// throw rb::InputError for a bad config), saves it and returns it. Stateless apart from the
// directory: safe to use from several threads and processes at once (a table two of them miss at
// the same time is built by both; the second rename replaces the first with identical content).
// No in-memory memoisation: keep the returned pointer to reuse a table within a process.
class DiskTableCache {
 public:
  // Creates the directory (and parents) if missing; throws std::runtime_error if that fails.
  explicit DiskTableCache(std::string directory);

  const std::string& directory() const { return dir_; }
  std::string lutPath(const ContactGeometryConfig& config) const;
  std::string kecPath(const ContactGeometryConfig& config) const;

  // *built (if given) is set to true when the table was built (and saved), false when loaded.
  // A failure to save the built table throws std::runtime_error (the cache directory is unusable).
  std::shared_ptr<const LutTable> lut(const ContactGeometryConfig& config,
                                      bool* built = nullptr) const;
  std::shared_ptr<const KecTable> kec(const ContactGeometryConfig& config,
                                      bool* built = nullptr) const;

 private:
  std::string dir_;
};

}  // namespace rb::contact
