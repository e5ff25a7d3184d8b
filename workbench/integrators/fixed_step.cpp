#include "workbench/integrators/fixed_step.hpp"

#include <cmath>

#include "workbench/core/error.hpp"

namespace rb::integ {

FixedStepIntegrator::FixedStepIntegrator(Method method, SolverSpec spec)
    : Integrator(std::move(spec)), method_(method) {}

FixedStepIntegrator::Status FixedStepIntegrator::eval(double t, const double* y, double* ydot) {
  ++stats_.rhs_evals;
  const int rc = sys_->rhs(t, y, ydot);
  if (rc != 0) {
    rec_.recordCode(rc, t, "right-hand side", sys_->lastError());
    if (rc > 0) {
      ++stats_.recoverable_rhs_failures;
      return Status::Recoverable;
    }
    return Status::Fatal;
  }
  if (!detail::allFinite(ydot, n_)) {
    rec_.recordNonFinite(t, "derivative", ydot, n_);
    return Status::NonFinite;
  }
  return Status::Ok;
}

// One classical RK4 step from (t, y_) into y_; y_ is only replaced when the step succeeded. k1
// receives f(t, y_) (ABM keeps it as history).
FixedStepIntegrator::Status FixedStepIntegrator::tryRk4(double t, double h, double* k1p) {
  Eigen::Map<Eigen::VectorXd> k1(k1p, n_);
  Status s = eval(t, y_.data(), k1p);
  if (s != Status::Ok) return s;
  const double hh = 0.5 * h;
  tmp_.noalias() = y_ + hh * k1;
  if ((s = eval(t + hh, tmp_.data(), k2_.data())) != Status::Ok) return s;
  tmp_.noalias() = y_ + hh * k2_;
  if ((s = eval(t + hh, tmp_.data(), k3_.data())) != Status::Ok) return s;
  tmp_.noalias() = y_ + h * k3_;
  if ((s = eval(t + h, tmp_.data(), k4_.data())) != Status::Ok) return s;
  ynew_.noalias() = y_ + (h / 6.0) * (k1 + 2.0 * k2_ + 2.0 * k3_ + k4_);
  if (!detail::allFinite(ynew_.data(), n_)) {
    rec_.recordNonFinite(t + h, "state", ynew_.data(), n_);
    return Status::NonFinite;
  }
  y_.swap(ynew_);  // pointer swap, no allocation
  ++stats_.steps;
  return Status::Ok;
}

// RK4 from t to t + h; on a recoverable rhs failure the step is discarded and split in halves.
FixedStepIntegrator::Status FixedStepIntegrator::advanceRk4(double t, double h, int depth,
                                                            double* k1) {
  const Status s = tryRk4(t, h, k1);
  if (s != Status::Recoverable) return s;
  ++stats_.rejected_steps;
  if (depth >= kMaxSplitDepth) return s;
  return splitRk4(t, h, depth + 1);
}

FixedStepIntegrator::Status FixedStepIntegrator::splitRk4(double t, double h, int depth) {
  const double hh = 0.5 * h;
  const Status s = advanceRk4(t, hh, depth, k1_.data());
  if (s != Status::Ok) return s;
  return advanceRk4(t + hh, hh, depth, k1_.data());
}

// Adams-Bashforth-Moulton, PECE, paper Eq. (32):
//   P: y*_n+1 = y_n + h (55 f_n - 59 f_n-1 + 37 f_n-2 - 9 f_n-3) / 24
//   E: f*_n+1 = f(t_n+1, y*_n+1)
//   C: y_n+1  = y_n + h (9 f*_n+1 + 19 f_n - 5 f_n-1 + f_n-2) / 24
//   E: f_n+1  = f(t_n+1, y_n+1)   (done at the start of the next step)
// NOTE: the corrector printed in the paper, (9 f_n+1 + 19 f_n - 5 f_n-1) / 24, drops the + f_n-2
// term (a typo: its weights sum to 23/24, so it is not even consistent). The 4th-order
// Adams-Moulton (AM3) corrector used here has weights 9, 19, -5, 1 (sum 24).
// The first 3 steps (and the 3 steps after a split step) are RK4, whose first stages are the
// history f_0, f_1, f_2.
FixedStepIntegrator::Status FixedStepIntegrator::abmStep(double t, double h) {
  const int slot = (head_ + 1) & 3;  // the oldest entry, f_n-4: receives f_n
  if (history_ < 3) {
    const long rejected = stats_.rejected_steps;
    const Status s = advanceRk4(t, h, 0, f_[slot].data());
    if (s != Status::Ok) return s;
    if (stats_.rejected_steps != rejected) {
      history_ = 0;  // split step: restart the history
    } else {
      head_ = slot;
      ++history_;
    }
    return Status::Ok;
  }
  Eigen::VectorXd& fn = f_[slot];
  const Eigen::VectorXd& fn1 = f_[head_];
  const Eigen::VectorXd& fn2 = f_[(head_ + 3) & 3];
  const Eigen::VectorXd& fn3 = f_[(head_ + 2) & 3];
  const double h24 = h / 24.0;
  Status s = eval(t, y_.data(), fn.data());
  if (s == Status::Ok) {
    tmp_.noalias() = y_ + h24 * (55.0 * fn - 59.0 * fn1 + 37.0 * fn2 - 9.0 * fn3);
    s = eval(t + h, tmp_.data(), k2_.data());
  }
  if (s == Status::Recoverable) {
    ++stats_.rejected_steps;
    history_ = 0;
    return splitRk4(t, h, 1);
  }
  if (s != Status::Ok) return s;
  ynew_.noalias() = y_ + h24 * (9.0 * k2_ + 19.0 * fn - 5.0 * fn1 + fn2);
  if (!detail::allFinite(ynew_.data(), n_)) {
    rec_.recordNonFinite(t + h, "state", ynew_.data(), n_);
    return Status::NonFinite;
  }
  y_.swap(ynew_);
  head_ = slot;
  ++stats_.steps;
  return Status::Ok;
}

std::string FixedStepIntegrator::failureMessage(Status s, double t_n) const {
  std::string m = std::string(name()) + ": failed at t = " + detail::num(t_n) + ": ";
  const auto names = [this](int i) { return sys_->componentName(i); };
  switch (s) {
    case Status::NonFinite:
      return m + rec_.describeNonFinite(names);
    case Status::Recoverable:
      return m + "the right-hand side kept failing recoverably down to the smallest substep " +
             detail::num(spec().step / double(1 << kMaxSplitDepth)) + " s (step / " +
             std::to_string(1 << kMaxSplitDepth) + "); last failure: " + rec_.describeCode();
    case Status::Fatal:
      return m + rec_.describeCode();
    case Status::Ok:
      break;
  }
  return m + "unknown failure";
}

RunResult FixedStepIntegrator::runOde(OdeSystem& sys, double t0, const Eigen::VectorXd& y0,
                                      const std::vector<double>& output_times,
                                      const Observer& observer, const Progress& progress) {
  const double h = spec().step;
  // Output times on the grid t0 + k h; the grid itself is t0 + n h (no accumulated rounding).
  std::vector<long> out_step(output_times.size());
  {
    int off_grid = 0;
    double first_off = 0.0;
    long prev = 0;
    for (std::size_t k = 0; k < output_times.size(); ++k) {
      const double r = (output_times[k] - t0) / h;
      const long nk = std::lround(r);
      if (std::abs(r - static_cast<double>(nk)) > 1e-6 || nk <= prev) {
        if (off_grid++ == 0) first_off = output_times[k];
      }
      out_step[k] = nk;
      prev = nk;
    }
    if (off_grid > 0)
      throw InputError(
          spec().loc, "solver.step: output time " + detail::num(first_off) + " s is not on the " +
                          std::string(name()) + " step grid t0 + k * " + detail::num(h) +
                          " s (t0 = " + detail::num(t0) + "; " + std::to_string(off_grid) + " of " +
                          std::to_string(output_times.size()) +
                          " output times are off the grid): choose an output interval that "
                          "is a multiple of the step");
  }

  sys_ = &sys;
  n_ = sys.size();
  for (auto* v : {&y_, &ynew_, &tmp_, &k1_, &k2_, &k3_, &k4_}) v->setZero(n_);
  for (auto& f : f_) f.setZero(n_);
  y_ = y0;
  head_ = 0;
  history_ = 0;
  stats_ = Stats{};
  rec_ = detail::RhsRecord{};

  RunResult res;
  res.t_reached = t0;
  auto finish = [&](bool ok) {
    res.ok = ok;
    res.stats = stats_;
    if (!ok) res.t_fail = res.t_reached;
    sys_ = nullptr;
    return res;
  };
  if (!observer(t0, y_)) {
    res.stopped_by_observer = true;
    res.message = std::string(name()) + ": stopped by the observer at t = " + detail::num(t0);
    return finish(true);
  }
  long n = 0;
  for (std::size_t k = 0; k < output_times.size(); ++k) {
    for (; n < out_step[k]; ++n) {
      const double t = t0 + static_cast<double>(n) * h;
      const Status s = method_ == Method::Rk4 ? advanceRk4(t, h, 0, k1_.data()) : abmStep(t, h);
      if (s != Status::Ok) {
        res.t_reached = t;
        res.message = failureMessage(s, t);
        if (s == Status::NonFinite) res.offending_components = rec_.nonfinite_comps;
        return finish(false);
      }
    }
    res.t_reached = output_times[k];
    if (!observer(output_times[k], y_)) {
      res.stopped_by_observer = true;
      res.message =
          std::string(name()) + ": stopped by the observer at t = " + detail::num(res.t_reached);
      return finish(true);
    }
    if (progress) progress(output_times[k], stats_);
  }
  return finish(true);
}

}  // namespace rb::integ
