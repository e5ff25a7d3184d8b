#include "workbench/train/train_ode.hpp"

#include <stdexcept>
#include <utility>

namespace rb::train {

TrainOde::TrainOde(std::vector<Part> parts, const std::vector<Connection>& connections)
    : parts_(std::move(parts)) {
  if (parts_.empty()) throw std::logic_error("TrainOde: a train needs a vehicle");
  // Buffers and couplers would add forces between the parts' bodies (and off-diagonal blocks to
  // the Jacobian pattern); until they are modelled a connection is refused, never ignored.
  if (!connections.empty())
    throw std::logic_error("TrainOde: connections between vehicles are not modelled");
  for (const auto& p : parts_) {
    offsets_.push_back(size_);
    size_ += p.ode->size();
  }
}

int TrainOde::rhs(double t, const double* y, double* ydot) {
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    const int rc = parts_[k].ode->rhs(t, y + offsets_[k], ydot + offsets_[k]);
    if (rc != 0) {
      failed_ = static_cast<int>(k);
      return rc;
    }
  }
  failed_ = -1;
  return 0;
}

integ::JacobianPattern TrainOde::jacobianPattern() const {
  if (parts_.size() == 1) return parts_.front().ode->jacobianPattern();
  integ::JacobianPattern out;
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    const integ::JacobianPattern p = parts_[k].ode->jacobianPattern();
    const int o = offsets_[k];
    const int n = parts_[k].ode->size();
    // A part without structure is a dense block of its own: still no entries across vehicles.
    for (int j = 0; j < n; ++j) {
      std::vector<int> rows;
      if (p.empty()) {
        for (int i = 0; i < n; ++i) rows.push_back(o + i);
      } else {
        for (const int i : p.rows[static_cast<std::size_t>(j)]) rows.push_back(o + i);
      }
      out.rows.push_back(std::move(rows));
    }
    for (int i = 0; i < n; ++i) {
      const int c = p.copy_of.empty() ? -1 : p.copy_of[static_cast<std::size_t>(i)];
      out.copy_of.push_back(c < 0 ? -1 : o + c);
    }
  }
  return out;
}

std::vector<int> TrainOde::stiffComponents() const {
  std::vector<int> out;
  for (std::size_t k = 0; k < parts_.size(); ++k)
    for (const int i : parts_[k].ode->stiffComponents()) out.push_back(offsets_[k] + i);
  return out;
}

std::string TrainOde::componentName(int i) const {
  std::size_t k = parts_.size() - 1;
  while (k > 0 && i < offsets_[k]) --k;
  const auto& p = parts_[k];
  const std::string local = p.ode->componentName(i - offsets_[k]);
  return p.name.empty() ? local : p.name + "." + local;
}

integ::ModelFailure TrainOde::lastFailure() const {
  if (failed_ < 0) return {};
  const auto& p = parts_[static_cast<std::size_t>(failed_)];
  integ::ModelFailure f = p.ode->lastFailure();
  if (!p.name.empty() && !f.body.empty()) f.body = p.name + "." + f.body;
  return f;
}

std::string TrainOde::lastError() const {
  if (failed_ < 0) return {};
  const auto& p = parts_[static_cast<std::size_t>(failed_)];
  const std::string e = p.ode->lastError();
  return p.name.empty() || e.empty() ? e : p.name + ": " + e;
}

}  // namespace rb::train
