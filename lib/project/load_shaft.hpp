// Readers of the shaft section's blocks: the layout, the freeze pipe (fixed
// wall or brine) and the layers of the ground. Internal to lib/project;
// problems go to the Node.
#pragma once

#include <string>
#include <vector>

#include "project/json_reader.hpp"
#include "project/load_basics.hpp"
#include "project/project.hpp"

namespace frostwall::project::detail {

// "layout": single, three-hole, four-hole, rings or measured pipes.
Layout read_layout(const Node& n);
// Distance of the farthest pipe centre from the shaft axis.
double outermost_pipe_radius(const Layout& layout);

// "pipe": {"diameter", "temperature", "model"} with the wall held at the
// temperature, or {"boundary": "brine", "brine_temperature",
// "heat_transfer_coefficient"} with brine behind a film. A pipe (or brine)
// warmer than the soil's freezing point is computable but freezes nothing:
// a warning, not an error. With a plant (`plant`), brine behind a film that
// the plant's circuit sets (the coaxial keys are read by read_plant).
Pipe read_pipe(const Node& n, bool plant);
void warn_warm_pipe(const Node& pipe, const Pipe& read, double freezing_point, std::vector<std::string>& warnings);

// "layers": [{"name", "depth", "soil", "pressure", "strength"}, ...]; soil,
// pressure and strength default to the project's ("pressure" then taken at
// the layer's depth). The design must be a strength check.
std::vector<Layer> read_layers(const Node& layers, const Node& root, const Project& project);

}  // namespace frostwall::project::detail
