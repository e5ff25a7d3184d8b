#include <string>
#include <utility>
#include <vector>

#include "workbench/contact/interpolation.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/dynamics/limits.hpp"
#include "workbench/dynamics/names.hpp"
#include "workbench/scenario/build.hpp"
#include "workbench/scenario/reader.hpp"

namespace rb::scenario {
namespace {

// contact.elastic.rail_support: the block's values, or its `along` points (keys not given there
// take the block's values). Every point needs a mass and both stiffnesses.
void readRailSupport(const Node& n, std::vector<dynamics::RailSupportPoint>& out, Diagnostics& d) {
  Reader r(n, block("contact.elastic.rail_support"), "contact.elastic.rail_support", d);
  dynamics::RailSupportPoint base;
  base.loc = n.loc;
  base.mass = r.number("mass");
  base.k_z = r.number("k_z");
  base.c_z = r.number("c_z");
  base.k_y = r.number("k_y");
  base.c_y = r.number("c_y");
  std::vector<dynamics::RailSupportPoint> points;
  if (const Node* along = r.value("along")) {
    if (along->type != Node::Type::Table || !along->fields.empty() || along->items.empty() ||
        along->items.size() > dynamics::kMaxRailSupportPoints) {
      r.error(*along,
              "along must be a list of 1 to " + std::to_string(dynamics::kMaxRailSupportPoints) +
                  " points { s = <m>, mass = .., k_z = .., ... }, got " + along->describe());
      return;
    }
    for (std::size_t i = 0; i < along->items.size(); ++i) {
      const Node& item = along->items[i];
      const std::string at = "contact.elastic.rail_support.along[" + std::to_string(i + 1) + "]";
      if (item.type != Node::Type::Table || !item.items.empty() || !item.field("s")) {
        r.error(item, "along[" + std::to_string(i + 1) +
                          "] must be { s = <m>, mass = .., k_z = .., ... }, got " +
                          item.describe());
        continue;
      }
      Reader o(item, block("contact.elastic.rail_support.along"), at, d);
      dynamics::RailSupportPoint p = base;
      p.loc = item.loc;
      p.s = o.number("s");
      for (auto [key, target] :
           {std::pair{"mass", &p.mass}, std::pair{"k_z", &p.k_z}, std::pair{"c_z", &p.c_z},
            std::pair{"k_y", &p.k_y}, std::pair{"c_y", &p.c_y}})
        if (o.has(key)) *target = o.number(key);
      if (!points.empty() && !(p.s > points.back().s))
        o.error(*item.field("s"), "the points' s must increase strictly (the one before is at " +
                                      formatNumber(points.back().s) + " m)");
      points.push_back(p);
    }
  } else {
    points.push_back(base);
  }
  for (const dynamics::RailSupportPoint& p : points)
    if (!(p.mass > 0.0) || !(p.k_z > 0.0) || !(p.k_y > 0.0)) {
      d.add(p.loc,
            "contact.elastic.rail_support: every point needs mass, k_z and k_y (a rail mass on "
            "springs), got mass = " +
                formatNumber(p.mass) + " kg, k_z = " + formatNumber(p.k_z) +
                " N/m, k_y = " + formatNumber(p.k_y) + " N/m");
      return;
    }
  out = std::move(points);
}

}  // namespace

bool buildContact(const Node& n, dynamics::ContactSpec& c, Diagnostics& d) {
  Reader r(n, block("contact"), "contact", d);
  c.loc = n.loc;
  // Read once: every reading of a bad value reports it.
  const std::string method = r.choice("method");
  if (method == kGuidedContact) {
    // Guided wheelsets have no wheel/rail contact: every other key would be silently unused.
    for (const auto& [k, v] : n.fields)
      if (k != "method")
        r.error(v, k + " has no effect with method = \"" + std::string(kGuidedContact) +
                       "\" (the wheelsets follow the track kinematically, no wheel/rail forces)");
    return true;
  }
  c.method = parse<dynamics::ContactMethod>(method).value_or(dynamics::ContactMethod{});
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
    if (const Node* rs = o.blockValue("rail_support"))
      readRailSupport(*rs, c.elastic.rail_support, d);
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
