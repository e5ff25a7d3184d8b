#pragma once
// Reading a finished result file back (the `assess` command recomputes /assessment from a
// result's datasets): datasets, attributes and the names in a group. Read-only; every failure is
// an empty answer, so the caller says what is missing.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rb::io {

class ResultReader {
 public:
  // Opens `path` read-only; ok() is false when it is not an HDF5 file that can be read.
  explicit ResultReader(const std::string& path);
  ~ResultReader();
  ResultReader(const ResultReader&) = delete;
  ResultReader& operator=(const ResultReader&) = delete;

  bool ok() const { return file_ >= 0; }
  // The object (group or dataset) exists.
  bool has(const std::string& path) const;
  // A 1-D float64 dataset; nullopt when absent or not 1-D.
  std::optional<std::vector<double>> dataset(const std::string& path) const;
  // A 1-D dataset of fixed-length strings (the /schema tables); nullopt when absent or not one.
  std::optional<std::vector<std::string>> strings(const std::string& path) const;
  // A numeric attribute of a group or dataset; nullopt when absent.
  std::optional<double> number(const std::string& object, const std::string& name) const;
  // A string attribute (fixed or variable length); nullopt when absent.
  std::optional<std::string> text(const std::string& object, const std::string& name) const;
  // Names of the members of a group (sorted), empty when it is not a group.
  std::vector<std::string> members(const std::string& group) const;
  // Where each vehicle's groups (/bodies, /contact, /assessment, ...) are: {""} for a run of one
  // vehicle, "/vehicles/<name>" for each vehicle of a run of several, front to rear (the order
  // of the attribute `names` of /vehicles; sorted by name when it is missing).
  std::vector<std::string> vehicleGroups() const;
  // The floating-point datasets and attributes that hold a NaN or an infinity, in the order of
  // the file's name index ("/bodies/ws1/y", an attribute as "/stats@t_reached"), at most `limit`
  // of them. Every element of every dataset is read: the cost is one pass over the file.
  std::vector<std::string> nonFinite(std::size_t limit) const;

 private:
  std::int64_t file_ = -1;
};

}  // namespace rb::io
