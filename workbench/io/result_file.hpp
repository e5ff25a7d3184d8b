#pragma once
// The HDF5 result file (architecture.md, "Output layout"). This folder is the only code that
// includes HDF5 headers; the rest of the engine sees this small interface.
//
// A file is written under "<path>.tmp" and renamed to <path> by finalize(), so a reader never sees
// a half-written result under the final name. Time series are appendable and flushed in chunks so
// a run that fails keeps everything written so far (finalize() is still called, with
// /stats/status = "failed").
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rb::io {

class ResultFile;

// An appendable 1-D float64 dataset with a `units` attribute, buffered in memory between flushes.
class Series {
 public:
  void append(double v) { buffer_.push_back(v); }
  std::size_t size() const { return written_ + buffer_.size(); }

 private:
  friend class ResultFile;
  Series(ResultFile* file, std::int64_t dataset) : file_(file), dataset_(dataset) {}
  ResultFile* file_;
  std::int64_t dataset_;
  std::size_t written_ = 0;
  std::vector<double> buffer_;
};

class ResultFile {
 public:
  // Creates "<path>.tmp" (truncating). Throws std::runtime_error naming the path on failure.
  explicit ResultFile(std::string path);
  ~ResultFile();
  ResultFile(const ResultFile&) = delete;
  ResultFile& operator=(const ResultFile&) = delete;

  const std::string& path() const { return path_; }
  std::string tmpPath() const { return path_ + ".tmp"; }

  // Attributes on a group (created with intermediate groups as needed; "/" is the root).
  void attr(const std::string& group, const std::string& name, const std::string& value);
  void attr(const std::string& group, const std::string& name, double value);
  void attr(const std::string& group, const std::string& name, std::int64_t value);

  // A complete 1-D dataset with a `units` attribute (SI, "-" for dimensionless).
  void dataset(const std::string& path, const std::vector<double>& data, const std::string& units);
  // A complete 2-D dataset, row-major data of rows x cols (e.g. a table over gauge x y).
  void dataset2d(const std::string& path, std::size_t rows, std::size_t cols,
                 const std::vector<double>& data, const std::string& units);
  // An appendable dataset; the returned Series lives as long as this file.
  Series& series(const std::string& path, const std::string& units);

  // Writes buffered series data and flushes the file to disk.
  void flush();
  // Flushes, closes and renames "<path>.tmp" to <path>. Idempotent.
  void finalize();

 private:
  std::int64_t group(const std::string& path);  // opens or creates; caller closes
  void flushSeries(Series& s);
  std::string path_;
  std::int64_t file_ = -1;
  bool finalized_ = false;
  std::vector<std::unique_ptr<Series>> series_;
};

}  // namespace rb::io
