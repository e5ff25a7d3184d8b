#pragma once
// Reading a finished result file back (`assess`, `check-result`, a study's summary, the track
// store): datasets, attributes and the names in a group. Read-only.
//
// A result file is input like any other, and this class is the one place its readers go through,
// so every guard against a forged file is here:
// - only a regular file is opened (a FIFO would block the open, a device or folder is no result);
// - a file holding a link that leaves it (an HDF5 external link or a user-defined link) is
//   refused as a whole: a reader must never read, nor a writer write, another file through it
//   (a soft link names a path of the same file and stays inside once no external link exists);
// - nothing is allocated from a declared size the file cannot hold: a dataset's or attribute's
//   declared bytes are compared with the file's (datasets with filters may expand up to
//   deflate's largest ratio);
// - samples() gives the samples of a signal only when every one is finite.
// These refusals throw BadResult naming the file and the dataset, attribute or link; the other
// failures (absent, another shape) are an empty answer, so the caller says what is missing.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rb::io {

// A result file (or a track store it references) that must not be read: not a regular file, a
// link leaving the file, a declared size beyond the file's bytes, a non-finite sample where
// finite ones are required. Bad input (exit 1), never a bug. The message names the file and the
// dataset's path ("r.h5: /bodies/ws1/y declares ...").
class BadResult : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ResultReader {
 public:
  // Opens `path` read-only; ok() is false when it does not exist or is not an HDF5 file that can
  // be read. Throws BadResult when it exists but is not a regular file, or holds a link that
  // leaves it.
  explicit ResultReader(const std::string& path);
  ~ResultReader();
  ResultReader(const ResultReader&) = delete;
  ResultReader& operator=(const ResultReader&) = delete;

  bool ok() const { return file_ >= 0; }
  const std::string& path() const { return path_; }
  // The object (group or dataset) exists.
  bool has(const std::string& path) const;
  // A 1-D dataset read as float64; nullopt when absent or not 1-D. Throws BadResult when it
  // declares more data than the file can hold.
  std::optional<std::vector<double>> dataset(const std::string& path) const;
  // dataset(), and every sample finite: throws BadResult naming the path and the first sample
  // that is NaN or infinite (a signal a computation uses: one NaN would spread to its results).
  std::optional<std::vector<double>> samples(const std::string& path) const;
  // Why `values` (read from `path`) cannot be used in a computation: "r.h5: /x holds NaN at
  // sample 3 of 100 ...", nullopt when every value is finite. samples() throws this message.
  std::optional<std::string> nonFiniteSample(const std::string& path,
                                             const std::vector<double>& values) const;
  // A 1-D dataset of fixed-length strings (the /schema tables); nullopt when absent or not one.
  std::optional<std::vector<std::string>> strings(const std::string& path) const;
  // A numeric attribute of a group or dataset holding one value; nullopt when absent or not one.
  std::optional<double> number(const std::string& object, const std::string& name) const;
  // number(), and finite: throws BadResult naming "object@name" when it is NaN or infinite.
  std::optional<double> finiteNumber(const std::string& object, const std::string& name) const;
  // A string attribute holding one string (fixed or variable length); nullopt when absent.
  std::optional<std::string> text(const std::string& object, const std::string& name) const;
  // Names of the attributes of a group or dataset (in name order), empty when it is absent.
  std::vector<std::string> attributes(const std::string& object) const;
  // Names of the members of a group (sorted), empty when it is not a group.
  std::vector<std::string> members(const std::string& group) const;
  // Where each vehicle's groups (/bodies, /contact, /assessment, ...) are: {""} for a run of one
  // vehicle, "/vehicles/<name>" for each vehicle of a run of several, front to rear (the order
  // of the attribute `names` of /vehicles; sorted by name when it is missing).
  std::vector<std::string> vehicleGroups() const;
  // The floating-point datasets and attributes that hold a NaN or an infinity, in the order of
  // the file's name index ("/bodies/ws1/y", an attribute as "/stats@t_reached"), at most `limit`
  // of them. Every element of every dataset is read: the cost is one pass over the file. Throws
  // BadResult as dataset() does.
  std::vector<std::string> nonFinite(std::size_t limit) const;

 private:
  std::string path_;
  std::int64_t file_ = -1;
  std::uint64_t bytes_ = 0;  // the file's size, the bound of every declared size
};

namespace detail {
// Throws BadResult naming `name` and the link when the open HDF5 file `file` holds an external or
// user-defined link (ResultFile's update of an existing result checks its copy so).
void requireSelfContained(std::int64_t file, const std::string& name);
}  // namespace detail

}  // namespace rb::io
