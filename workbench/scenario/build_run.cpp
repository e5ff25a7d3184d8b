#include <cmath>

#include "workbench/core/strings.hpp"
#include "workbench/scenario/build.hpp"
#include "workbench/scenario/reader.hpp"

namespace rb::scenario {
namespace {

// run.assessment.floor_positions: a list of finite numbers [m].
std::vector<double> floorPositions(Reader& r) {
  std::vector<double> out;
  const Node* v = r.value("floor_positions");
  if (!v) return out;
  if (v->type != Node::Type::Table || !v->fields.empty() || v->items.empty()) {
    r.error(*v, "floor_positions must be a non-empty list of numbers {x1, x2, ...} [m], got " +
                    v->describe());
    return out;
  }
  for (std::size_t i = 0; i < v->items.size(); ++i) {
    const Node& item = v->items[i];
    if (item.type != Node::Type::Number || !std::isfinite(item.number)) {
      r.error(item, "floor_positions[" + std::to_string(i + 1) +
                        "] must be a finite number [m], got " + item.describe());
      continue;
    }
    out.push_back(item.number);
  }
  return out;
}

void buildAssessment(const Node& n, assessment::AssessmentSpec& a, Diagnostics& d) {
  Reader r(n, block("run.assessment"), "run.assessment", d);
  a.loc = n.loc;
  a.safety = r.boolean("safety");
  a.stability = r.boolean("stability");
  a.comfort = r.boolean("comfort");
  a.wear = r.boolean("wear");
  a.sample_every = r.number("sample_every");
  a.floor_positions = floorPositions(r);
  a.alpha = r.number("alpha");
  a.flange_angle = r.number("flange_angle");
  a.mu = r.number("mu");
  if (r.has("mu") && a.mu <= 0) r.error(n, "mu must be > 0 (omit it to use contact.mu)");
  a.yq_limit = r.number("yq_limit");
  a.instability_frequency = r.number("instability_frequency");
  if (r.has("instability_frequency") && a.instability_frequency <= 2.0)
    r.error(n, "instability_frequency must be > 2 Hz (the band-pass is f0 +- 2 Hz), got " +
                   formatNumber(a.instability_frequency));
  a.comfort_limit = r.number("comfort_limit");
}

}  // namespace

void buildRun(const Node& n, RunSpec& run, Diagnostics& d) {
  Reader r(n, block("run"), "run", d);
  run.loc = n.loc;
  run.distance = r.number("distance");
  run.duration = r.number("duration");
  if (r.has("distance") && r.has("duration"))
    r.error(n, "give either distance or duration, not both");
  if (const Node* out = r.blockValue("output")) {
    Reader o(*out, block("run.output"), "run.output", d);
    run.output_every = o.number("every");
    if (o.has("elements")) run.output_elements = o.names("elements");
    run.body_accelerations = o.boolean("body_accelerations");
    run.max_output_samples = o.number("max_samples");
    run.output_patches = o.boolean("patches");
  }
  if (const Node* e = r.blockValue("effects")) buildEffects(*e, run.effects, d);
  // run.assessment = true asks for every group that applies to the vehicle (the run drops the
  // groups it cannot compute and says so); a table asks for what it names.
  const Node* a = r.value("assessment");
  if (a && a->type == Node::Type::Bool) {
    auto& s = run.assessment;
    s.loc = a->loc;
    s.safety = s.stability = s.comfort = s.wear = a->boolean;
    s.all = a->boolean;
  } else if (const Node* t = r.blockValue("assessment")) {
    buildAssessment(*t, run.assessment, d);
  }
}

}  // namespace rb::scenario
