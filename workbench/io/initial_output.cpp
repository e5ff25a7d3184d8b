#include "workbench/io/initial_output.hpp"

#include <cstdint>

namespace rb::io {

std::vector<SchemaEntry> writeInitialConditions(ResultFile& f, const InitialConditionsRecord& r,
                                                const std::string& g) {
  f.attr(g, "count", static_cast<std::int64_t>(r.value.size()));
  f.attr(g, "description",
         std::string("vehicle.initial: offsets of body coordinates (track frame), held while "
                     "the rest of the static equilibrium settles around them, then rates added; "
                     "state is the first output sample"));
  f.stringDataset(g + "/body", r.body);
  f.stringDataset(g + "/key", r.key);
  f.dataset(g + "/value", r.value, "SI (per entry: unit)");
  f.stringDataset(g + "/unit", r.unit);
  f.stringDataset(g + "/state_names", r.state_names);
  f.dataset(g + "/equilibrium", r.equilibrium, "SI (per component: m, rad, m/s, rad/s, N)");
  f.dataset(g + "/state", r.state, "SI (per component: m, rad, m/s, rad/s, N)");
  return {
      {g + "/body", "-", "body of each given condition", ""},
      {g + "/key", "-", "coordinate or rate of each given condition (y, yaw_dot, ...)", ""},
      {g + "/value", "SI (per entry: unit)", "offset of each given condition", ""},
      {g + "/unit", "-", "unit of each given condition's value", ""},
      {g + "/state_names", "-", "name of every state component (car.y, ws1.psi_dot, ...)", ""},
      {g + "/equilibrium", "SI (per component: m, rad, m/s, rad/s, N)",
       "the static-equilibrium state the conditions offset", ""},
      {g + "/state", "SI (per component: m, rad, m/s, rad/s, N)",
       "the state the run starts from: the offsets held, the rest settled, the rates added", ""}};
}

}  // namespace rb::io
