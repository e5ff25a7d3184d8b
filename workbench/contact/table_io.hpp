#pragma once
// On-disk cache of the contact tables (LUT, KEC), so a parameter sweep whose cases run as separate
// processes builds each distinct table once.
//
// Keying. A table is determined by its inputs (the four profiles sample by sample, positioning,
// grids, KEC transition lengths, solver tolerances, the interpolation between the nodes:
// everything configHash covers) and by the code
// that builds it. tableInputKey() writes all of that out as a canonical byte string, together with
// the table kind, kTableAlgorithmVersion and the workbench version. The file name is a hash of
// that key; the file stores the key itself, and a load compares it byte for byte with the key
// expected by the caller. Any difference (another table, another algorithm version, another
// workbench version, a hash collision) is a cache miss: the table is built and the file replaced.
//
// Threat model. The checksum detects corruption, not tampering: anyone who can write to the cache
// folder can plant a self-consistent file (right key, right checksum, wrong numbers), and nothing
// computed from the file alone can prevent that offline. What the key does guarantee is that a
// file built for one table can never stand in for ANOTHER table: copying or renaming a valid file,
// rewriting its hash and recomputing its checksum does not make it load for a different input.
// Keep the cache folder as private as the results it speeds up.
//
// File format (version kTableFormatVersion), every number as the machine stores it in memory
// (little-endian IEEE doubles and uint64 on the platforms we build for). Cache files are
// MACHINE-LOCAL: do not ship them between machines; a file written with another byte order is
// rejected by the byte-order marker and rebuilt.
//   char[16] magic "railbench-lut" / "railbench-kec", zero padded
//   u64      byte-order marker 0x0102030405060708
//   u64      format version
//   u64      table-algorithm version
//   u64      key size in bytes, then the key (tableInputKey)
//   u64      payload size in bytes
//   ...      payload: channel count, grids, sizes, every member the evaluation reads (raw doubles),
//            jumps / two-point contacts / transitions, build statistics (warnings, notes)
//   u64      checksum (FNV-1a 64, word-wise) of everything before it
// The KEC equivalent-profile splines are not stored: they are rebuilt from the stored node values
// with the builder's own code (KecTable::makeFSpline), which reproduces the coefficients bit for
// bit. Loaded tables evaluate bit-identically to the built ones and keep their build statistics
// (stats().build_seconds is the time of the original build).
//
// Files are read only when they are regular files (a FIFO or device in the cache is a miss, never a
// hang). Writes go to a unique "<path>.tmp.<random>" file that is then renamed over <path> (atomic
// on POSIX file systems), so readers never see a partial file and two processes racing to write
// the same table (identical content) are harmless.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "workbench/contact/config.hpp"
#include "workbench/contact/kec.hpp"
#include "workbench/contact/lut.hpp"

namespace rb::contact {

// Version of the table-building code. RULE: bump it in the same commit as any change that can
// alter the content of a LUT or KEC table built from the same inputs (workbench/contact/
// {config,geometry,lut_build,kec_build}.cpp, the profile splines and readers
// they use, the grids' defaults are inputs and need no bump). Cached tables of any other version
// are then rebuilt, never reused. It is also part of a study case's input hash
// (workbench/study/runner.cpp).
inline constexpr std::uint64_t kTableAlgorithmVersion = 1;
// Layout of the cache file (see above); bumped when the layout changes (3: the LUT's per-node
// contact-point branches and jump threshold, LutTable::branch).
inline constexpr std::uint64_t kTableFormatVersion = 3;

enum class TableKind { Lut, Kec };

// The complete canonical description of what a table of `kind` is built from (see the header
// comment): kind, kTableAlgorithmVersion, the workbench version, every number of the config and
// every profile sample as raw IEEE bits. Equal keys <=> interchangeable tables.
std::string tableInputKey(const ContactGeometryConfig& config, TableKind kind);

// The complete bytes of a table file of `kind` around `payload` (header with `key`, the payload,
// the checksum: the format above), as saveTable writes them. For tools and tests that craft files.
std::string tableFileBytes(TableKind kind, const std::string& key, std::string_view payload);

// Write the table built from `config` to `path` (atomically, see above). Throws std::runtime_error
// naming the path on any I/O error.
void saveTable(const LutTable& table, const ContactGeometryConfig& config, const std::string& path);
void saveTable(const KecTable& table, const ContactGeometryConfig& config, const std::string& path);

// The table stored in `path` if the file is a regular, complete, uncorrupted table file of this
// format and algorithm version whose stored key equals tableInputKey(config, kind); std::nullopt
// otherwise (missing, not a regular file, truncated, corrupt, other magic / version / byte order /
// key). Never throws for a bad file.
std::optional<LutTable> loadLut(const std::string& path, const ContactGeometryConfig& config);
std::optional<KecTable> loadKec(const std::string& path, const ContactGeometryConfig& config);

// "0123456789abcdef": the 16 lowercase hex digits of a 64-bit hash.
std::string hashHex(std::uint64_t hash);

// A directory of cached tables: <dir>/<hash of tableInputKey as 16 hex>.lut and .kec. Each call
// loads the file when it is valid for the config, otherwise builds the table (buildLut / buildKec,
// which throw rb::InputError for a bad config), saves it and returns it. Stateless apart from the
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

  // *built (if given) is set to true when the table was built, false when loaded. A failure to
  // save the built table does not lose it: the table is returned and the reason put in
  // *save_error when given (else std::runtime_error is thrown: the cache directory is unusable).
  std::shared_ptr<const LutTable> lut(const ContactGeometryConfig& config, bool* built = nullptr,
                                      std::string* save_error = nullptr) const;
  std::shared_ptr<const KecTable> kec(const ContactGeometryConfig& config, bool* built = nullptr,
                                      std::string* save_error = nullptr) const;

 private:
  std::string dir_;
};

}  // namespace rb::contact
