#include "workbench/scenario/build.hpp"
#include "workbench/scenario/reader.hpp"
#include "workbench/vehicle/names.hpp"

namespace rb::scenario {
namespace {

vehicle::BodySpec buildBody(const Node& b, const std::string& path, Diagnostics& d) {
  Reader br(b, block("body"), path, d);
  vehicle::BodySpec body;
  body.loc = b.loc;
  body.name = br.string("name");
  body.kind = br.choiceOf<vehicle::BodyKind>("kind");
  body.mass = br.number("mass");
  if (br.vec3("inertia", body.inertia) && !(body.inertia.minCoeff() > 0))
    br.error(b, "inertia must be > 0 kg m^2 in every axis");
  body.x = br.number("x");
  body.height = br.number("height");
  return body;
}

// One suspension element (Appendix A); the keys its kind has in the schema are read.
vehicle::ElementSpec buildElement(const Node& e, const std::string& path, Diagnostics& d) {
  Reader er(e, block(e.kind), path, d);
  vehicle::ElementSpec el;
  el.loc = e.loc;
  el.kind = parse<vehicle::ElementKind>(e.kind).value_or(vehicle::ElementKind::SpringDamper);
  el.name = er.string("name");
  el.body1 = er.string("from");
  el.body2 = er.string("to");
  er.vec3("at_from", el.point1);
  er.vec3("at_to", el.point2);
  el.direction = er.choiceOf<vehicle::Direction>("direction");
  const BlockSpec& bs = block(e.kind);
  if (bs.key("stiffness")) el.stiffness = er.number("stiffness");
  if (bs.key("damping")) el.damping = er.number("damping");
  if (bs.key("series_stiffness")) el.series_stiffness = er.number("series_stiffness");
  if (bs.key("length0")) el.length0 = er.number("length0");
  if (bs.key("preload")) el.preload = er.number("preload");
  if (bs.key("table")) er.pairList("table", el.table_d, el.table_f);
  return el;
}

}  // namespace

void buildVehicle(const Node& n, vehicle::VehicleSpec& v, Diagnostics& d) {
  Reader r(n, block("vehicle"), "vehicle", d);
  v.loc = n.loc;
  v.name = r.string("name");
  v.speed = r.number("speed");
  v.acceleration = r.number("acceleration");
  v.wheel_radius = r.number("wheel_radius");
  v.start = r.number("start");
  auto bodies = r.blockList("bodies");
  for (std::size_t i = 0; i < bodies.size(); ++i)
    v.bodies.push_back(buildBody(*bodies[i], "vehicle.bodies[" + std::to_string(i + 1) + "]", d));
  if (!r.has("elements")) return;
  auto elements = r.blockList("elements");
  for (std::size_t i = 0; i < elements.size(); ++i)
    v.elements.push_back(
        buildElement(*elements[i], "vehicle.elements[" + std::to_string(i + 1) + "]", d));
}

}  // namespace rb::scenario
