#pragma once
// Internal helpers shared by the integrator implementations (not part of the module's API).
#include <bit>
#include <cmath>
#include <cstdint>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "workbench/integrators/ode.hpp"

namespace rb::integ::detail {

// True when every v[i] is finite: no exponent field is all ones. Integer OR-reduction without
// branches, so the compiler vectorises it (a floating-point sum would be a serial chain).
inline bool allFinite(const double* v, long n) {
  constexpr std::uint64_t kExp = 0x7ff0000000000000ULL;
  std::uint64_t bad = 0;
  for (long i = 0; i < n; ++i)
    bad |= static_cast<std::uint64_t>((std::bit_cast<std::uint64_t>(v[i]) & kExp) == kExp);
  return bad == 0;
}

std::vector<int> nonFiniteComponents(const double* v, long n);

using NameFn = std::function<std::string(int)>;
// "x2, x3" (at most 8 names, then "and 5 more").
std::string componentList(const std::vector<int>& comps, const NameFn& name);

// What the model did on its last failing call, recorded by the callback wrappers. Only written on
// failure paths (may allocate there).
struct RhsRecord {
  int code = 0;                // last non-zero return of rhs/residual/jacobian
  double t = 0.0;              // time of that call
  std::string what;            // "right-hand side", "Jacobian", "residual"
  std::string model_error;     // the model's lastError() right after that call
  ModelFailure model_failure;  // and its lastFailure()
  bool nonfinite = false;      // a NaN/Inf was seen (latest event below)
  double nonfinite_t = 0.0;
  std::string nonfinite_where;  // "derivative", "state", "residual", "Jacobian"
  std::vector<int> nonfinite_comps;
  std::exception_ptr exception;  // thrown by the model inside a C callback, rethrown later
  long recoverable = 0;          // recoverable failures (> 0 returns, NaN/Inf turned recoverable)

  void recordCode(int c, double tt, const char* w, std::string err, ModelFailure why = {}) {
    code = c;
    t = tt;
    what = w;
    model_error = std::move(err);
    model_failure = std::move(why);
  }
  void recordNonFinite(double tt, const char* where, const double* v, long n) {
    nonfinite = true;
    nonfinite_t = tt;
    nonfinite_where = where;
    nonfinite_comps = nonFiniteComponents(v, n);
  }
  // "right-hand side returned -1 at t = 0.55: <model error>"
  std::string describeCode() const;
  // "NaN/Inf in the derivative of x2 at t = 0.5"
  std::string describeNonFinite(const NameFn& name) const;
};

// CPU (process) and wall clocks in seconds.
double cpuSeconds();
double wallSeconds();

}  // namespace rb::integ::detail
