// Reading back what a run left in its output directory: summary.json, the
// project file as given (project.json), the CSV series and the VTK
// snapshots and front curves. The report is built from these files alone,
// so `frostwall report <dir>` rebuilds it without running anything.
#pragma once

#include <array>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "io/csv_table.hpp"
#include "post/isoline.hpp"
#include "particles/vec.hpp"

namespace frostwall::report {

// The run's CSV tables (io/csv_table.hpp).
using io::CsvTable;
using io::read_csv;

// The particles of a field_XXXX.vtu snapshot and the fields the report uses.
struct FieldSnapshot {
  std::vector<particles::Vec<2>> position;
  std::vector<double> volume;
  std::vector<int> boundary;  // -1 free
  std::vector<double> temperature;
  std::vector<particles::Vec<2>> darcy_flux;  // m/s; empty without groundwater
};
FieldSnapshot read_field(const std::filesystem::path& file);

// The solid of a PD run's snapshot: its free particles (boundary -1) with
// |displacement| (m) and damage; empty when the file has no displacement.
// Also the temperature (degC) and, for a porous plate, the material of
// each particle (0 matrix, 1 pore water, 2 pore ice); each empty when the
// file lacks it.
struct SolidSnapshot {
  FieldSnapshot particles;  // temperature holds |displacement|
  std::vector<double> damage;
  std::vector<double> temperature;
  std::vector<int> material;
};
SolidSnapshot read_solid(const std::filesystem::path& file);

// The grains of a CFD-DEM snapshot (grains_XXXX.vtu): centres, diameters
// and |displacement| since the run started (empty when the file has none).
struct GrainSnapshot {
  std::vector<std::array<double, 3>> position;
  std::vector<double> diameter, displacement;
};
GrainSnapshot read_grains(const std::filesystem::path& file);

// The polylines of an interface_XXXX.vtp file (closed ones repeat their first point).
std::vector<post::Polyline> read_polylines(const std::filesystem::path& file);

// The snapshots a .pvd collection lists, in its order: time (the
// project's time unit) and file; empty when there is no such file.
struct PvdEntry {
  double time = 0.0;
  std::string file;
};
std::vector<PvdEntry> read_pvd(const std::filesystem::path& file);

nlohmann::json read_json(const std::filesystem::path& file);
std::optional<std::string> read_text(const std::filesystem::path& file);

}  // namespace frostwall::report
