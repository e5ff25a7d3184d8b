#pragma once
// The HDF5 result file (architecture.md, "Output layout"). This folder is the only code that
// includes HDF5 headers; the rest of the engine sees this small interface.
//
// Life cycle: a file is written under a temporary name of its own, "<path>.tmp.<host>.<pid>.<n>",
// created exclusively (two runs writing the same <path> never share a temporary); the temporaries
// of <path> left by processes of this host that no longer exist (killed) are removed then.
// finalize() flushes, closes and only then renames it over <path>, so <path> only ever holds a
// complete, closed file. A file that is not finalized (an exception, a run that did not start) is
// closed and deleted by the destructor: an earlier result at <path> is never replaced by a run that
// did not run. Every HDF5 call is checked; a failure (disk full, I/O error) throws WriteError and
// the temporary is deleted. Time series are appendable and flushed in chunks so a run that fails
// keeps everything written so far (its caller finalizes it with /stats/status = "failed").
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace rb::io {

// The result could not be written (disk full, I/O error, no permission): an environment problem,
// not a bug. Nothing was left under the final name.
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ResultFile;

// Samples per HDF5 chunk of an appendable series: a writer that flushes every kSeriesChunk
// samples writes whole chunks only.
inline constexpr std::size_t kSeriesChunk = 1024;

// An appendable 1-D float64 dataset with a `units` attribute, buffered in memory between flushes.
class Series {
 public:
  void append(double v) { buffer_.push_back(v); }
  std::size_t size() const { return written_ + buffer_.size(); }

 private:
  friend class ResultFile;
  explicit Series(std::int64_t dataset) : dataset_(dataset) {}
  std::int64_t dataset_;
  std::size_t written_ = 0;
  std::vector<double> buffer_;
};

class ResultFile {
 public:
  // How the file stores its time series. Compact, for the many small files of a study: the
  // chunks of every series are shuffled and deflate-compressed (lossless: a reader gets back the
  // very bytes written; the padding of a partly filled chunk costs almost nothing) and the chunk
  // index nodes are small. Plain files are read by any HDF5 reader without filters.
  enum class Storage { Plain, Compact };
  // Creates the temporary beside `path`. Throws WriteError naming the path on failure.
  explicit ResultFile(std::string path, Storage storage = Storage::Plain);
  // Updates the existing result `path`: the temporary is a copy of it, opened for writing, and
  // finalize() renames it over `path`, so a failed update leaves `path` as it was. Throws
  // WriteError when `path` cannot be copied or opened.
  struct UpdateExisting {};
  ResultFile(std::string path, UpdateExisting);
  // Closes and deletes the temporary unless finalize() succeeded; never throws.
  ~ResultFile();
  ResultFile(const ResultFile&) = delete;
  ResultFile& operator=(const ResultFile&) = delete;

  const std::string& path() const { return path_; }
  const std::string& tmpPath() const { return tmp_; }

  // Attributes on a group (created with intermediate groups as needed; "/" is the root). String
  // attributes may be large (a whole scenario text): they use HDF5's dense attribute storage.
  void attr(const std::string& group, const std::string& name, const std::string& value);
  void attr(const std::string& group, const std::string& name, double value);
  void attr(const std::string& group, const std::string& name, std::int64_t value);

  // A complete 1-D dataset with a `units` attribute (SI, "-" for dimensionless).
  void dataset(const std::string& path, const std::vector<double>& data, const std::string& units);
  // A complete 2-D dataset, row-major data of rows x cols (e.g. a table over gauge x y).
  void dataset2d(const std::string& path, std::size_t rows, std::size_t cols,
                 const std::vector<double>& data, const std::string& units);
  // A complete 1-D dataset of fixed-length UTF-8 strings (names that index another dataset).
  void stringDataset(const std::string& path, const std::vector<std::string>& values);
  // Removes a group or dataset (and everything below it) when it exists.
  void remove(const std::string& path);
  // An appendable dataset; the returned Series lives as long as this file.
  Series& series(const std::string& path, const std::string& units);

  // Writes buffered series data and flushes the file to disk. Throws WriteError.
  void flush();
  // Flushes, closes and renames the temporary to path(). Throws WriteError (the temporary is then
  // deleted and path() is left as it was). Idempotent after success.
  void finalize();
  // Closes and deletes the temporary; path() is left as it was. Never throws.
  void discard() noexcept;
  bool finalized() const { return finalized_; }

 private:
  // Opens or creates the group (with its missing parents); the handle stays open in groups_
  // until the file is closed, so the caller does not close it.
  std::int64_t group(const std::string& path);
  // The group holding `path` ("/a/b/c" -> "/a/b", "/c" -> "/") and the name in it ("c").
  std::int64_t parentGroup(const std::string& path, std::string& leaf);
  void closeGroups() noexcept;
  void flushSeries(Series& s);
  void closeAll() noexcept;
  [[noreturn]] void fail(const std::string& what, const std::string& name);
  std::string path_;
  std::string tmp_;
  std::int64_t file_ = -1;
  bool finalized_ = false;
  Storage storage_ = Storage::Plain;
  std::vector<std::unique_ptr<Series>> series_;
  // The groups opened so far, by path: a result has hundreds of datasets in a few dozen groups,
  // and looking a group up again walks the path through the file's group structure each time.
  std::map<std::string, std::int64_t, std::less<>> groups_;
};

}  // namespace rb::io
