#include "workbench/integrators/fixed_step.hpp"
#include "workbench/core/strings.hpp"

#include <cmath>
#include <limits>

#include "workbench/core/error.hpp"
#include "workbench/integrators/exponential.hpp"

namespace rb::integ {

FixedStepIntegrator::FixedStepIntegrator(Method method, SolverSpec spec)
    : Integrator(std::move(spec)), method_(method) {}

FixedStepIntegrator::Status FixedStepIntegrator::eval(double t, const double* y, double* ydot) {
  ++stats_.rhs_evals;
  const int rc = sys_->rhs(t, y, ydot);
  if (rc != 0) {
    rec_.recordCode(rc, t, "right-hand side", sys_->lastError(), sys_->lastFailure());
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
  if (exponential()) refreshDiagonal(t, k1p);
  const double hh = 0.5 * h;
  tmp_.noalias() = y_ + hh * k1;
  if (exponential()) expRk4Stage(0, hh, k1p);
  if ((s = eval(t + hh, tmp_.data(), k2_.data())) != Status::Ok) return s;
  tmp_.noalias() = y_ + hh * k2_;
  if (exponential()) expRk4Stage(1, hh, k2_.data());
  if ((s = eval(t + hh, tmp_.data(), k3_.data())) != Status::Ok) return s;
  tmp_.noalias() = y_ + h * k3_;
  if (exponential()) expRk4Stage(2, hh, k3_.data());
  if ((s = eval(t + h, tmp_.data(), k4_.data())) != Status::Ok) return s;
  ynew_.noalias() = y_ + (h / 6.0) * (k1 + 2.0 * k2_ + 2.0 * k3_ + k4_);
  if (exponential()) expRk4Final(h, ynew_);
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
  if (exponential()) yh_[static_cast<std::size_t>(slot)] = y_;
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
    if (exponential()) refreshDiagonal(t, fn.data());
    tmp_.noalias() = y_ + h24 * (55.0 * fn - 59.0 * fn1 + 37.0 * fn2 - 9.0 * fn3);
    if (exponential()) expAbmPredict(h, slot, tmp_);
    s = eval(t + h, tmp_.data(), k2_.data());
  }
  if (s == Status::Recoverable) {
    ++stats_.rejected_steps;
    history_ = 0;
    return splitRk4(t, h, 1);
  }
  if (s != Status::Ok) return s;
  ynew_.noalias() = y_ + h24 * (9.0 * k2_ + 19.0 * fn - 5.0 * fn1 + fn2);
  if (exponential()) expAbmCorrect(h, slot, ynew_);
  if (!detail::allFinite(ynew_.data(), n_)) {
    rec_.recordNonFinite(t + h, "state", ynew_.data(), n_);
    return Status::NonFinite;
  }
  y_.swap(ynew_);
  head_ = slot;
  ++stats_.steps;
  return Status::Ok;
}

// d_i = df_i / dy_i of every stiff component by one forward difference with all of them moved
// at once: a stiff component's derivative depends on the others only through the slow
// coordinates (each spin rate acts on its own wheelset's creep forces), so their cross terms
// vanish. Refreshed every kDiagonalRefreshSteps steps (the creep coefficients change with the
// normal loads and the speed); a failed or non-decaying estimate keeps the classical treatment
// of that component (d_i = 0).
void FixedStepIntegrator::refreshDiagonal(double t, const double* f_at_y) {
  if (last_refresh_ >= 0 && stats_.steps - last_refresh_ < kDiagonalRefreshSteps) return;
  last_refresh_ = stats_.steps;
  ypert_ = y_;
  std::vector<double>& dy = diag_increment_;
  for (std::size_t k = 0; k < stiff_.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(stiff_[k]);
    dy[k] = 1e-6 * std::max(std::abs(y_(i)), 1.0);
    ypert_(i) += dy[k];
  }
  ++stats_.jacobian_evals;
  ++stats_.rhs_evals_jac;
  if (sys_->rhs(t, ypert_.data(), tmp_.data()) != 0 || !detail::allFinite(tmp_.data(), n_)) return;
  for (std::size_t k = 0; k < stiff_.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(stiff_[k]);
    const double d = (tmp_(i) - f_at_y[i]) / dy[k];
    diag_[k] = d < 0.0 ? d : 0.0;
  }
}

// The weights of stiff component j at z = h d_j, recomputed only when z changes (d_j is refreshed
// every kDiagonalRefreshSteps steps, h changes only in split steps): the phi functions cost
// about as much as a model evaluation when evaluated for every component at every step.
const expo::Weights& FixedStepIntegrator::weightsFor(std::size_t j, double z) const {
  if (!(weight_z_[j] == z)) {
    weights_[j] = expo::weights(z);
    weight_z_[j] = z;
  }
  return weights_[j];
}

// ETDRK4 stages of the stiff components (Cox-Matthews): a = e^{z/2} y + h/2 phi1(z/2) N(y),
// b = e^{z/2} y + h/2 phi1(z/2) N(a), c = e^{z/2} a + h/2 phi1(z/2) (2 N(b) - N(y)); k is the
// derivative at the previous stage. tmp_ holds the classical stage; its stiff entries are
// replaced.
void FixedStepIntegrator::expRk4Stage(int stage, double hh, const double* k) {
  for (std::size_t j = 0; j < stiff_.size(); ++j) {
    const auto i = static_cast<Eigen::Index>(stiff_[j]);
    const double d = diag_[j];
    const expo::Weights& w = weightsFor(j, 2.0 * hh * d);
    const double yi = y_(i);
    if (stage == 0) {
      st_n1_[j] = k[i] - d * yi;
      st_a_[j] = w.e_half * yi + hh * w.phi1_half * st_n1_[j];
      tmp_(i) = st_a_[j];
    } else if (stage == 1) {
      st_b_[j] = w.e_half * yi + hh * w.phi1_half * (k[i] - d * st_a_[j]);
      tmp_(i) = st_b_[j];
    } else {
      const double nb = k[i] - d * st_b_[j];
      st_c_[j] = w.e_half * st_a_[j] + hh * w.phi1_half * (2.0 * nb - st_n1_[j]);
      tmp_(i) = st_c_[j];
    }
  }
}

void FixedStepIntegrator::expRk4Final(double h, Eigen::VectorXd& ynew) const {
  for (std::size_t j = 0; j < stiff_.size(); ++j) {
    const auto i = static_cast<Eigen::Index>(stiff_[j]);
    const double d = diag_[j];
    const expo::Weights& w = weightsFor(j, h * d);
    const double na = k2_(i) - d * st_a_[j], nb = k3_(i) - d * st_b_[j];
    const double nc = k4_(i) - d * st_c_[j];
    ynew(i) = w.e_full * y_(i) + h * (w.f1 * st_n1_[j] + 2.0 * w.f2 * (na + nb) + w.f3 * nc);
  }
}

// Exponential Adams-Bashforth 4 predictor of the stiff components from the history f_, yh_ (the
// newest at slot, then head_, ...): N_j = f_j - d y_j.
void FixedStepIntegrator::expAbmPredict(double h, int slot, Eigen::VectorXd& ystar) const {
  const std::array<int, 4> node{slot, head_, (head_ + 3) & 3, (head_ + 2) & 3};
  for (std::size_t j = 0; j < stiff_.size(); ++j) {
    const auto i = static_cast<Eigen::Index>(stiff_[j]);
    const double d = diag_[j];
    const expo::Weights& w = weightsFor(j, h * d);
    double sum = 0.0;
    for (std::size_t m = 0; m < 4; ++m) {
      const auto nd = static_cast<std::size_t>(node[m]);
      sum += w.ab[m] * (f_[nd](i) - d * yh_[nd](i));
    }
    ystar(i) = w.e_full * y_(i) + h * sum;
  }
}

// Exponential Adams-Moulton 4 corrector: N*_n+1 from f(y*) (k2_ at tmp_), then N_n, N_n-1, N_n-2.
void FixedStepIntegrator::expAbmCorrect(double h, int slot, Eigen::VectorXd& ynew) const {
  const std::array<int, 3> node{slot, head_, (head_ + 3) & 3};
  for (std::size_t j = 0; j < stiff_.size(); ++j) {
    const auto i = static_cast<Eigen::Index>(stiff_[j]);
    const double d = diag_[j];
    const expo::Weights& w = weightsFor(j, h * d);
    double sum = w.am[0] * (k2_(i) - d * tmp_(i));
    for (std::size_t m = 0; m < 3; ++m) {
      const auto nd = static_cast<std::size_t>(node[m]);
      sum += w.am[m + 1] * (f_[nd](i) - d * yh_[nd](i));
    }
    ynew(i) = w.e_full * y_(i) + h * sum;
  }
}

std::string FixedStepIntegrator::failureMessage(Status s, double t_n) const {
  std::string m = std::string(name()) + ": failed at t = " + formatNumber(t_n, 10) + ": ";
  const auto names = [this](int i) { return sys_->componentName(i); };
  switch (s) {
    case Status::NonFinite:
      return m + rec_.describeNonFinite(names);
    case Status::Recoverable:
      return m + "the right-hand side kept failing recoverably down to the smallest substep " +
             formatNumber(spec().step / double(1 << kMaxSplitDepth), 10) + " s (step / " +
             std::to_string(1 << kMaxSplitDepth) + "); last failure: " + rec_.describeCode();
    case Status::Fatal:
      return m + rec_.describeCode();
    case Status::Ok:
      break;
  }
  return m + "unknown failure";
}

void FixedStepIntegrator::recordFailure(Status s, double t_n, RunResult& res) const {
  res.t_reached = t_n;
  res.message = failureMessage(s, t_n);
  if (s == Status::NonFinite) {
    res.failure = FailureKind::NonFinite;
    res.offending_components = rec_.nonfinite_comps;
  } else {
    res.failure = FailureKind::Model;
    res.cause = rec_.model_failure;
  }
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
      throw InputError(spec().loc,
                       "solver.step: output time " + formatNumber(first_off, 10) +
                           " s is not on the " + std::string(name()) + " step grid t0 + k * " +
                           formatNumber(h, 10) + " s (t0 = " + formatNumber(t0, 10) + "; " +
                           std::to_string(off_grid) + " of " + std::to_string(output_times.size()) +
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
  stiff_ = spec().stiff == StiffTreatment::Exponential ? sys.stiffComponents() : std::vector<int>{};
  diag_.assign(stiff_.size(), 0.0);
  diag_increment_.assign(stiff_.size(), 0.0);
  for (auto* v : {&st_a_, &st_b_, &st_c_, &st_n1_}) v->assign(stiff_.size(), 0.0);
  weights_.assign(stiff_.size(), expo::Weights{});
  weight_z_.assign(stiff_.size(), std::numeric_limits<double>::quiet_NaN());
  last_refresh_ = -1;
  if (exponential()) {
    for (auto& v : yh_) v.setZero(n_);
    ypert_.setZero(n_);
  }
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
    res.message = std::string(name()) + ": stopped by the observer at t = " + formatNumber(t0, 10);
    return finish(true);
  }
  long n = 0;
  for (std::size_t k = 0; k < output_times.size(); ++k) {
    for (; n < out_step[k]; ++n) {
      const double t = t0 + static_cast<double>(n) * h;
      const Status s = method_ == Method::Rk4 ? advanceRk4(t, h, 0, k1_.data()) : abmStep(t, h);
      if (s != Status::Ok) {
        recordFailure(s, t, res);
        return finish(false);
      }
    }
    res.t_reached = output_times[k];
    if (!observer(output_times[k], y_)) {
      res.stopped_by_observer = true;
      res.message = std::string(name()) +
                    ": stopped by the observer at t = " + formatNumber(res.t_reached, 10);
      return finish(true);
    }
    if (progress) progress(output_times[k], stats_);
  }
  return finish(true);
}

}  // namespace rb::integ
