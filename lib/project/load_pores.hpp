// Readers of a porous plate (frost damage): geometry.pores, listed or drawn
// by a generator, and the "pore_fluid" that fills them. Internal to
// lib/project (load_project.cpp calls them); problems go to the Node.
#pragma once

#include <vector>

#include "project/json_reader.hpp"
#include "project/project.hpp"

namespace frostwall::project::detail {

// Reads geometry.pores into rectangle.pores, and rectangle.pore_generator
// when they are drawn; checks that each pore lies inside the plate and
// that no two listed pores overlap. Needs the rectangle's width and height
// (read first; the checks against the plate are skipped when one is bad).
// plate_saturation: geometry.saturation, every pore's unless it gives its own.
void read_pores(const Node& n, Rectangle& rectangle, const Node& plate_saturation);

// Random sequential addition, the same on every platform for a seed
// (std::mt19937_64, its raw output turned into [0, 1) here): each pore
// draws its radius, then up to 10000 centres; a centre is taken when the
// disc keeps min_gap from every side and from every pore placed so far.
// Returns the pores placed: fewer than g.count when one could not be.
std::vector<Pore> draw_pores(const PoreGenerator& g, double width, double height);

PoreFluid read_pore_fluid(const Node& n);

// After geometry and mechanics: reads "pore_fluid" (a warning without
// pores), sets mechanics.freezing_expansion to its default when the plate
// has pores and refuses one given without pores.
void read_pore_settings(const Node& root, Project& project);

}  // namespace frostwall::project::detail
