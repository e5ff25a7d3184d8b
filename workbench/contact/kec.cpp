#include "workbench/contact/kec.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "workbench/contact/geometry.hpp"
#include "workbench/core/error.hpp"

namespace rb::contact {
namespace {

constexpr double kPenTol = 1e-9;             // [m] penetration that signals a jump
constexpr std::size_t kProfileChannels = 8;  // F .. KrTrans, per branch sample
constexpr const char* kSideName[2] = {"left", "right"};

std::string mm(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4f mm", v * 1e3);
  return b;
}

struct Sample {
  ContactState x;
  std::array<double, 2> sk{}, fk{};
  std::array<ContactPoint, 2> cp;
};

struct Piece {
  std::vector<Sample> s;  // in sweep order
};

struct Junction {
  std::size_t jumping = 0;  // side index of the wheel whose contact jumps
  bool flange = false;      // the new contact is on the flange side of the boundary
  double y = 0.0;
};

struct Sweep {
  std::vector<Piece> pieces;
  std::vector<Junction> junctions;  // junctions[i] between pieces[i] and pieces[i + 1]
  std::string end;
};

class Builder {
 public:
  Builder(const ContactGeometryConfig& cfg, TableBuildStats& st)
      : cfg_(cfg), solver_(cfg), st_(st) {
    step_ =
        cfg.kec_sample_step > 0.0 ? cfg.kec_sample_step : std::min(0.25 * cfg.kec_s.step, 0.05e-3);
    margin_ = 2.0 * cfg.kec_s.step;
  }

  const ContactSolver& solver() const { return solver_; }

  Sample makeSample(const ContactState& x) const {
    Sample s;
    s.x = x;
    const WheelsetPose pose{x.y, x.z, x.phi};
    for (std::size_t k = 0; k < 2; ++k) {
      const KnifePoint kp = knifePoint(kSideSign[k], cfg_.rail_lr, cfg_.r0, x.y, x.z, x.phi);
      s.sk[k] = kp.s_k;
      s.fk[k] = kp.f_k;
      s.cp[k] = solver_.describe(k == 0 ? Side::Left : Side::Right, pose, 0.0, x.s[2 * k],
                                 x.s[2 * k + 1]);
    }
    return s;
  }

  // Continuation step to parameter value `target`, cut into substeps when Newton fails.
  bool advance(ContactState& x, Parameter p, double target) {
    const double p0 = solver_.parameterValue(x, p);
    for (int parts = 1; parts <= 8; parts *= 2) {
      ContactState t = x;
      bool ok = true;
      for (int i = 1; i <= parts && ok; ++i) {
        const double v = p0 + (target - p0) * static_cast<double>(i) / parts;
        const int n = solver_.newton(t, p, v, 0.0);
        st_.newton_iterations += n >= 0 ? n : cfg_.newton_max_iter;
        ok = n >= 0;
      }
      if (ok) {
        x = t;
        return true;
      }
    }
    return false;
  }

  // Deepest sampled penetration of wheel k away from its current contact point.
  bool penetratesElsewhere(const ContactState& x, std::size_t k, ContactSolver::Gap& g) const {
    const Side side = k == 0 ? Side::Left : Side::Right;
    std::array<ContactSolver::Gap, 4> m;
    const int n = solver_.localMinima(side, WheelsetPose{x.y, x.z, x.phi}, 0.0, Window::All,
                                      x.s[2 * k], 2.0 * cfg_.search_step, m);
    if (n == 0 || !(m[0].gap < -kPenTol)) return false;
    g = m[0];
    return true;
  }

