// Build of the KEC tables (paper section 2.4, steps 1-4; see kec.hpp): the real contact followed
// toward each flange, the equivalent profiles with their contact-point jumps, the regularisation
// of the jumps (Fig. 9-10, the weights of Eq. 26) and the resampling on the KEC grid. The online
// solver and the table evaluation are in kec_solve.cpp.
#include "workbench/contact/kec.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

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

  // Step 1 of the build in one direction: the real contact followed by continuation in the knife
  // position of the wheel approaching its flange (dir > 0: left, y increasing), from x0 to the
  // end of the KEC grid or the flange tip, cut into branches at the contact-point jumps.
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
      const SweepStep s = continuationStep(x, p, pv + step);
      if (s.failure != nullptr) {
        sw.end = s.failure;
        break;
      }
      if (s.jside >= 0) {
        // A new branch starts at the contact point after the jump.
        if (!s.fold) cur.s.push_back(makeSample(s.xj));
        sw.pieces.push_back(std::move(cur));
        sw.junctions.push_back(junction(s));
        cur = Piece{};
        cur.s.push_back(makeSample(s.xnew));
        x = s.xnew;
        pv = solver_.parameterValue(x, p);
        continue;
      }
      x = s.xn;
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
  // Outcome of one continuation step from x to the parameter value `target`: the next point xn
  // of the same branch, or a contact-point jump of wheel jside (two-point contact at xj, the
  // branch continued at xnew; fold: the branch through x ended there), or a failure (why).
  struct SweepStep {
    ContactState xn, xj, xnew;
    int jside = -1;
    bool fold = false;
    const char* failure = nullptr;
  };

  SweepStep continuationStep(const ContactState& x, Parameter p, double target) {
    SweepStep s;
    s.xn = x;
    if (advance(s.xn, p, target)) {
      ContactSolver::Gap g;
      for (std::size_t k = 0; k < 2 && s.jside < 0; ++k) {
        if (penetratesElsewhere(s.xn, k, g)) s.jside = static_cast<int>(k);
      }
      if (s.jside >= 0 &&
          !locateJump(x, s.xn, p, static_cast<std::size_t>(s.jside), g, s.xj, s.xnew)) {
        s.failure = "a contact-point jump could not be located";
      }
    } else if (jumpAtFold(x, p, target, s.jside, s.xnew)) {
      // The branch ends (fold): the contact jumps to the nearest other candidate point.
      s.xj = x;
      s.fold = true;
    } else {
      s.failure = "continuation failed (branch ended, no other contact found)";
    }
    return s;
  }

  // The junction of a jump step: which wheel jumps, and whether its new contact point lies on the
  // flange side of the tread/flange boundary while the old one did not (tread-flange jump).
  Junction junction(const SweepStep& s) const {
    const auto k = static_cast<std::size_t>(s.jside);
    const Side side = k == 0 ? Side::Left : Side::Right;
    Junction J;
    J.jumping = k;
    const double b = solver_.flangeBoundary(side);
    J.flange = solver_.hasFlange(side) && kSideSign[k] * (s.xnew.s[2 * k] - b) < 0.0 &&
               kSideSign[k] * (s.xj.s[2 * k] - b) >= 0.0;
    J.y = s.xj.y;
    return J;
  }

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

// ---- Table build, section 2.4 steps 1-4 ---------------------------------------------------------

// Transition lengths d_hat, d_bar (Table 9) against the bound below which the constraint Jacobian
// of Eq. (22) becomes ill-conditioned, and against the resolution of the KEC grid.
void checkTransitionLengths(const ContactGeometryConfig& config, TableBuildStats& st) {
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
}

// Start of both sweeps: the centred wheelset (Eq. 12 with the global search).
ContactState centredContact(const ContactSolver& solver) {
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
  return x0;
}

// The contact branches of both sweeps as sample lists in ascending s_k (sweep `sl` runs toward low
// s_k, `sr` toward high s_k; both start at the centred wheelset, whose sample is kept once), with
// the junctions (contact-point jumps) between consecutive branches.
struct OrderedBranches {
  std::vector<std::vector<const Sample*>> pieces;
  std::vector<const Junction*> junctions;  // junctions[m] between pieces[m] and pieces[m + 1]
};

OrderedBranches orderBranches(const Sweep& sl, const Sweep& sr) {
  OrderedBranches br;
  for (std::size_t i = sl.pieces.size(); i-- > 1;) {
    std::vector<const Sample*> v;
    for (auto it = sl.pieces[i].s.rbegin(); it != sl.pieces[i].s.rend(); ++it) v.push_back(&*it);
    br.pieces.push_back(std::move(v));
    br.junctions.push_back(&sl.junctions[i - 1]);
  }
  {
    std::vector<const Sample*> v;
    for (auto it = sl.pieces[0].s.rbegin(); it != sl.pieces[0].s.rend(); ++it) v.push_back(&*it);
    for (std::size_t i = 1; i < sr.pieces[0].s.size(); ++i) v.push_back(&sr.pieces[0].s[i]);
    br.pieces.push_back(std::move(v));
  }
  for (std::size_t i = 1; i < sr.pieces.size(); ++i) {
    br.junctions.push_back(&sr.junctions[i - 1]);
    std::vector<const Sample*> v;
    for (const Sample& smp : sr.pieces[i].s) v.push_back(&smp);
    br.pieces.push_back(std::move(v));
  }
  return br;
}

