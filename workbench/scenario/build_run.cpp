#include <algorithm>
#include <cmath>
#include <optional>

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

// One entry of run.assessment.sections, { name = "...", from = s0, to = s1 } with finite
// 0 <= from < to [m] and a name that is an HDF5 group name (letters, digits, '_', '-'); nullopt
// after reporting what is wrong.
std::optional<assessment::SectionSpec> section(Reader& r, const Node& item,
                                               const std::string& what) {
  if (item.type != Node::Type::Table || !item.items.empty()) {
    r.error(item, what + " must be a table { name = \"...\", from = s0, to = s1 }, got " +
                      item.describe());
    return std::nullopt;
  }
  assessment::SectionSpec sec;
  sec.loc = item.loc;
  bool ok = true;
  for (const auto& [key, value] : item.fields) {
    const bool range = key == "from" || key == "to";
    if (key == "name" && value.type == Node::Type::String) {
      sec.name = value.string;
    } else if (range && value.type == Node::Type::Number && std::isfinite(value.number)) {
      (key == "from" ? sec.from : sec.to) = value.number;
    } else {
      const char* why = key == "name" ? " must be a string"
                        : range       ? " must be a finite number [m]"
                                      : " is not a key (name, from, to)";
      r.error(value, what + "." + key + why + ", got " + value.describe());
      ok = false;
    }
  }
  if (!ok) return std::nullopt;
  if (!item.field("name") || !item.field("from") || !item.field("to")) {
    r.error(item, what + " needs name, from and to");
    return std::nullopt;
  }
  if (!assessment::validSectionName(sec.name)) {
    r.error(*item.field("name"),
            what + ".name '" + sec.name + "' must be 1-64 letters, digits, '_' or '-'");
    return std::nullopt;
  }
  if (!(sec.from >= 0.0 && sec.from < sec.to)) {
    r.error(item, what + " needs 0 <= from < to, got from = " + formatNumber(sec.from) +
                      " m, to = " + formatNumber(sec.to) + " m");
    return std::nullopt;
  }
  return sec;
}

// run.assessment.sections: a list of sections with distinct names.
std::vector<assessment::SectionSpec> sections(Reader& r) {
  std::vector<assessment::SectionSpec> out;
  const Node* v = r.value("sections");
  if (!v) return out;
  if (v->type != Node::Type::Table || !v->fields.empty() || v->items.empty()) {
    r.error(*v,
            "sections must be a non-empty list { { name = \"...\", from = s0, to = s1 }, "
            "... } [m], got " +
                v->describe());
    return out;
  }
  if (v->items.size() > assessment::kMaxSections) {
    r.error(*v, "sections: at most " + std::to_string(assessment::kMaxSections) +
                    " sections, got " + std::to_string(v->items.size()));
    return out;
  }
  for (std::size_t i = 0; i < v->items.size(); ++i) {
    const std::string what = "sections[" + std::to_string(i + 1) + "]";
    auto sec = section(r, v->items[i], what);
    if (!sec) continue;
    const bool twice = std::any_of(out.begin(), out.end(),
                                   [&](const auto& other) { return other.name == sec->name; });
    if (twice)
      r.error(v->items[i], what + ".name '" + sec->name + "' is given twice");
    else
      out.push_back(std::move(*sec));
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
  if (const Node* every = r.value("sample_every")) a.sample_every_loc = every->loc;
  a.floor_positions = floorPositions(r);
  a.alpha = r.number("alpha");
  a.sections = sections(r);
  a.flange_angle = r.number("flange_angle");
  a.mu = r.number("mu");
  a.yq_limit = r.number("yq_limit");
  a.instability_frequency = r.number("instability_frequency");
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
    if (const Node* every = o.value("every")) run.output_every_loc = every->loc;
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