  Sweep sweep(const ContactState& x0, int dir) {
    Sweep sw;
    const Parameter p = dir > 0 ? Parameter::LeftKnife : Parameter::RightKnife;
    const std::size_t own = dir > 0 ? 0 : 1;
    const Side own_side = own == 0 ? Side::Left : Side::Right;
    const double step = dir > 0 ? -step_ : step_;  // s_k decreases when y increases
    const double sdir = dir > 0 ? -1.0 : 1.0;      // direction of s along the sweep
    const double tip = solver_.flangeTip(own_side);
    const double sig = kSideSign[own];
    ContactState x = x0;
    Piece cur;
    cur.s.push_back(makeSample(x));
    double pv = solver_.parameterValue(x, p);
    const double s_end = dir > 0 ? cfg_.kec_s.min - margin_ : cfg_.kec_s.max + margin_;
    const int max_steps =
        static_cast<int>(std::ceil((cfg_.kec_s.max - cfg_.kec_s.min + 4 * margin_) / step_)) + 10;
    for (int n = 0;; ++n) {
      if (n > max_steps) {
        sw.end = "step limit";
        break;
      }
      ContactState xn = x;
      int jside = -1;
      ContactSolver::Gap g;
      ContactState xj, xnew;
      bool fold = false;
      if (advance(xn, p, pv + step)) {
        for (std::size_t k = 0; k < 2 && jside < 0; ++k) {
          if (penetratesElsewhere(xn, k, g)) jside = static_cast<int>(k);
        }
        if (jside >= 0 && !locateJump(x, xn, p, static_cast<std::size_t>(jside), g, xj, xnew)) {
          sw.end = "a contact-point jump could not be located";
          break;
        }
      } else {
        // The branch ends (fold): the contact jumps to the nearest other candidate point.
        if (!jumpAtFold(x, p, pv + step, jside, xnew)) {
          sw.end = "continuation failed (branch ended, no other contact found)";
          break;
        }
        xj = x;
        fold = true;
      }
      if (jside >= 0) {
        const auto k = static_cast<std::size_t>(jside);
        Junction J;
        J.jumping = k;
        const double b = solver_.flangeBoundary(k == 0 ? Side::Left : Side::Right);
        J.flange = solver_.hasFlange(k == 0 ? Side::Left : Side::Right) &&
                   kSideSign[k] * (xnew.s[2 * k] - b) < 0.0 &&
                   kSideSign[k] * (xj.s[2 * k] - b) >= 0.0;
        J.y = xj.y;
        if (!fold) cur.s.push_back(makeSample(xj));
        sw.pieces.push_back(std::move(cur));
        sw.junctions.push_back(J);
        cur = Piece{};
        cur.s.push_back(makeSample(xnew));
        x = xnew;
        pv = solver_.parameterValue(x, p);
        continue;
      }
      x = xn;
      pv += step;
      cur.s.push_back(makeSample(x));
      if (sdir * (cur.s.back().sk[own] - s_end) > 0.0) {
        sw.end = "end of the KEC grid";
        break;
      }
      if (solver_.hasFlange(own_side) && sig * (x.s[2 * own] - tip) < 0.0) {
        sw.end = "flange tip reached (the wheel climbed the rail)";
        break;
      }
    }
    sw.pieces.push_back(std::move(cur));
    return sw;
  }

 private:
  // Two-point contact between parameter values of xa (no penetration) and xb (penetration of wheel
  // k at the sampled point g): bisection on the indentation of the other point (Eq. 15 by Newton).
  bool locateJump(const ContactState& xa, const ContactState& xb, Parameter p, std::size_t k,
                  const ContactSolver::Gap& g, ContactState& xj, ContactState& xnew) {
    const Side side = k == 0 ? Side::Left : Side::Right;
    auto other = [&](const ContactState& x, double sw, double sr, FlangeContact& f) {
      f = solver_.indentation(side, WheelsetPose{x.y, x.z, x.phi}, 0.0, sw, sr);
      return f.converged && std::abs(f.point.s_w - x.s[2 * k]) > 2.0 * cfg_.search_step;
    };
    FlangeContact fb;
    if (!other(xb, g.s_w, g.s_r, fb) || fb.delta < 0.0) return false;
    double pa = solver_.parameterValue(xa, p), pb = solver_.parameterValue(xb, p);
    ContactState lo = xa, hi = xb;
    FlangeContact fhi = fb;
    for (int it = 0; it < 80 && std::abs(pb - pa) > 1e-13; ++it) {
      const double pm = 0.5 * (pa + pb);
      ContactState xm = lo;
      if (!advance(xm, p, pm)) return false;
      FlangeContact fm;
      if (other(xm, fhi.point.s_w, fhi.point.s_r, fm) && fm.delta >= 0.0) {
        hi = xm;
        fhi = fm;
        pb = pm;
      } else {
        lo = xm;
        pa = pm;
      }
    }
    xj = hi;
    xnew = hi;
    xnew.s[2 * k] = fhi.point.s_w;
    xnew.s[2 * k + 1] = fhi.point.s_r;
    const int n = solver_.newton(xnew, p, pb, 0.0);
    st_.newton_iterations += std::max(n, 0);
    return n >= 0;
  }