// Real branches of the equivalent profile of wheel k (step 2): the channels of each branch as
// splines of s_k. The equivalent profile must be a function of s_k: samples that do not advance in
// s_k are dropped (warned).
std::vector<ProfilePiece> branchSplines(const OrderedBranches& br, std::size_t k,
                                        TableBuildStats& st) {
  std::vector<ProfilePiece> pp(br.pieces.size());
  std::size_t dropped = 0;
  for (std::size_t m = 0; m < br.pieces.size(); ++m) {
    for (const Sample* smp : br.pieces[m]) {
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
  return pp;
}

// Transition bands of the Eq. (26) regularisation (step 3): the requested [s_j - L_low, s_j +
// L_high] around each jump s_j, L = d_hat on the flange side of the jump and d_bar on the field
// side (left profile: flange side = low s_k; right profile: high s_k), cut to the neighbouring
// branches and so that neighbouring bands do not overlap. Shortened bands are noted, unusable ones
// warned.
std::vector<KecTransition> transitionBands(const std::vector<ProfilePiece>& pp,
                                           const std::vector<const Junction*>& junctions,
                                           std::size_t k, const ContactGeometryConfig& config,
                                           TableBuildStats& st) {
  const std::array<double, 2> low_len{config.kec_dhat, config.kec_dbar};   // flange side: left low
  const std::array<double, 2> high_len{config.kec_dbar, config.kec_dhat};  // right high
  std::vector<KecTransition> tr;
  for (std::size_t m = 0; m < junctions.size(); ++m) {
    const Junction& J = *junctions[m];
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
                         mm(tr[m].s_jump) + " shortened to [" + mm(tr[m].lo) + ", " + mm(tr[m].hi) +
                         "] (the branch on one side is shorter than the " +
                         "transition length, or the next jump is close)");
    }
    if (shortened && (!(tr[m].lo < tr[m].s_jump && tr[m].s_jump < tr[m].hi) ||
                      tr[m].hi - tr[m].lo < config.kec_min_transition)) {
      st.warnings.push_back(std::string("KEC: ") + kSideName[k] + " transition at s_k = " +
                            mm(tr[m].s_jump) + " is only [" + mm(tr[m].lo) + ", " + mm(tr[m].hi) +
                            "]: jumps too close together for the transition " + "lengths");
    }
  }
  return tr;
}

// The regularised channels of one equivalent profile at s_k (Fig. 9-10): values and exact
// s_k-derivatives (f also its second derivative). In a transition [lo, hi] between branch L (below)
// and H (above): f is the quintic Hermite matching f, f', f'' of L at lo and of H at hi; every
// other channel is the linear ramp between L(lo) and H(hi); the weight of the flange-side end B
// ramps 0 -> 1 (Eq. 26). Outside transitions: the real branch.
class RegularisedProfile {
 public:
  RegularisedProfile(const std::vector<ProfilePiece>& pp, const std::vector<KecTransition>& tr,
                     std::size_t k)
      : pp_(pp), tr_(tr), k_(k) {}

  void eval(double sv, double* val, double* der, double& f2) const {
    std::size_t m = 0;
    while (m < tr_.size() && sv > tr_[m].hi) ++m;
    if (m < tr_.size() && sv >= tr_[m].lo) {
      evalTransition(m, sv, val, der, f2);
    } else {
      evalBranch(m, sv, val, der, f2);
    }
  }

 private:
  // Inside transition m, between branches m (below) and m + 1 (above).
  void evalTransition(std::size_t m, double sv, double* val, double* der, double& f2) const {
    const KecTransition& t = tr_[m];
    double la[kProfileChannels], la1[kProfileChannels], la2[kProfileChannels];
    double hb[kProfileChannels], hb1[kProfileChannels], hb2[kProfileChannels];
    pp_[m].eval(t.lo, la, la1, la2);
    pp_[m + 1].eval(t.hi, hb, hb1, hb2);
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
    const double wB = k_ == 0 ? 1.0 - u : u;
    const double dwB = (k_ == 0 ? -1.0 : 1.0) / L;
    const double* A = k_ == 0 ? hb : la;
    const double* B = k_ == 0 ? la : hb;
    val[kProfileChannels] = wB;
    der[kProfileChannels] = dwB;
    val[kProfileChannels + 1] = A[1];
    val[kProfileChannels + 2] = A[2];
    val[kProfileChannels + 3] = B[1];
    val[kProfileChannels + 4] = B[2];
    for (std::size_t c = kProfileChannels + 1; c < kKecQuantities; ++c) der[c] = 0.0;
  }

  // On the real branch m: the branch point is both A and B, with weight 0.
  void evalBranch(std::size_t m, double sv, double* val, double* der, double& f2) const {
    double d2[kProfileChannels];
    pp_[m].eval(sv, val, der, d2);
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
  }

