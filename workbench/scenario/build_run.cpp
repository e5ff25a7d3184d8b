#include "workbench/scenario/build.hpp"
#include "workbench/scenario/reader.hpp"

namespace rb::scenario {

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
  }
}

}  // namespace rb::scenario
