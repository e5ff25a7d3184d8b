#include "workbench/core/error.hpp"

namespace rb {
namespace {
std::string joinDiagnostics(const std::vector<Diagnostic>& diags) {
  std::string out;
  for (const auto& d : diags) {
    if (!out.empty()) out += '\n';
    out += d.str();
  }
  return out;
}
}  // namespace

std::string SourceLoc::str() const {
  if (line > 0) return file + ":" + std::to_string(line);
  return file.empty() ? std::string("<unknown>") : file;
}

std::string Diagnostic::str() const {
  return loc.str() + ": " + message;
}

InputError::InputError(std::vector<Diagnostic> diags)
    : std::runtime_error(joinDiagnostics(diags)), diags_(std::move(diags)) {}

InputError::InputError(const SourceLoc& loc, const std::string& message)
    : InputError(std::vector<Diagnostic>{Diagnostic{loc, message}}) {}

void Diagnostics::add(const SourceLoc& loc, std::string message) {
  diags_.push_back(Diagnostic{loc, std::move(message)});
}

void Diagnostics::add(const InputError& e) {
  for (const auto& d : e.diagnostics()) diags_.push_back(d);
}

void Diagnostics::throwIfAny() const {
  if (!diags_.empty()) throw InputError(diags_);
}

void checkFailed(const char* expr, const char* file, int line, const std::string& msg) {
  throw std::logic_error(std::string("internal error at ") + file + ":" + std::to_string(line) +
                         ": check '" + expr + "' failed: " + msg);
}

}  // namespace rb
