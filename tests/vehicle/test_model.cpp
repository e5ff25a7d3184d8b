// Vehicle compilation: validation, element grouping and counting, the Lua vehicle files.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "fixtures.hpp"
#include "workbench/vehicle/guided.hpp"
#include "workbench/vehicle/model.hpp"

namespace rb::vehicle {
namespace {

const track::TrackModel& straight() {
  static const track::TrackModel tm = track::compileTrack(rbtest::tangentTrack());
  return tm;
}

std::string errorsOf(const VehicleSpec& spec) {
  try {
    compileVehicle(spec, straight());
  } catch (const InputError& e) {
    return e.what();
  }
  return "<no error>";
}

// anti_roll_bar = false leaves the paper's Table 4 alone: 48 elements, no roll coupling of car and
// bogie besides the springs.
TEST(ManchesterWagon, WithoutAntiRollBarsTheTable4Count) {
  const scenario::ScenarioSpec s = rbtest::loadTestScenario("manchester_table4.lua");
  ASSERT_TRUE(s.has_vehicle);
  EXPECT_EQ(s.vehicle.elements.size(), 48u);
  for (const ElementSpec& e : s.vehicle.elements)
    EXPECT_EQ(e.name.find("anti_roll"), std::string::npos) << e.name;
}

TEST(ManchesterWagon, Table4ElementsAndAntiRollBarsGroupedByKind) {
  const VehicleModel m = compileVehicle(rbtest::manchesterWagon(), straight());
  ASSERT_EQ(m.bodies.size(), 7u);
  // Table 4, per bogie (x 2 bogies = 48), one element per row group and location:
  //   primary, per axle box (4/bogie): vertical (Kpz || Dpz-Kseries_pz) + longitudinal
  //   (Kpx || Dpx) + lateral (Kpy || Dpy)                                            = 12
  //   secondary: vertical (Ksz || Dsz-Kseries_sz) 2 + shear x 2 + shear y 2 + bending 2
  //   + longitudinal (Ksx || Dsx) 1 + lateral (Dsy-Ksy) 2 + lateral bumpstop 1        = 12
  // and the anti-roll bar of the Manchester benchmark data, 1/bogie (a bending spring about x).
  EXPECT_EQ(m.elementCount(), 50);
  EXPECT_EQ(m.series_dampers.size(), 16u);  // 8 primary + 4 secondary vertical + 4 secondary y
  EXPECT_EQ(m.spring_dampers.size(), 18u);  // 16 primary x/y + 2 secondary x
  EXPECT_EQ(m.shear_springs.size(), 8u);
  EXPECT_EQ(m.bending_springs.size(), 6u);  // 4 secondary yaw bending + 2 anti-roll bars
  EXPECT_EQ(m.bumpstops.size(), 2u);
  EXPECT_EQ(m.element_kinds,
            (std::vector<std::string>{"spring_damper", "series_damper", "shear_spring",
                                      "bending_spring", "bumpstop"}));
  // Per bogie and per suspension stage.
  std::map<std::string, int> per;
  for (const ElementId& id : m.elements()) {
    const ElementGeometry& g = m.element(id);
    const std::string a = m.bodies[static_cast<std::size_t>(g.body1)].name;
    const std::string b = m.bodies[static_cast<std::size_t>(g.body2)].name;
    ++per[a == "car" ? "secondary " + b : "primary " + a];
  }
  EXPECT_EQ(per["primary bogie1"], 12);
  EXPECT_EQ(per["primary bogie2"], 12);
  EXPECT_EQ(per["secondary bogie1"], 13);
  EXPECT_EQ(per["secondary bogie2"], 13);
  // Lookup by name.
  const auto id = m.findElement("bump_y_bogie2");
  ASSERT_TRUE(id.has_value());
  EXPECT_EQ(id->kind, ElementKind::Bumpstop);
  EXPECT_EQ(id->index, 1);
  EXPECT_DOUBLE_EQ(m.bumpstops[1].law.clearance(), 0.025);
  EXPECT_FALSE(m.findElement("nope").has_value());
}

TEST(ManchesterWagon, KindsNotPresentAreNotRecorded) {
  VehicleSpec v = rbtest::withoutDampers(rbtest::manchesterWagon());
  std::erase_if(v.elements, [](const ElementSpec& e) { return e.kind == ElementKind::Bumpstop; });
  const VehicleModel m = compileVehicle(v, straight());
  EXPECT_TRUE(m.series_dampers.empty());
  EXPECT_TRUE(m.bumpstops.empty());
  EXPECT_EQ(m.element_kinds,
            (std::vector<std::string>{"spring_damper", "shear_spring", "bending_spring"}));
}

TEST(ManchesterWagon, NominalConfigurationHasUndeformedElements) {
  // The attachment points of each element coincide in the nominal configuration except where
  // they are on different levels by design; directional deformations are measured from there.
  const VehicleModel m = compileVehicle(rbtest::manchesterWagon(), straight());
  for (const ElementId& id : m.elements())
    EXPECT_LT(m.element(id).delta_nominal.norm(), 1e-12) << m.element(id).name;
}

TEST(GuidedLayout, StateNamesAndIndices) {
  const VehicleModel m = compileVehicle(rbtest::manchesterWagon(), straight());
  GuidedVehicleOde ode(m);
  // 3 free bodies x 10 + 16 series dampers: 8 primary vertical, 4 secondary vertical and 4
  // secondary lateral (Dsy with its series stiffness Ksy).
  EXPECT_EQ(ode.size(), 3 * 10 + 16);
  EXPECT_EQ(ode.componentName(0), "car.y");
  EXPECT_EQ(ode.componentName(4), "car.psi");
  EXPECT_EQ(ode.componentName(9), "bogie1.psi");
  EXPECT_EQ(ode.componentName(15), "car.y_dot");
  EXPECT_EQ(ode.componentName(29), "bogie2.psi_dot");
  EXPECT_EQ(ode.componentName(33), "series[3].f");
  EXPECT_EQ(ode.componentName(45), "series[15].f");
  EXPECT_EQ(ode.componentName(46), "y[46]");
  EXPECT_EQ(ode.index(m.findBody("bogie2"), kRoll), 12);
  EXPECT_EQ(ode.index(m.findBody("bogie2"), kRoll, true), 27);
  EXPECT_EQ(ode.index(m.findBody("ws1"), kY), -1);
  EXPECT_EQ(ode.indexOf("bogie1.z_dot"), 21);
  EXPECT_EQ(ode.indexOf("series[11].f"), 41);
  EXPECT_EQ(ode.indexOf("series[15].f"), 45);
  EXPECT_EQ(ode.indexOf("series[16].f"), -1);
  // Series dampers in file order: per bogie the 4 primary vertical ones, then per side the
  // secondary vertical and lateral ones.
  const std::vector<std::string> series_names = {
      "prim_z_ws1_l",   "prim_z_ws1_r",   "prim_z_ws2_l",   "prim_z_ws2_r",
      "sec_z_bogie1_l", "sec_y_bogie1_l", "sec_z_bogie1_r", "sec_y_bogie1_r",
      "prim_z_ws3_l",   "prim_z_ws3_r",   "prim_z_ws4_l",   "prim_z_ws4_r",
      "sec_z_bogie2_l", "sec_y_bogie2_l", "sec_z_bogie2_r", "sec_y_bogie2_r"};
  ASSERT_EQ(m.series_dampers.size(), series_names.size());
  for (std::size_t e = 0; e < series_names.size(); ++e) {
    EXPECT_EQ(m.series_dampers[e].g.name, series_names[e]) << e;
    EXPECT_EQ(m.findElement(series_names[e])->index, static_cast<int>(e));
  }
  EXPECT_EQ(m.series_dampers[5].g.direction, Direction::Y);
  EXPECT_EQ(m.series_dampers[5].stiffness, 0.0);  // no parallel spring
}

TEST(Validation, EveryProblemWithItsSourceLocation) {
  VehicleSpec v = rbtest::manchesterWagon();
  // Source locations of the blocks in scenarios/vehicles/manchester_wagon1.lua.
  const auto at = [](const auto& block) { return block.loc.str() + ": "; };
  ASSERT_NE(at(v.bodies[1]).find("manchester_wagon1.lua:"), std::string::npos);
  v.bodies[1].mass = -1.0;              // bogie1
  v.bodies[2].inertia[1] = 0.0;         // ws1
  v.bodies[3].name = "ws1";             // ws2 renamed: duplicate
  v.elements[0].body2 = "ws9";          // prim_z_ws1_l: unknown body
  v.elements[1].name = "prim_z_ws1_l";  // prim_x_ws1_l renamed: duplicate element name
  v.elements[2].damping = -5.0;         // prim_y_ws1_l
  v.elements[3].damping = 0.0;          // prim_z_ws1_r: series damper without damping
  auto& bump = v.elements.back();       // bump_y_bogie2
  bump.table_d.clear();
  bump.table_f.clear();
  for (ElementSpec& e : v.elements)
    if (e.kind == ElementKind::ShearSpring) {
      e.direction = Direction::Axial;  // first shear spring
      break;
    }
  v.elements[4].length0 = 0.3;  // prim_x_ws1_r: directional element with length0
  v.bodies[0].mass = 0.0;       // car
  const std::string msg = errorsOf(v);
  const auto has = [&](const std::string& s) {
    EXPECT_NE(msg.find(s), std::string::npos) << "missing: " << s << "\nin:\n" << msg;
  };
  has(at(v.bodies[0]) + "body 'car' (car): mass must be > 0 kg, got 0");
  has(at(v.bodies[1]) + "body 'bogie1' (bogie): mass must be > 0 kg, got -1");
  has(at(v.bodies[2]) + "body 'ws1' (wheelset): inertia must be > 0 kg m^2 in every axis");
  has(at(v.bodies[3]) + "body 'ws1' (wheelset): duplicate body name (also " +
      v.bodies[2].loc.str() + ")");
  has(at(v.elements[0]) +
      "element 'prim_z_ws1_l' (series_damper): unknown body 'ws9' in 'to' (bodies: car, bogie1, "
      "ws1, bogie2, ws3, ws4)");
  has(at(v.elements[1]) + "element 'prim_z_ws1_l' (spring_damper): duplicate element name (also " +
      v.elements[0].loc.str() + ")");
  has(at(v.elements[2]) +
      "element 'prim_y_ws1_l' (spring_damper): damping must be >= 0 N s/m, got -5");
  has(at(v.elements[3]) +
      "element 'prim_z_ws1_r' (series_damper): damping must be > 0 N s/m, got 0");
  has(at(bump) + "element 'bump_y_bogie2' (bumpstop): table is empty");
  has("(shear_spring): direction must be x, y or z");
  has(at(v.elements[4]) +
      "element 'prim_x_ws1_r' (spring_damper): length0 applies to axial elements only");
  // All in one exception, one per line.
  EXPECT_GE(std::count(msg.begin(), msg.end(), '\n'), 10);
}

TEST(Validation, AxialElementNeedsDistinctPoints) {
  VehicleSpec v = rbtest::manchesterWagon();
  v.elements[1].direction = Direction::Axial;  // prim_x_ws1_l: coincident points
  EXPECT_NE(errorsOf(v).find("an axial element needs distinct attachment points"),
            std::string::npos);
}

TEST(Validation, UnsupportedFreeBodyIsReportedByTheStaticSolver) {
  VehicleSpec v = rbtest::manchesterWagon();
  // Remove everything between the car and bogie 2: the car can still not fall (bogie 1), but its
  // pitch is free... remove all secondary elements instead: the car floats.
  std::erase_if(v.elements, [](const ElementSpec& e) { return e.body1 == "car"; });
  const VehicleModel m = compileVehicle(v, straight());
  GuidedVehicleOde ode(m);
  try {
    ode.initialState(0.0);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(v.loc.str() + ": vehicle 'manchester_wagon1': no static equilibrium"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("car.z"), std::string::npos) << msg;
  }
}

// ---- Lua vehicle files (scenarios/vehicles) through the scenario loader ----

TEST(LuaVehicles, ManchesterFileHasTheTable2And4Values) {
  // Every Manchester test takes the wagon from the Lua file (fixtures.hpp); spot checks of the
  // paper's Tables 2 and 4 and of the geometry guard the file itself.
  const scenario::ScenarioSpec s = rbtest::loadTestScenario("manchester_tangent.lua");
  ASSERT_TRUE(s.has_vehicle);
  const VehicleSpec& v = s.vehicle;
  EXPECT_EQ(v.name, "manchester_wagon1");
  EXPECT_DOUBLE_EQ(v.speed, 20.0);
  EXPECT_DOUBLE_EQ(v.start, 20.0);
  EXPECT_DOUBLE_EQ(v.wheel_radius, 0.46);
  ASSERT_EQ(v.bodies.size(), 7u);
  ASSERT_EQ(v.elements.size(), 50u);
  std::map<std::string, const BodySpec*> body;
  for (const BodySpec& b : v.bodies) body[b.name] = &b;
  std::map<std::string, const ElementSpec*> el;
  for (const ElementSpec& e : v.elements) el[e.name] = &e;
  ASSERT_TRUE(body.count("car") && body.count("bogie2") && body.count("ws4"));
  EXPECT_DOUBLE_EQ(body["car"]->mass, 32000.0);
  EXPECT_EQ(body["car"]->inertia, Eigen::Vector3d(56800, 1970000, 1970000));
  EXPECT_DOUBLE_EQ(body["car"]->height, 1.8);
  EXPECT_DOUBLE_EQ(body["bogie2"]->mass, 2615.0);
  EXPECT_DOUBLE_EQ(body["bogie2"]->x, -9.5);
  EXPECT_DOUBLE_EQ(body["ws4"]->mass, 1813.0);
  EXPECT_DOUBLE_EQ(body["ws4"]->x, -9.5 - 1.28);
  const auto check = [&](const std::string& name, ElementKind kind, Direction dir, double K,
                         double D, double Ks) {
    ASSERT_TRUE(el.count(name)) << name;
    const ElementSpec& e = *el[name];
    EXPECT_EQ(e.kind, kind) << name;
    EXPECT_EQ(e.direction, dir) << name;
    EXPECT_DOUBLE_EQ(e.stiffness, K) << name;
    EXPECT_DOUBLE_EQ(e.damping, D) << name;
    EXPECT_DOUBLE_EQ(e.series_stiffness, Ks) << name;
    EXPECT_DOUBLE_EQ(e.preload, 0.0) << name;
  };
  using K = ElementKind;
  check("prim_z_ws3_r", K::SeriesSpringDamper, Direction::Z, 1220e3, 4e3, 1000e3);
  check("prim_x_ws1_l", K::SpringDamper, Direction::X, 31391e3, 15e3, 0.0);
  check("prim_y_ws2_r", K::SpringDamper, Direction::Y, 3884e3, 2e3, 0.0);
  check("sec_z_bogie1_l", K::SeriesSpringDamper, Direction::Z, 430e3, 4e3, 1000e3);
  check("sec_shear_x_bogie2_r", K::ShearSpring, Direction::X, 160e3, 0.0, 0.0);
  check("sec_shear_y_bogie1_r", K::ShearSpring, Direction::Y, 160e3, 0.0, 0.0);
  check("sec_bend_bogie2_l", K::BendingSpring, Direction::Z, 10.5e3, 0.0, 0.0);
  // Ksy is the series stiffness of the lateral damper Dsy; no parallel spring (docs/vehicle.md).
  check("sec_y_bogie2_l", K::SeriesSpringDamper, Direction::Y, 0.0, 32e3, 6000e3);
  check("sec_x_bogie1", K::SpringDamper, Direction::X, 5000e3, 25e3, 0.0);
  // Anti-roll bar Kr 940 kN m/rad [MB], a bending spring about the longitudinal axis.
  check("anti_roll_bogie2", K::BendingSpring, Direction::X, 940e3, 0.0, 0.0);
  ASSERT_TRUE(el.count("bump_y_bogie2"));
  EXPECT_EQ(el["bump_y_bogie2"]->table_d.size(), 10u);
  EXPECT_DOUBLE_EQ(el["bump_y_bogie2"]->table_d[1], 0.025);
  EXPECT_DOUBLE_EQ(el["bump_y_bogie2"]->table_f.back(), 230000.0);
  // Attachment points: axle box of ws4 (rear axle of bogie 2) on the right, secondary spring of
  // bogie 1 on the left, bumpstop on the centre line.
  EXPECT_LT((el["prim_z_ws4_r"]->point1 - Eigen::Vector3d(-1.28, -1.0, 0.46 - 0.6)).norm(), 1e-12);
  EXPECT_LT((el["prim_z_ws4_r"]->point2 - Eigen::Vector3d(0.0, -1.0, 0.0)).norm(), 1e-12);
  EXPECT_LT((el["sec_y_bogie1_l"]->point1 - Eigen::Vector3d(9.5, 1.0, 0.8275 - 1.8)).norm(), 1e-12);
  EXPECT_LT((el["sec_y_bogie1_l"]->point2 - Eigen::Vector3d(0.0, 1.0, 0.8275 - 0.6)).norm(), 1e-12);
  EXPECT_LT((el["bump_y_bogie2"]->point1 - Eigen::Vector3d(-9.5, 0.0, 0.65 - 1.8)).norm(), 1e-12);
  // Source locations point into the vehicle file.
  EXPECT_NE(v.elements[0].loc.file.find("manchester_wagon1.lua"), std::string::npos);
  EXPECT_GT(v.elements[0].loc.line, 0);
  EXPECT_NO_THROW(compileVehicle(v, track::compileTrack(s.track)));
}

TEST(LuaVehicles, SingleWheelsetCarriesAQuarterOfTheWagon) {
  const scenario::ScenarioSpec s = rbtest::loadTestScenario("single_wheelset.lua");
  const track::TrackModel tm = track::compileTrack(s.track);
  const VehicleModel m = compileVehicle(s.vehicle, tm);
  EXPECT_DOUBLE_EQ(m.speed, 10.0);
  ASSERT_EQ(m.bodies.size(), 2u);
  EXPECT_EQ(m.bodies[0].kind, BodyKind::Frame);
  EXPECT_EQ(m.elementCount(), 8);
  GuidedVehicleOde ode(m);
  EXPECT_EQ(ode.size(), 2);  // the two primary vertical series damper forces
  const Eigen::VectorXd y = ode.initialState(0.0);
  // Everything kinematic: the axle boxes carry the preload only, (32000 + 2 x 2615) / 4 g.
  const BodyOutput ws = ode.bodyOutput(0.0, y.data(), m.findBody("ws"));
  EXPECT_NEAR(-ws.suspension_force.z(), (32000.0 + 2 * 2615.0) / 4 * 9.81, 1e-6);
  EXPECT_NEAR(ws.suspension_force.y(), 0.0, 1e-9);
}

}  // namespace
}  // namespace rb::vehicle
