#include "workbench/vehicle/stage_clock.hpp"

#include <chrono>
#include <limits>

namespace rb::vehicle {
namespace {

std::int64_t nowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// The countdown of a clock that never times (period 0): it returns to this value at every wrap.
constexpr unsigned kNever = std::numeric_limits<unsigned>::max();

}  // namespace

void StageClock::setPeriod(unsigned period) {
  period_ = period;
  countdown_ = period == 0 ? kNever : (period + 1) / 2;
  evaluations_ = samples_ = rejected_ = 0;
  kept_ns_ = 0;
  ns_.fill(0);
}

void StageClock::use(std::initializer_list<Stage> stages) {
  for (const Stage s : stages) used_ |= bit(s);
}

bool StageClock::begin() {
  if (period_ == 0) {
    countdown_ = kNever;
    return false;
  }
  countdown_ = period_;
  pending_.fill(0);
  begin_ns_ = last_ns_ = nowNs();
  return true;
}

void StageClock::mark(Stage s) {
  const std::int64_t now = nowNs();
  pending_[static_cast<std::size_t>(s)] += now - last_ns_;
  last_ns_ = now;
}

void StageClock::finish() {
  const std::int64_t took = last_ns_ - begin_ns_;
  if (samples_ > 0 && took > kOutlierFactor * kept_ns_ / samples_) {
    ++rejected_;
    return;
  }
  ++samples_;
  kept_ns_ += took;
  for (std::size_t i = 0; i < kStageCount; ++i) ns_[i] += pending_[i];
}

}  // namespace rb::vehicle
