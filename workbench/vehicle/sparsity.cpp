#include "workbench/vehicle/sparsity.hpp"

#include <vector>

namespace rb::vehicle {
namespace {

// The states of body b (positions and rates) and its acceleration rows (the rate states).
struct BodyStates {
  std::vector<int> states;
  std::vector<int> accelerations;
};

BodyStates bodyStates(const VehicleLayout& l, std::size_t b) {
  BodyStates out;
  if (const int k = l.freeSlot(b); k >= 0) {
    for (int c = 0; c < kFreeBodyDof; ++c) {
      out.states.push_back(l.position(k, c));
      out.states.push_back(l.rate(k, c));
      out.accelerations.push_back(l.rate(k, c));
    }
  } else if (const int w = l.wheelsetSlot(b); w >= 0) {
    for (int c = 0; c < kWheelsetCoordinates; ++c) {
      if (l.wsPosition(w, c) >= 0) out.states.push_back(l.wsPosition(w, c));
      if (l.wsRate(w, c) >= 0) {
        out.states.push_back(l.wsRate(w, c));
        out.accelerations.push_back(l.wsRate(w, c));
      }
    }
    // The rail masses under its wheels (the track under the rail) move with its contact forces.
    if (w < l.rail_masses)
      for (int side = 0; side < 2; ++side)
        for (int c = 0; c < 2; ++c) {
          out.states.push_back(l.railPosition(w, side, c));
          out.states.push_back(l.railRate(w, side, c));
          out.accelerations.push_back(l.railRate(w, side, c));
        }
  }
  return out;
}

class DependencyMatrix {
 public:
  explicit DependencyMatrix(int n) : n_(static_cast<std::size_t>(n)), depends_(n_ * n_, false) {}
  void mark(int row, int column) {
    depends_[static_cast<std::size_t>(column) * n_ + static_cast<std::size_t>(row)] = true;
  }
  void mark(const std::vector<int>& rows, const std::vector<int>& columns) {
    for (const int i : rows)
      for (const int j : columns) mark(i, j);
  }
  std::vector<std::vector<int>> rowsOfColumns() const {
    std::vector<std::vector<int>> rows(n_);
    for (std::size_t j = 0; j < n_; ++j)
      for (std::size_t i = 0; i < n_; ++i)
        if (depends_[j * n_ + i]) rows[j].push_back(static_cast<int>(i));
    return rows;
  }

 private:
  std::size_t n_;
  std::vector<bool> depends_;  // column-major
};

}  // namespace

integ::JacobianPattern jacobianPattern(const VehicleModel& model, const VehicleLayout& layout) {
  const int n = layout.size;
  DependencyMatrix dep(n);
  std::vector<BodyStates> bodies;
  bodies.reserve(model.bodies.size());
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    bodies.push_back(bodyStates(layout, b));
    dep.mark(bodies.back().accelerations, bodies.back().states);
  }
  for (const ElementId id : model.elements()) {
    const ElementGeometry& g = model.element(id);
    const BodyStates& b1 = bodies[static_cast<std::size_t>(g.body1)];
    const BodyStates& b2 = bodies[static_cast<std::size_t>(g.body2)];
    dep.mark(b1.accelerations, b2.states);
    dep.mark(b2.accelerations, b1.states);
    if (id.kind != ElementKind::SeriesSpringDamper) continue;
    const std::vector<int> force{layout.series(id.index)};
    dep.mark(force, force);
    for (const BodyStates* b : {&b1, &b2}) {
      dep.mark(b->accelerations, force);
      dep.mark(force, b->states);
    }
  }
  integ::JacobianPattern out;
  out.copy_of.assign(static_cast<std::size_t>(n), -1);
  const auto copy = [&](int p, int k) {
    if (p < 0 || k < 0) return;
    out.copy_of[static_cast<std::size_t>(p)] = k;
    dep.mark(p, k);
  };
  for (int k = 0; k < layout.n_free; ++k)
    for (int c = 0; c < kFreeBodyDof; ++c) copy(layout.position(k, c), layout.rate(k, c));
  for (int w = 0; w < layout.n_ws; ++w)
    for (int c = 0; c < kWheelsetCoordinates; ++c)
      copy(layout.wsPosition(w, c), layout.wsRate(w, c));
  for (int w = 0; w < layout.rail_masses; ++w)
    for (int side = 0; side < 2; ++side)
      for (int c = 0; c < 2; ++c)
        copy(layout.railPosition(w, side, c), layout.railRate(w, side, c));
  out.rows = dep.rowsOfColumns();
  return out;
}

}  // namespace rb::vehicle
