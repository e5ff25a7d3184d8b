// The linear critical speed (stability.hpp): the least damped mode's damping ratio on a speed
// sweep (any mode; and the hunting modes alone), the first sign change from positive to negative,
// refined by the Illinois variant of regula falsi (superlinear on a smooth damping curve, never
// leaves the bracket).
#include <cmath>
#include <sstream>

#include "workbench/core/strings.hpp"
#include "workbench/stability/stability.hpp"

namespace rb::stability {

namespace {

void addCost(CriticalSpeed& c, const Analysis& a) {
  c.rhs_evaluations += a.rhs_evaluations;
  c.cpu_s += a.cpu_s;
}

// Which mode a crossing follows: the least damped of any kind, or of the hunting modes.
enum class Which { Any, Hunting };

int modeIndex(const Analysis& a, Which w) {
  return w == Which::Any ? a.least_damped : a.least_hunting;
}

double damping(const Analysis& a, Which w) {
  return w == Which::Any ? a.leastDamping() : a.huntingDamping();
}

const char* modeWord(Which w) {
  return w == Which::Any ? "least damped mode" : "least damped hunting mode";
}

std::string noneInRange(const std::vector<Analysis>& sweep, Which w) {
  std::ostringstream s;
  s << "none in range";
  if (!sweep.empty())
    s << ": " << modeWord(w) << " damping " << damping(sweep.front(), w) << " at "
      << sweep.front().speed << " m/s, " << damping(sweep.back(), w) << " at " << sweep.back().speed
      << " m/s";
  return s.str();
}

// A bracket of the critical speed: speeds a < b with the damping fa > 0 >= fb.
struct Bracket {
  double a, fa, b, fb;
};

struct Crossing {
  bool found = false;
  double speed = 0.0, lo = 0.0, hi = 0.0;
  std::string why;
  const Analysis* unstable_side = nullptr;  // the analysis at the bracket's unstable end
  double step_uncertainty = std::nan("");
};

// Refines the bracket to tol; `br` keeps the narrowest bracket reached (also when an analysis
// throws). A refinement speed without the followed mode ends the refinement, with x.why saying so.
void refine(Analyser& an, CriticalSpeed& c, Crossing& x, Bracket& br, double tol, Which w,
            std::size_t& hi_index) {
  auto& [a, fa, b, fb] = br;
  int side = 0;
  for (int it = 0; it < 40 && b - a > tol; ++it) {
    double v = b - fb * (b - a) / (fb - fa);
    if (!(v > a && v < b)) v = 0.5 * (a + b);
    Analysis r = an.analyse(v);
    addCost(c, r);
    const double fv = damping(r, w);
    c.refinement.push_back(std::move(r));
    if (!std::isfinite(fv)) {
      std::ostringstream m;
      m << "refinement stopped at " << v << " m/s: no " << modeWord(w)
        << " there; the critical speed is interpolated in " << a << " .. " << b << " m/s";
      x.why = m.str();
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
      hi_index = c.refinement.size() - 1;
      if (side == 1) fa *= 0.5;
      side = 1;
    }
  }
  x.lo = a;
  x.hi = b;
  x.speed = b - fb * (b - a) / (fb - fa);
  if (!(x.speed >= a && x.speed <= b)) x.speed = 0.5 * (a + b);
  x.found = true;
}

// The step uncertainty from the analysis nearest the critical speed and the slope of the damping
// over the sweep's bracket [v_a, v_b] (CriticalSpeed::step_uncertainty).
double stepUncertainty(const CriticalSpeed& c, double speed, const Analysis& a, const Analysis& b,
                       Which w) {
  const Analysis* nearest = &a;
  auto closer = [&](const Analysis& x) {
    if (std::abs(x.speed - speed) < std::abs(nearest->speed - speed)) nearest = &x;
  };
  closer(b);
  for (const Analysis& x : c.refinement) closer(x);
  const int i = modeIndex(*nearest, w);
  if (i < 0) return std::nan("");
  const double slope = (damping(b, w) - damping(a, w)) / (b.speed - a.speed);
  const double dzeta = nearest->modes[static_cast<std::size_t>(i)].step_change;
  return std::abs(dzeta / slope);
}

// The first crossing of the followed mode's damping over c.sweep, refined. Consecutive speeds
// with that mode: a speed without one (its damping NaN) in between must not hide the crossing.
Crossing crossing(Analyser& an, CriticalSpeed& c, double tol, Which w) {
  Crossing x;
  std::size_t last = c.sweep.size();
  for (std::size_t i = 0; i < c.sweep.size(); ++i) {
    const double fb = damping(c.sweep[i], w);
    if (!std::isfinite(fb)) continue;
    const double fa = last < c.sweep.size() ? damping(c.sweep[last], w) : std::nan("");
    if (fa > 0.0 && fb <= 0.0) {
      Bracket br{c.sweep[last].speed, fa, c.sweep[i].speed, fb};
      // Index of the unstable end: in the sweep (kSweep) or the refinement.
      constexpr std::size_t kSweep = static_cast<std::size_t>(-1);
      std::size_t hi_index = kSweep;
      try {
        refine(an, c, x, br, tol, w, hi_index);
      } catch (const Failure& e) {
        x.found = true;  // the narrowest bracket reached stands
        x.lo = br.a;
        x.hi = br.b;
        x.speed = br.a - br.fa * (br.b - br.a) / (br.fb - br.fa);
        x.why = std::string("refinement stopped: ") + e.what();
      }
      x.unstable_side = hi_index == kSweep ? &c.sweep[i] : &c.refinement[hi_index];
      x.step_uncertainty = stepUncertainty(c, x.speed, c.sweep[last], c.sweep[i], w);
      return x;
    }
    last = i;
  }
  x.why = noneInRange(c.sweep, w);
  return x;
}

// The modes unstable at the sweep's lowest speed, one line (empty when none).
std::string unstableAtStart(const Analysis& a) {
  std::string s;
  for (std::size_t i : a.unstableModes()) s += (s.empty() ? "" : "; ") + describe(a.modes[i]);
  return s;
}

}  // namespace

CriticalSpeed linearCriticalSpeed(Analyser& an, std::vector<Analysis> sweep, double tol) {
  CriticalSpeed c;
  for (const Analysis& a : sweep) addCost(c, a);
  c.sweep = std::move(sweep);
  // A mode unstable at the lowest speed analysed puts the answer below the range, whatever
  // crossings follow (a mode may regain its damping and another lose it further up).
  if (!c.sweep.empty() && !c.sweep.front().unstableModes().empty()) {
    const Analysis& f = c.sweep.front();
    c.below_range = true;
    const Mode& m = f.modes[static_cast<std::size_t>(f.least_damped)];
    c.mode = describe(m) + " at " + formatNumber(f.speed, 4) + " m/s";
    c.mode_is_hunting = m.hunting;
    std::ostringstream s;
    s << "below the lowest speed analysed (" << f.speed
      << " m/s): unstable there: " << unstableAtStart(f);
    c.why = s.str();
    c.step_uncertainty = std::nan("");
  } else {
    // Refinement analyses are appended to c.refinement, which may reallocate: what is needed of
    // the unstable side is taken before the hunting crossing below.
    const Crossing any = crossing(an, c, tol, Which::Any);
    c.why = any.why;
    c.step_uncertainty = any.step_uncertainty;
    if (any.found) {
      c.found = true;
      c.speed = any.speed;
      c.bracket_lo = any.lo;
      c.bracket_hi = any.hi;
      const Analysis& u = *any.unstable_side;
      if (u.least_damped >= 0) {
        const Mode& m = u.modes[static_cast<std::size_t>(u.least_damped)];
        c.mode = describe(m) + " at " + formatNumber(u.speed, 4) + " m/s";
        c.mode_is_hunting = m.hunting;
      }
    }
  }
  if (c.found && c.mode_is_hunting) {
    c.hunting_found = true;
    c.hunting_speed = c.speed;
    c.hunting_why = c.why;
  } else {
    const Crossing h = crossing(an, c, tol, Which::Hunting);
    c.hunting_found = h.found;
    c.hunting_speed = h.found ? h.speed : 0.0;
    c.hunting_why = h.why;
    if (!h.found && !c.sweep.empty() && c.sweep.front().huntingDamping() <= 0.0)
      c.hunting_why = "a hunting mode is unstable at the lowest speed analysed (" +
                      formatNumber(c.sweep.front().speed, 4) + " m/s)";
  }
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