  // The branch through x cannot be continued (a fold, or the degenerate conformal contact of equal
  // concave wheel and convex rail radii, S1002 flange root on 60E1 gauge corner): the contact
  // jumps. Eq. (12) is solved at the next parameter value from wheel points at increasing distance
  // (jump_threshold + j 0.5 mm, flange side first, both wheels); the first solution whose contact
  // moved and which leaves no penetration anywhere is the new branch.
  bool jumpAtFold(const ContactState& x, Parameter p, double pv_next, int& jside,
                  ContactState& xnew) {
    jside = -1;
    const double dstep = 0.5e-3;
    for (int j = 0; j < 40 && jside < 0; ++j) {
      for (std::size_t k = 0; k < 2 && jside < 0; ++k) {
        const Side side = k == 0 ? Side::Left : Side::Right;
        const profiles::Profile& wheel = k == 0 ? *cfg_.left_wheel : *cfg_.right_wheel;
        const profiles::Profile& rail = k == 0 ? *cfg_.left_rail : *cfg_.right_rail;
        for (double dir : {-kSideSign[k], kSideSign[k]}) {  // flange-ward first
          const double sw = x.s[2 * k] + dir * (cfg_.jump_threshold + dstep * j);
          if (!wheel.inside(sw)) continue;
          const double sr = solver_.railBelow(side, WheelsetPose{x.y, x.z, x.phi}, 0.0, sw);
          if (!rail.inside(sr)) continue;
          ContactState t = x;
          t.s[2 * k] = sw;
          t.s[2 * k + 1] = sr;
          const int it = solver_.newton(t, p, pv_next, 0.0);
          st_.newton_iterations += std::max(it, 0);
          if (it < 0 || std::abs(t.s[2 * k] - x.s[2 * k]) <= cfg_.jump_threshold) continue;
          ContactSolver::Gap g;
          if (penetratesElsewhere(t, 0, g) || penetratesElsewhere(t, 1, g)) continue;
          jside = static_cast<int>(k);
          xnew = t;
          break;
        }
      }
    }
    if (jside >= 0) {
      char b[200];
      std::snprintf(b, sizeof b,
                    "KEC: %s contact branch ended (fold or conformal contact) at y = %.4f mm, "
                    "s_w = %.3f mm; continued at s_w = %.3f mm",
                    kSideName[jside], x.y * 1e3, x.s[2 * static_cast<std::size_t>(jside)] * 1e3,
                    xnew.s[2 * static_cast<std::size_t>(jside)] * 1e3);
      st_.notes.push_back(b);
    }
    return jside >= 0;
  }

