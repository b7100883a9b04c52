// The CGAL Delaunay triangulation frostwall uses, with a particle index
// stored at each vertex (Voronoi volumes, front curves).
#pragma once

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <cstddef>

namespace frostwall::geometry {

using Kernel2 = CGAL::Exact_predicates_inexact_constructions_kernel;
using IndexedDelaunay = CGAL::Delaunay_triangulation_2<
    Kernel2, CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Kernel2>>>;

}  // namespace frostwall::geometry