  const std::vector<ProfilePiece>& pp_;
  const std::vector<KecTransition>& tr_;
  std::size_t k_;
};
static_assert(kProfileChannels + 5 == kKecQuantities, "KEC channel layout");

// Step 4: the regularised channels resampled on the uniform KEC grid as local cubic Hermite data,
// herm[(i * kKecQuantities + q) * 2 + {0: value, 1: d/ds_k}].
std::vector<double> resampleOnGrid(const RegularisedProfile& reg, const GridSpec& grid,
                                   std::size_t ng) {
  std::vector<double> herm(ng * kKecQuantities * 2, 0.0);
  for (std::size_t i = 0; i < ng; ++i) {
    double val[kKecQuantities], der[kKecQuantities], f2 = 0.0;
    reg.eval(grid.at(i), val, der, f2);
    for (std::size_t q = 0; q < kKecQuantities; ++q) {
      herm[(i * kKecQuantities + q) * 2] = val[q];
      herm[(i * kKecQuantities + q) * 2 + 1] = der[q];
    }
  }
  return herm;
}

// The real contact points A (field side) and B (flange side) of each transition.
void transitionEndPoints(const RegularisedProfile& reg, std::vector<KecTransition>& tr) {
  for (KecTransition& t : tr) {
    double val[kKecQuantities], der[kKecQuantities], f2;
    reg.eval(0.5 * (t.lo + t.hi), val, der, f2);
    t.s_w_field = val[kProfileChannels + 1];
    t.s_w_flange = val[kProfileChannels + 3];
  }
}

// Steepness of the regularised maps inside each transition (exact, before resampling: |f''| and
// |ds_w/ds_k| against their bounds) and the resolution of the transition by the KEC grid.
void checkTransitionSteepness(const RegularisedProfile& reg, const std::vector<KecTransition>& tr,
                              std::size_t k, const ContactGeometryConfig& config,
                              TableBuildStats& st) {
  for (const KecTransition& t : tr) {
    double max_f2 = 0.0, max_sw = 0.0;
    for (int q = 0; q <= 200; ++q) {
      double val[kKecQuantities], der[kKecQuantities], f2 = 0.0;
      reg.eval(t.lo + (t.hi - t.lo) * q / 200.0, val, der, f2);
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

// The regularised equivalent profile of wheel k on the KEC grid (steps 2-4).
struct EquivalentProfile {
  std::vector<double> herm;       // KecTable::herm_ layout
  std::array<double, 2> valid{};  // s_k range computed from contact geometry
  std::vector<KecTransition> trans;
};

EquivalentProfile equivalentProfile(const OrderedBranches& br, std::size_t k,
                                    const ContactGeometryConfig& config, TableBuildStats& st) {
  EquivalentProfile ep;
  const std::vector<ProfilePiece> pp = branchSplines(br, k, st);
  ep.trans = transitionBands(pp, br.junctions, k, config, st);
  ep.valid = {pp.front().lo(), pp.back().hi()};
  const RegularisedProfile reg(pp, ep.trans, k);
  ep.herm = resampleOnGrid(reg, config.kec_s, config.kec_s.count());
  transitionEndPoints(reg, ep.trans);
  if (ep.valid[0] > config.kec_s.min || ep.valid[1] < config.kec_s.max) {
    st.notes.push_back(std::string("KEC: ") + kSideName[k] + " profile computed on s_k in [" +
                       mm(ep.valid[0]) + ", " + mm(ep.valid[1]) +
                       "], extrapolated linearly beyond");
  }
  checkTransitionSteepness(reg, ep.trans, k, config, st);
  return ep;
}

}  // namespace

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
  tab.interp_ = config.interpolation;
  Builder bld(config, st);
  checkTransitionLengths(config, st);

  // Step 1: the real contact followed from the centred wheelset toward each flange.
  const ContactState x0 = centredContact(bld.solver());
  const Sweep sl = bld.sweep(x0, +1);  // toward the left flange (y > 0, s_k decreasing)
  const Sweep sr = bld.sweep(x0, -1);  // toward the right flange (y < 0, s_k increasing)
  st.notes.push_back("KEC: branch toward the left flange ended: " + sl.end);
  st.notes.push_back("KEC: branch toward the right flange ended: " + sr.end);
  std::size_t n_samples = 0;
  for (const Sweep* sw : {&sl, &sr}) {
    for (const Piece& p : sw->pieces) n_samples += p.s.size();
  }
  st.nodes = n_samples;

  // Steps 2-4 per equivalent profile.
  const OrderedBranches br = orderBranches(sl, sr);
  for (std::size_t k = 0; k < 2; ++k) {
    EquivalentProfile ep = equivalentProfile(br, k, config, st);
    tab.herm_[k] = std::move(ep.herm);
    tab.valid_[k] = ep.valid;
    tab.trans_[k] = std::move(ep.trans);
    tab.makeFSpline(k);
  }
  const std::size_t ng = tab.n_;
  st.bytes = 2 * (ng * kKecQuantities * 2 * sizeof(double) + (ng - 1) * 4 * sizeof(double));
  st.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return tab;
}

}  // namespace rb::contact