  const ContactGeometryConfig& cfg_;
  ContactSolver solver_;
  TableBuildStats& st_;
  double step_ = 0.0, margin_ = 0.0;
};

// Branch data of one piece on one profile: samples in ascending s and their spline.
struct ProfilePiece {
  std::vector<double> s;
  std::array<std::vector<double>, kProfileChannels> v;
  CubicSplineSet spline;
  void build() { spline = CubicSplineSet(SplineGrid(s), {v.begin(), v.end()}); }
  double lo() const { return s.front(); }
  double hi() const { return s.back(); }
  // Values, first and second derivatives; linear continuation beyond the samples.
  void eval(double x, double* out, double* d1 = nullptr, double* d2 = nullptr) const {
    double val[kProfileChannels], dv[kProfileChannels], ddv[kProfileChannels];
    const double e = std::clamp(x, lo(), hi());
    spline.eval(e, val, dv, ddv);
    for (std::size_t c = 0; c < kProfileChannels; ++c) {
      out[c] = val[c] + dv[c] * (x - e);
      if (d1) d1[c] = dv[c];
      if (d2) d2[c] = x == e ? ddv[c] : 0.0;
    }
  }
};

void sampleChannels(const Sample& smp, std::size_t k, double* v) {
  const ContactPoint& p = smp.cp[k];
  v[0] = smp.fk[k];
  v[1] = p.s_w;
  v[2] = p.s_r;
  v[3] = p.gamma;
  v[4] = p.radius;
  v[5] = p.k_wheel_trans;
  v[6] = p.k_wheel_long;
  v[7] = p.k_rail_trans;
}

// Quintic Hermite on [a, b] matching value, slope and curvature at both ends: value, first and
// second derivative at s.
void quinticHermite(double a, double b, const double* fa, const double* fb, double s, double* out) {
  const double h = b - a, t = (s - a) / h;
  const double t2 = t * t, t3 = t2 * t, t4 = t3 * t, t5 = t4 * t;
  // Basis for value (p), slope (m) and curvature (c) at 0 and 1, and their derivatives in t.
  const double p0 = 1 - 10 * t3 + 15 * t4 - 6 * t5, p1 = 10 * t3 - 15 * t4 + 6 * t5;
  const double m0 = t - 6 * t3 + 8 * t4 - 3 * t5, m1 = -4 * t3 + 7 * t4 - 3 * t5;
  const double c0 = 0.5 * (t2 - 3 * t3 + 3 * t4 - t5), c1 = 0.5 * (t3 - 2 * t4 + t5);
  const double dp0 = -30 * t2 + 60 * t3 - 30 * t4, dp1 = -dp0;
  const double dm0 = 1 - 18 * t2 + 32 * t3 - 15 * t4, dm1 = -12 * t2 + 28 * t3 - 15 * t4;
  const double dc0 = 0.5 * (2 * t - 9 * t2 + 12 * t3 - 5 * t4),
               dc1 = 0.5 * (3 * t2 - 8 * t3 + 5 * t4);
  const double ddp0 = -60 * t + 180 * t2 - 120 * t3, ddp1 = -ddp0;
  const double ddm0 = -36 * t + 96 * t2 - 60 * t3, ddm1 = -24 * t + 84 * t2 - 60 * t3;
  const double ddc0 = 0.5 * (2 - 18 * t + 36 * t2 - 20 * t3),
               ddc1 = 0.5 * (6 * t - 24 * t2 + 20 * t3);
  out[0] =
      p0 * fa[0] + p1 * fb[0] + h * (m0 * fa[1] + m1 * fb[1]) + h * h * (c0 * fa[2] + c1 * fb[2]);
  out[1] = (dp0 * fa[0] + dp1 * fb[0]) / h + (dm0 * fa[1] + dm1 * fb[1]) +
           h * (dc0 * fa[2] + dc1 * fb[2]);
  out[2] = (ddp0 * fa[0] + ddp1 * fb[0]) / (h * h) + (ddm0 * fa[1] + ddm1 * fb[1]) / h +
           (ddc0 * fa[2] + ddc1 * fb[2]);
}

// The interval of s_k on the uniform grid (min, step, n nodes; clamped to the end intervals) and
// the cubic Hermite basis at its local coordinate t: v = A0 v0 + A1 v1 + C0 v0' + C1 v1'. Shared
// by KecTable::eval and evalValues, so their values are the same to the bit.
struct HermiteCell {
  std::size_t i;
  double t, A0, A1, C0, C1;
};
HermiteCell hermiteCell(double min, double h, std::size_t n, double s_k) {
  double tf = std::floor((s_k - min) / h);
  tf = std::clamp(tf, 0.0, static_cast<double>(n - 2));
  const double t = (s_k - min) / h - tf;
  const double t2 = t * t, t3 = t2 * t;
  return {static_cast<std::size_t>(tf), t,
          2 * t3 - 3 * t2 + 1,          -2 * t3 + 3 * t2,
          (t3 - 2 * t2 + t) * h,        (t3 - t2) * h};
}

}  // namespace

std::string kecQuantityName(KecQuantity q) {
  static const char* names[kKecQuantities] = {
      "f",         "s_w",    "s_r",   "gamma", "radius", "k_w_trans", "k_w_long",
      "k_r_trans", "weight", "s_w_A", "s_r_A", "s_w_B",  "s_r_B"};
  return names[static_cast<std::size_t>(q)];
}

bool KecTable::inTransition(Side side, double s_k) const {
  for (const KecTransition& t : trans_[idx(side)]) {
    if (s_k >= t.lo && s_k <= t.hi) return true;
  }
  return false;
}

void KecTable::eval(Side side, double s_k, KecPoint& out) const {
  const std::size_t k = idx(side);
  const HermiteCell c = hermiteCell(grid_.min, grid_.step, n_, s_k);
  const double A0 = c.A0, A1 = c.A1, C0 = c.C0, C1 = c.C1, t = c.t, t2 = t * t, h = grid_.step;
  const double dA0 = (6 * t2 - 6 * t) / h, dA1 = -dA0;
  const double dC0 = 3 * t2 - 4 * t + 1, dC1 = 3 * t2 - 2 * t;
  const double* p0 = &herm_[k][c.i * kKecQuantities * 2];
  const double* p1 = p0 + kKecQuantities * 2;
  for (std::size_t q = 1; q < kKecQuantities; ++q) {
    out.value[q] = A0 * p0[2 * q] + A1 * p1[2 * q] + C0 * p0[2 * q + 1] + C1 * p1[2 * q + 1];
    out.d_ds[q] = dA0 * p0[2 * q] + dA1 * p1[2 * q] + dC0 * p0[2 * q + 1] + dC1 * p1[2 * q + 1];
  }
  fspl_[k].eval(s_k, {&out.value[0], 1}, {&out.d_ds[0], 1}, {&out.d2f, 1});
  out.inside = s_k >= valid_[k][0] && s_k <= valid_[k][1];
}

void KecTable::evalValues(Side side, double s_k, KecPoint& out) const {
  // eval() without f and without derivatives (the dynamics reads values of the maps only); the
  // same expressions, so the values are bit-identical to eval()'s, except on an interval where a
  // channel is constant (equal node values, zero slopes): there the interpolant IS that constant
  // and it is returned exactly (A0 v + A1 v can be 1 ulp off). The end points A, B of a transition
  // band (SwA ... SrB, the only channels checked) are such channels, and an exact value lets the
  // dynamics reuse its last describe() of them.
  const std::size_t k = idx(side);
  const HermiteCell c = hermiteCell(grid_.min, grid_.step, n_, s_k);
  const double A0 = c.A0, A1 = c.A1, C0 = c.C0, C1 = c.C1;
  const double* p0 = &herm_[k][c.i * kKecQuantities * 2];
  const double* p1 = p0 + kKecQuantities * 2;
  constexpr auto kFirstPoint = static_cast<std::size_t>(KecQuantity::SwA);
  for (std::size_t q = 1; q < kFirstPoint; ++q)
    out.value[q] = A0 * p0[2 * q] + A1 * p1[2 * q] + C0 * p0[2 * q + 1] + C1 * p1[2 * q + 1];
  for (std::size_t q = kFirstPoint; q < kKecQuantities; ++q) {
    const bool constant = p0[2 * q] == p1[2 * q] && p0[2 * q + 1] == 0.0 && p1[2 * q + 1] == 0.0;
    out.value[q] = constant
                       ? p0[2 * q]
                       : A0 * p0[2 * q] + A1 * p1[2 * q] + C0 * p0[2 * q + 1] + C1 * p1[2 * q + 1];
  }
  out.inside = s_k >= valid_[k][0] && s_k <= valid_[k][1];
}

double KecTable::f(Side side, double s_k, double* df, double* d2f) const {
  // One interval lookup for all orders (solveKec calls this twice per Newton iteration).
  double v = 0.0, d1 = 0.0, d2 = 0.0;
  fspl_[idx(side)].eval(s_k, {&v, 1}, {&d1, 1}, {&d2, 1});
  if (df) *df = d1;
  if (d2f) *d2f = d2;
  return v;
}

void KecTable::makeFSpline(std::size_t k) {
  std::vector<double> fvals(n_);
  for (std::size_t i = 0; i < n_; ++i) fvals[i] = herm_[k][i * kKecQuantities * 2];
  fspl_[k] = CubicSplineSet(SplineGrid::uniform(grid_.min, grid_.step, n_),
                            std::vector<std::vector<double>>{fvals});
}

KecTable buildKec(const ContactGeometryConfig& config) {
  const auto t0 = std::chrono::steady_clock::now();
  checkConfig(config);
  KecTable tab;
  TableBuildStats& st = tab.stats_;
  tab.grid_ = config.kec_s;
  tab.n_ = config.kec_s.count();
  tab.r0_ = config.r0;
  tab.lr_ = config.rail_lr;
  tab.hash_ = configHash(config);
  Builder bld(config, st);
  const ContactSolver& solver = bld.solver();

  for (double L : {config.kec_dhat, config.kec_dbar}) {
    if (L < config.kec_min_transition) {
      st.warnings.push_back("KEC: transition length " + mm(L) + " is below " +
                            mm(config.kec_min_transition) +
                            ": the constraint Jacobian becomes ill-conditioned in the transition "
                            "(the paper's simulations stall); use at least 0.05 mm");
    }
  }
  if (config.kec_dhat + config.kec_dbar < 3.0 * config.kec_s.step) {
    st.warnings.push_back(
        "KEC: transition d_hat + d_bar = " + mm(config.kec_dhat + config.kec_dbar) +
        " is resolved by fewer than 3 steps of the KEC grid (step " + mm(config.kec_s.step) +
        "): refine the grid");
  }

  // Start: centred wheelset (Eq. 12 with the global search).
  const TreadContact c0 = solver.solveTread(0.0, 0.0);
  if (!c0.converged) {
    throw InputError(SourceLoc{"contact geometry", 0},
                     "KEC: no contact solution for the centred wheelset: check the profiles and "
                     "their positioning (Lw, Lr)");
  }
  ContactState x0;
  x0.y = 0.0;
  x0.z = c0.z;
  x0.phi = c0.phi;
  x0.s = c0.s;
  const Sweep sl = bld.sweep(x0, +1);  // toward the left flange (y > 0, s_k decreasing)
  const Sweep sr = bld.sweep(x0, -1);  // toward the right flange (y < 0, s_k increasing)
  st.notes.push_back("KEC: branch toward the left flange ended: " + sl.end);
  st.notes.push_back("KEC: branch toward the right flange ended: " + sr.end);

  std::size_t n_samples = 0;
  for (const Sweep* sw : {&sl, &sr}) {
    for (const Piece& p : sw->pieces) n_samples += p.s.size();
  }
  st.nodes = n_samples;
  const std::size_t ng = tab.n_;
  const std::array<double, 2> low_len{config.kec_dhat, config.kec_dbar};   // flange side: left low
  const std::array<double, 2> high_len{config.kec_dbar, config.kec_dhat};  // right high
  for (std::size_t k = 0; k < 2; ++k) {
    // Pieces as sample lists in ascending s (sweep sl runs toward low s, sr toward high s), with
    // the junctions between consecutive pieces.
    std::vector<std::vector<const Sample*>> pieces;
    std::vector<const Junction*> juncs;
    for (std::size_t i = sl.pieces.size(); i-- > 1;) {
      std::vector<const Sample*> v;
      for (auto it = sl.pieces[i].s.rbegin(); it != sl.pieces[i].s.rend(); ++it) v.push_back(&*it);
      pieces.push_back(std::move(v));
      juncs.push_back(&sl.junctions[i - 1]);
    }
    {
      std::vector<const Sample*> v;
      for (auto it = sl.pieces[0].s.rbegin(); it != sl.pieces[0].s.rend(); ++it) v.push_back(&*it);
      for (std::size_t i = 1; i < sr.pieces[0].s.size(); ++i) v.push_back(&sr.pieces[0].s[i]);
      pieces.push_back(std::move(v));
    }
    for (std::size_t i = 1; i < sr.pieces.size(); ++i) {
      juncs.push_back(&sr.junctions[i - 1]);
      std::vector<const Sample*> v;
      for (const Sample& smp : sr.pieces[i].s) v.push_back(&smp);
      pieces.push_back(std::move(v));
    }
    // Branch splines; the equivalent profile must be a function of s_k: samples that do not
    // advance in s_k are dropped (warned).
    std::vector<ProfilePiece> pp(pieces.size());
    std::size_t dropped = 0;
    for (std::size_t m = 0; m < pieces.size(); ++m) {
      for (const Sample* smp : pieces[m]) {
        const double sv = smp->sk[k];
        if (!pp[m].s.empty() && !(sv > pp[m].s.back() + 1e-12)) {
          ++dropped;
          continue;
        }
        double v[kProfileChannels];
        sampleChannels(*smp, k, v);
        pp[m].s.push_back(sv);
        for (std::size_t c = 0; c < kProfileChannels; ++c) pp[m].v[c].push_back(v[c]);
      }
      if (pp[m].s.size() < 2) {
        // A one-sample branch (two jumps in a row): give it a tiny extent.
        pp[m].s.push_back(pp[m].s.back() + 1e-9);
        for (std::size_t c = 0; c < kProfileChannels; ++c) pp[m].v[c].push_back(pp[m].v[c].back());
      }
      pp[m].build();
    }
    if (dropped > 0) {
      st.warnings.push_back(std::string("KEC: ") + kSideName[k] +
                            " equivalent profile: " + std::to_string(dropped) +
                            " branch samples dropped where s_k did not advance monotonically");
    }
    // Transitions: requested [s_j - L_low, s_j + L_high], cut to the neighbouring branches and so
    // that they do not overlap.
    std::vector<KecTransition>& tr = tab.trans_[k];
    for (std::size_t m = 0; m < juncs.size(); ++m) {
      const Junction& J = *juncs[m];
      KecTransition t;
      t.s_jump = 0.5 * (pp[m].hi() + pp[m + 1].lo());
      t.lo = t.s_jump - low_len[k];
      t.hi = t.s_jump + high_len[k];
      t.own = J.jumping == k;
      t.flange = t.own && J.flange;
      t.y = J.y;
      tr.push_back(t);
    }
    std::vector<double> lo_req(tr.size()), hi_req(tr.size());
    for (std::size_t m = 0; m < tr.size(); ++m) {
      lo_req[m] = tr[m].lo;
      hi_req[m] = tr[m].hi;
      tr[m].lo = std::max(tr[m].lo, pp[m].lo());
      tr[m].hi = std::min(tr[m].hi, pp[m + 1].hi());
    }
    for (std::size_t m = 0; m + 1 < tr.size(); ++m) {
      if (tr[m].hi > tr[m + 1].lo) {  // overlap: both end in the middle of the overlap
        const double mid = 0.5 * (tr[m].hi + tr[m + 1].lo);
        tr[m].hi = mid;
        tr[m + 1].lo = mid;
      }
    }
    for (std::size_t m = 0; m < tr.size(); ++m) {
      const bool shortened = tr[m].lo > lo_req[m] + 1e-12 || tr[m].hi < hi_req[m] - 1e-12;
      if (shortened) {
        st.notes.push_back(std::string("KEC: ") + kSideName[k] + " transition at s_k = " +
                           mm(tr[m].s_jump) + " shortened to [" + mm(tr[m].lo) + ", " +
                           mm(tr[m].hi) + "] (the branch on one side is shorter than the " +
                           "transition length, or the next jump is close)");
      }
      if (shortened && (!(tr[m].lo < tr[m].s_jump && tr[m].s_jump < tr[m].hi) ||
                        tr[m].hi - tr[m].lo < config.kec_min_transition)) {
        st.warnings.push_back(std::string("KEC: ") + kSideName[k] + " transition at s_k = " +
                              mm(tr[m].s_jump) + " is only [" + mm(tr[m].lo) + ", " + mm(tr[m].hi) +
                              "]: jumps too close together for the transition " + "lengths");
      }
    }
    tab.valid_[k] = {pp.front().lo(), pp.back().hi()};

    // Regularised channels at s: values and exact s-derivatives (f also second derivative).
    // In a transition [lo, hi] between branch L (below) and H (above): f is the quintic Hermite
    // matching f, f', f'' of L at lo and of H at hi; every other channel is the linear ramp
    // between L(lo) and H(hi); the weight of the flange-side end B ramps 0 -> 1.
    auto regularised = [&](double sv, double* val, double* der, double& f2) {
      std::size_t m = 0;
      while (m < tr.size() && sv > tr[m].hi) ++m;
      double a[kProfileChannels], b[kProfileChannels];
      double wB = 0.0, dwB = 0.0;
      if (m < tr.size() && sv >= tr[m].lo) {
        const KecTransition& t = tr[m];
        double la[kProfileChannels], la1[kProfileChannels], la2[kProfileChannels];
        double hb[kProfileChannels], hb1[kProfileChannels], hb2[kProfileChannels];
        pp[m].eval(t.lo, la, la1, la2);
        pp[m + 1].eval(t.hi, hb, hb1, hb2);
        const double L = t.hi - t.lo, u = (sv - t.lo) / L;
        const double fa[3] = {la[0], la1[0], la2[0]}, fb[3] = {hb[0], hb1[0], hb2[0]};
        double fq[3];
        quinticHermite(t.lo, t.hi, fa, fb, sv, fq);
        val[0] = fq[0];
        der[0] = fq[1];
        f2 = fq[2];
        for (std::size_t c = 1; c < kProfileChannels; ++c) {
          val[c] = (1.0 - u) * la[c] + u * hb[c];
          der[c] = (hb[c] - la[c]) / L;
        }
        // Left wheel: the flange side is the low-s end; right wheel: the high-s end.
        wB = k == 0 ? 1.0 - u : u;
        dwB = (k == 0 ? -1.0 : 1.0) / L;
        const double* A = k == 0 ? hb : la;
        const double* B = k == 0 ? la : hb;
        std::copy_n(A, kProfileChannels, a);
        std::copy_n(B, kProfileChannels, b);
        val[kProfileChannels] = wB;
        der[kProfileChannels] = dwB;
        val[kProfileChannels + 1] = a[1];
        val[kProfileChannels + 2] = a[2];
        val[kProfileChannels + 3] = b[1];
        val[kProfileChannels + 4] = b[2];
        for (std::size_t c = kProfileChannels + 1; c < kKecQuantities; ++c) der[c] = 0.0;
        return;
      }
      double d2[kProfileChannels];
      pp[m].eval(sv, val, der, d2);
      f2 = d2[0];
      val[kProfileChannels] = 0.0;
      der[kProfileChannels] = 0.0;
      val[kProfileChannels + 1] = val[1];
      val[kProfileChannels + 2] = val[2];
      val[kProfileChannels + 3] = val[1];
      val[kProfileChannels + 4] = val[2];
      der[kProfileChannels + 1] = der[1];
      der[kProfileChannels + 2] = der[2];
      der[kProfileChannels + 3] = der[1];
      der[kProfileChannels + 4] = der[2];
    };
    static_assert(kProfileChannels + 5 == kKecQuantities, "KEC channel layout");
    tab.herm_[k].assign(ng * kKecQuantities * 2, 0.0);
    for (std::size_t i = 0; i < ng; ++i) {
      double val[kKecQuantities], der[kKecQuantities], f2 = 0.0;
      regularised(config.kec_s.at(i), val, der, f2);
      for (std::size_t q = 0; q < kKecQuantities; ++q) {
        tab.herm_[k][(i * kKecQuantities + q) * 2] = val[q];
        tab.herm_[k][(i * kKecQuantities + q) * 2 + 1] = der[q];
      }
    }
    tab.makeFSpline(k);
    for (KecTransition& t : tr) {
      double val[kKecQuantities], der[kKecQuantities], f2;
      regularised(0.5 * (t.lo + t.hi), val, der, f2);
      t.s_w_field = val[kProfileChannels + 1];
      t.s_w_flange = val[kProfileChannels + 3];
    }
    if (tab.valid_[k][0] > config.kec_s.min || tab.valid_[k][1] < config.kec_s.max) {
      st.notes.push_back(std::string("KEC: ") + kSideName[k] + " profile computed on s_k in [" +
                         mm(tab.valid_[k][0]) + ", " + mm(tab.valid_[k][1]) +
                         "], extrapolated linearly beyond");
    }
    // Steepness of the regularised maps (exact, before resampling) and their resolution.
    for (const KecTransition& t : tr) {
      double max_f2 = 0.0, max_sw = 0.0;
      for (int q = 0; q <= 200; ++q) {
        double val[kKecQuantities], der[kKecQuantities], f2 = 0.0;
        regularised(t.lo + (t.hi - t.lo) * q / 200.0, val, der, f2);
        max_f2 = std::max(max_f2, std::abs(f2));
        max_sw = std::max(max_sw, std::abs(der[1]));
      }
      char b[256];
      if (max_f2 > config.kec_max_curvature) {
        std::snprintf(b, sizeof b,
                      "KEC: %s transition at s_k = %.4f mm: |f''| reaches %.3g 1/m (bound %.3g): "
                      "transition too short",
                      kSideName[k], t.s_jump * 1e3, max_f2, config.kec_max_curvature);
        st.warnings.push_back(b);
      }
      if (max_sw > config.kec_max_map_slope) {
        std::snprintf(b, sizeof b,
                      "KEC: %s transition at s_k = %.4f mm: |ds_w/ds_k| reaches %.3g (bound %.3g): "
                      "transition too short",
                      kSideName[k], t.s_jump * 1e3, max_sw, config.kec_max_map_slope);
        st.warnings.push_back(b);
      }
      if (t.hi - t.lo < 3.0 * config.kec_s.step) {
        st.warnings.push_back(std::string("KEC: ") + kSideName[k] +
                              " transition at s_k = " + mm(t.s_jump) + " (" + mm(t.hi - t.lo) +
                              ") spans fewer than 3 grid steps: refine the KEC grid");
      }
    }
  }
  st.bytes = 2 * (ng * kKecQuantities * 2 * sizeof(double) + (ng - 1) * 4 * sizeof(double));
  st.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return tab;
}

// ---- Online solver ------------------------------------------------------------------------------

KecSolution solveKec(const KecTable& tab, const KecInput& in, const KecSolution* warm) {
  KecSolution sol;
  const double r0 = tab.r0(), lr = tab.railLr();
  double z, phi, sl, sr;
  if (warm && warm->status != KecStatus::NotConverged) {
    z = warm->z;
    phi = warm->phi;
    sl = warm->s_lk;
    sr = warm->s_rk;
  } else {
    phi = 0.0;
    sl = in.y_lir - in.y;
    sr = in.y_rir - in.y;
    z = r0 + tab.f(Side::Left, sl) + in.z_lir;
  }
  constexpr int kMaxIter = 30;
  constexpr double kTol = 1e-13;
  constexpr double kMaxStep = 2e-3;
  Eigen::Matrix4d J;
  Eigen::Vector4d g;
  double fl = 0, dfl = 0, d2fl = 0, fr = 0, dfr = 0, d2fr = 0;
  bool ok = false;
  for (int it = 0; it <= kMaxIter; ++it) {
    fl = tab.f(Side::Left, sl, &dfl, &d2fl);
    fr = tab.f(Side::Right, sr, &dfr, &d2fr);
    g << in.y + sl + phi * (r0 + fl) - in.y_lir, in.y + sr + phi * (r0 + fr) - in.y_rir,
        z + phi * (lr + sl) - r0 - fl - in.z_lir, z + phi * (-lr + sr) - r0 - fr - in.z_rir;
    J << 0.0, r0 + fl, 1.0 + phi * dfl, 0.0,  //
        0.0, r0 + fr, 0.0, 1.0 + phi * dfr,   //
        1.0, lr + sl, phi - dfl, 0.0,         //
        1.0, -lr + sr, 0.0, phi - dfr;
    sol.residual = g.cwiseAbs().maxCoeff();
    sol.iterations = it;
    if (!std::isfinite(sol.residual)) break;
    if (sol.residual <= kTol) {
      ok = true;
      break;
    }
    if (it == kMaxIter) break;
    // 4x4: the closed-form (cofactor) inverse of Eigen is several times cheaper than a pivoted
    // LU here; a singular J gives non-finite steps, caught below.
    Eigen::Vector4d dx = -(J.inverse() * g);
    if (!dx.allFinite()) break;
    const double m = std::max(std::abs(dx(2)), std::abs(dx(3)));
    if (m > kMaxStep) dx *= kMaxStep / m;
    z += dx(0);
    phi += dx(1);
    sl += dx(2);
    sr += dx(3);
  }
  sol.z = z;
  sol.phi = phi;
  sol.s_lk = sl;
  sol.s_rk = sr;
  sol.f_lk = fl;
  sol.f_rk = fr;
  sol.df_lk = dfl;
  sol.df_rk = dfr;
  sol.d2f_lk = d2fl;
  sol.d2f_rk = d2fr;
  sol.g_x = J;
  if (!ok) {
    sol.status = KecStatus::NotConverged;
    return sol;
  }
  Eigen::Matrix<double, 4, 5> gp;
  gp << 1, -1, 0, 0, 0,  //
      1, 0, -1, 0, 0,    //
      0, 0, 0, -1, 0,    //
      0, 0, 0, 0, -1;
  sol.dx_dp = -(J.inverse() * gp);
  const bool inside = sl >= tab.validMin(Side::Left) && sl <= tab.validMax(Side::Left) &&
                      sr >= tab.validMin(Side::Right) && sr <= tab.validMax(Side::Right);
  sol.status = inside ? KecStatus::Ok : KecStatus::OutOfTable;
  return sol;
}

Eigen::Vector4d kecQuadraticTerm(const KecSolution& sol, const Eigen::Vector4d& xd) {
  // Second time derivative of g at fixed xddot, pddot: the terms quadratic in velocities.
  const double phid = xd(1), sld = xd(2), srd = xd(3);
  Eigen::Vector4d c;
  c << 2.0 * phid * sol.df_lk * sld + sol.phi * sol.d2f_lk * sld * sld,
      2.0 * phid * sol.df_rk * srd + sol.phi * sol.d2f_rk * srd * srd,
      2.0 * phid * sld - sol.d2f_lk * sld * sld, 2.0 * phid * srd - sol.d2f_rk * srd * srd;
  // A solved system already holds g_x^-1: dx_dp = -g_x^-1 g_p and the last four columns of -g_p
  // are the unit vectors, so dx_dp's last four columns ARE g_x^-1 (exactly, the products with
  // 0 / -1 round nothing). That saves a pivoted 4x4 LU per wheelset and evaluation.
  if (sol.status != KecStatus::NotConverged) return -(sol.dx_dp.rightCols<4>() * c);
  return -sol.g_x.partialPivLu().solve(c);
}

}  // namespace rb::contact
