// Particles joined by links, and the bottleneck search on them: the
// closure of the wall (post/closure.hpp) and of each gap between two pipes
// (post/gap_closure.hpp) add particles in the order of a field and ask
// when one linked component first holds both ends of a path.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "particles/vec.hpp"

namespace frostwall::post {

// Node i's links are link[start[i]] .. link[start[i + 1] - 1].
struct LinkGraph {
  std::vector<std::uint32_t> start{0};
  std::vector<std::uint32_t> link;

  std::size_t nodes() const { return start.size() - 1; }
  // Appends the next node and its links.
  void add_row(const std::vector<std::uint32_t>& row);
};

// Links among `nodes` nodes along the edges of the Delaunay triangulation
// of the points `where`, no longer than three local spacings (the larger
// of the two ends' spacing[node]), so none crosses a pipe hole. Point k
// stands for node source[k]: the first `nodes` points are the nodes
// themselves, those after them images of nodes. An edge between two
// images (a copy of one between their nodes) or from a node to itself is
// left out. Each row is sorted, without repeats.
LinkGraph delaunay_links(const std::vector<particles::Vec<2>>& where, const std::vector<std::uint32_t>& source,
                         std::size_t nodes, const std::vector<double>& spacing);

// Union-find on a link graph, its scratch kept between calls.
class ComponentJoin {
 public:
  // Adds the nodes in `order` one at a time, each joined to the linked
  // nodes added before it; a component carries the union of its nodes'
  // flag bits. The first node whose addition gives its component every bit
  // of `all`; none when no component ever holds them all.
  std::optional<std::uint32_t> first_holding(const LinkGraph& graph, const std::vector<std::uint32_t>& order,
                                             const std::vector<char>& flags, char all);

 private:
  std::vector<std::uint32_t> parent_;
  std::vector<char> added_, flags_;
};

}  // namespace frostwall::post
