#pragma once
// Errors with source location (architecture.md, "Errors"): user input problems are collected as
// Diagnostics carrying file:line and thrown together as one InputError, so a scenario reports all
// of its problems at once. Internal invariants use RB_CHECK, which stays on in release builds.
#include <stdexcept>
#include <string>
#include <vector>

namespace rb {

// Where a value came from: a scenario file and line, or "<command line>" for --set overrides.
struct SourceLoc {
  std::string file;
  int line = 0;
  std::string str() const;  // "file:line", or "file" when line is 0
};

struct Diagnostic {
  SourceLoc loc;
  std::string message;
  std::string str() const;  // "file:line: message"
};

// One or more problems in user input. what() is all diagnostics, one per line.
class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<Diagnostic> diags);
  InputError(const SourceLoc& loc, const std::string& message);
  const std::vector<Diagnostic>& diagnostics() const { return diags_; }

 private:
  std::vector<Diagnostic> diags_;
};

// Collects problems; throwIfAny() raises them together.
class Diagnostics {
 public:
  void add(const SourceLoc& loc, std::string message);
  void add(const InputError& e);
  bool empty() const { return diags_.empty(); }
  std::size_t size() const { return diags_.size(); }
  const std::vector<Diagnostic>& items() const { return diags_; }
  void throwIfAny() const;

 private:
  std::vector<Diagnostic> diags_;
};

// Always-on invariant check for programming errors (not for user input).
[[noreturn]] void checkFailed(const char* expr, const char* file, int line, const std::string& msg);

}  // namespace rb

#define RB_CHECK(cond, msg)                                         \
  do {                                                              \
    if (!(cond)) ::rb::checkFailed(#cond, __FILE__, __LINE__, msg); \
  } while (0)
