// open_in_paraview.py: a ParaView Python script that every run writes
// beside its files. It loads the run's time series with frostwall's colour
// maps: temperature diverging at the freezing point, the frozen front (the
// 0.5 liquid-fraction contour) as black lines, the design isotherm as a
// magenta contour, grains as spheres of their radius coloured by their
// displacement. Run it with `paraview --script=open_in_paraview.py` or
// `pvpython open_in_paraview.py --png` (which saves open_in_paraview.png).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace frostwall::io {

struct ParaviewSeries {
  enum class Kind { temperature, grains, fluid };
  std::string pvd;  // relative to the script, e.g. "ring.pvd"; or a multiblock "shaft.vtm" (a 3-D view)
  Kind kind = Kind::temperature;
  bool visible = true;  // shown when the script opens; the rest are in the pipeline, hidden
};

struct ParaviewScene {
  std::string title;  // the project's name
  std::vector<ParaviewSeries> series;
  double freezing_point = 0.0;          // degC: the white of the temperature map
  double coldest = 0.0, warmest = 0.0;  // degC: what the boundaries and the start span
  std::optional<double> isotherm;       // degC: the design isotherm
  bool solid = false;                   // the temperature files carry displacement and damage
};

// Writes the script (atomically); throws std::invalid_argument on a scene
// without series.
void write_paraview_script(const std::filesystem::path& file, const ParaviewScene& scene);

}  // namespace frostwall::io
