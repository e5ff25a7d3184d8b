#include "workbench/contact/interpolation.hpp"
#include "workbench/dynamics/limits.hpp"
#include "workbench/dynamics/names.hpp"
#include "workbench/scenario/build.hpp"
#include "workbench/scenario/reader.hpp"

namespace rb::scenario {

bool buildContact(const Node& n, dynamics::ContactSpec& c, Diagnostics& d) {
  Reader r(n, block("contact"), "contact", d);
  c.loc = n.loc;
  if (r.choice("method") == kGuidedContact) {
    // Guided wheelsets have no wheel/rail contact: every other key would be silently unused.
    for (const auto& [k, v] : n.fields)
      if (k != "method")
        r.error(v, k + " has no effect with method = \"" + std::string(kGuidedContact) +
                       "\" (the wheelsets follow the track kinematically, no wheel/rail forces)");
    return true;
  }
  c.method = r.choiceOf<dynamics::ContactMethod>("method");
  c.kec_dhat = r.number("dhat");
  c.kec_dbar = r.number("dbar");
  c.flange_stiffness = r.number("flange_stiffness");
  c.flange_damping = r.number("flange_damping");
  c.creep = r.choiceOf<dynamics::CreepModel>("creep");
  if (const Node* f = r.blockValue("fastsim")) {
    Reader o(*f, block("contact.fastsim"), "contact.fastsim", d);
    // A value out of its range is reported by number(); it must not reach the int conversion.
    const auto count = [&o](const char* key, const Range& range, int fallback) {
      const double x = o.number(key);
      return range.contains(x) ? static_cast<int>(x) : fallback;
    };
    c.fastsim.strips = count("strips", creep::kFastsimStripsRange, c.fastsim.strips);
    c.fastsim.elements = count("elements", creep::kFastsimElementsRange, c.fastsim.elements);
    c.fastsim.bound = o.choiceOf<creep::FastsimBound>("bound");
    if (c.creep != dynamics::CreepModel::Fastsim)
      r.error(*n.field("fastsim"), "fastsim applies to creep = \"fastsim\" only (creep = \"" +
                                       std::string(nameOf(c.creep)) + "\")");
  }
  if (const Node* e = r.blockValue("elastic")) {
    Reader o(*e, block("contact.elastic"), "contact.elastic", d);
    c.elastic.loc = e->loc;
    c.elastic.damping_ratio = o.number("damping_ratio");
    c.elastic.sample_step = o.number("sample_step");
    c.elastic.derailment_lift = o.number("derailment_lift");
    c.elastic.min_curvature_ratio = o.number("min_curvature_ratio");
    if (const double lift = c.elastic.derailment_lift;
        lift >= 0.0 && !dynamics::kDerailmentLiftRange.contains(lift))
      o.error(*e->field("derailment_lift"), "derailment_lift must be in " +
                                                dynamics::kDerailmentLiftRange.text() +
                                                " m, or -1 for half the wheel's flange height");
    if (c.method != dynamics::ContactMethod::Elastic)
      r.error(*n.field("elastic"), "elastic applies to method = \"elastic\" only (method = \"" +
                                       std::string(nameOf(c.method)) + "\")");
  }
  c.mu = r.number("mu");
  c.youngs_modulus = r.number("youngs_modulus");
  c.poisson = r.number("poisson");
  c.normal_forces = r.choiceOf<dynamics::NormalForceCoupling>("normal_forces");
  c.wheelset_spin = r.choiceOf<dynamics::WheelsetSpin>("wheelset_spin");
  c.min_normal_force = r.number("min_normal_force");
  c.table_interpolation = r.choiceOf<contact::TableInterpolation>("table_interpolation");
  // Options that belong to the other method are conflicts, not silently ignored.
  const bool kec = c.method == dynamics::ContactMethod::Kec;
  for (const char* k : {"flange_stiffness", "flange_damping"})
    if (kec && r.has(k))
      r.error(
          *n.field(k),
          std::string(k) + " applies to method 'lut' only (KEC treats the flange as a constraint)");
  for (const char* k : {"dhat", "dbar"})
    if (!kec && r.has(k)) r.error(*n.field(k), std::string(k) + " applies to method 'kec' only");
  // The elastic method has no table, no multipliers and no constraint normal force.
  if (c.method == dynamics::ContactMethod::Elastic)
    for (const char* k : {"flange_stiffness", "flange_damping", "normal_forces", "min_normal_force",
                          "table_interpolation"})
      if (r.has(k))
        r.error(*n.field(k),
                std::string(k) +
                    " applies to the constraint methods 'kec' and 'lut' only (method = "
                    "\"elastic\": Hertz normal forces per patch from the approach, no table, "
                    "derailment by contact.elastic.derailment_lift)");
  return false;
}

}  // namespace rb::scenario
