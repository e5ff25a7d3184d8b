// The linear critical speed (stability.hpp): the least damped hunting mode's damping ratio on a
// speed sweep, the first sign change from positive to negative, refined by the Illinois variant of
// regula falsi (superlinear on a smooth damping curve, never leaves the bracket).
#include <cmath>
#include <sstream>

#include "workbench/stability/stability.hpp"

namespace rb::stability {

namespace {

void addCost(CriticalSpeed& c, const Analysis& a) {
  c.rhs_evaluations += a.rhs_evaluations;
  c.cpu_s += a.cpu_s;
}

std::string noneInRange(const std::vector<Analysis>& sweep) {
  std::ostringstream s;
  s << "none in range";
  if (!sweep.empty())
    s << ": least damped hunting mode damping " << sweep.front().huntingDamping() << " at "
      << sweep.front().speed << " m/s, " << sweep.back().huntingDamping() << " at "
      << sweep.back().speed << " m/s";
  return s.str();
}

// A bracket of the critical speed: speeds a < b with the damping fa > 0 >= fb.
struct Bracket {
  double a, fa, b, fb;
};

// Refines the bracket to tol; `br` keeps the narrowest bracket reached (also when an analysis
// throws). A refinement speed without a hunting mode ends the refinement, with c.why saying so.
void refine(Analyser& an, CriticalSpeed& c, Bracket& br, double tol) {
  auto& [a, fa, b, fb] = br;
  int side = 0;
  for (int it = 0; it < 40 && b - a > tol; ++it) {
    double v = b - fb * (b - a) / (fb - fa);
    if (!(v > a && v < b)) v = 0.5 * (a + b);
    Analysis x = an.analyse(v);
    addCost(c, x);
    const double fv = x.huntingDamping();
    c.refinement.push_back(std::move(x));
    if (!std::isfinite(fv)) {
      std::ostringstream m;
      m << "refinement stopped at " << v << " m/s: no hunting mode there; the critical speed is "
        << "interpolated in " << a << " .. " << b << " m/s";
      c.why = m.str();
      break;
    }
    if (fv > 0.0) {
      a = v;
      fa = fv;
      if (side == -1) fb *= 0.5;  // Illinois: the end kept twice in a row is halved
      side = -1;
    } else {
      b = v;
      fb = fv;
      if (side == 1) fa *= 0.5;
      side = 1;
    }
  }
  c.bracket_lo = a;
  c.bracket_hi = b;
  c.speed = b - fb * (b - a) / (fb - fa);
  if (!(c.speed >= a && c.speed <= b)) c.speed = 0.5 * (a + b);
  c.found = true;
}

// CriticalSpeed::step_uncertainty from the analysis nearest the critical speed and the slope of
// the damping over the sweep's bracket [v_a, v_b].
double stepUncertainty(const CriticalSpeed& c, const Analysis& a, const Analysis& b) {
  const Analysis* nearest = &a;
  auto closer = [&](const Analysis& x) {
    if (std::abs(x.speed - c.speed) < std::abs(nearest->speed - c.speed)) nearest = &x;
  };
  closer(b);
  for (const Analysis& x : c.refinement) closer(x);
  if (nearest->least_hunting < 0) return std::nan("");
  const double slope = (b.huntingDamping() - a.huntingDamping()) / (b.speed - a.speed);
  const double dzeta = nearest->modes[static_cast<std::size_t>(nearest->least_hunting)].step_change;
  return std::abs(dzeta / slope);
}

}  // namespace

CriticalSpeed linearCriticalSpeed(Analyser& an, std::vector<Analysis> sweep, double tol) {
  CriticalSpeed c;
  for (const Analysis& a : sweep) addCost(c, a);
  c.sweep = std::move(sweep);
  // Consecutive speeds with a hunting mode: a speed without one (its damping NaN) in between
  // must not hide the crossing.
  std::size_t last = c.sweep.size();
  for (std::size_t i = 0; i < c.sweep.size(); ++i) {
    const double fb = c.sweep[i].huntingDamping();
    if (!std::isfinite(fb)) continue;
    const double fa = last < c.sweep.size() ? c.sweep[last].huntingDamping() : std::nan("");
    if (fa > 0.0 && fb <= 0.0) {
      Bracket br{c.sweep[last].speed, fa, c.sweep[i].speed, fb};
      try {
        refine(an, c, br, tol);
      } catch (const Failure& e) {
        c.found = true;  // the narrowest bracket reached stands
        c.bracket_lo = br.a;
        c.bracket_hi = br.b;
        c.speed = br.a - br.fa * (br.b - br.a) / (br.fb - br.fa);
        c.why = std::string("refinement stopped: ") + e.what();
      }
      c.step_uncertainty = stepUncertainty(c, c.sweep[last], c.sweep[i]);
      return c;
    }
    last = i;
  }
  c.why = noneInRange(c.sweep);
  return c;
}

CriticalSpeed linearCriticalSpeed(const scenario::ScenarioSpec& spec, double v_lo, double v_hi,
                                  int n, const Options& options, double tol) {
  Analyser an(spec, options);
  std::vector<Analysis> sweep;
  const int m = std::max(n, 2);
  for (int i = 0; i < m; ++i) sweep.push_back(an.analyse(v_lo + (v_hi - v_lo) * i / (m - 1)));
  return linearCriticalSpeed(an, std::move(sweep), tol);
}

}  // namespace rb::stability
