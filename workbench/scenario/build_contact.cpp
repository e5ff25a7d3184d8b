#include "workbench/contact/interpolation.hpp"
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
  return false;
}

}  // namespace rb::scenario
