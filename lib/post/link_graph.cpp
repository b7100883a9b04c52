#include "post/link_graph.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

#include "geometry/triangulation.hpp"

namespace frostwall::post {

void LinkGraph::add_row(const std::vector<std::uint32_t>& row) {
  link.insert(link.end(), row.begin(), row.end());
  start.push_back(static_cast<std::uint32_t>(link.size()));
}

LinkGraph delaunay_links(const std::vector<particles::Vec<2>>& where, const std::vector<std::uint32_t>& source,
                         std::size_t nodes, const std::vector<double>& spacing) {
  std::vector<std::vector<std::uint32_t>> near(nodes);
  for (const auto& [a, b] : geometry::delaunay_edges(where)) {
    if (a >= nodes && b >= nodes) continue;
    const std::uint32_t i = source[a], j = source[b];
    if (i == j) continue;
    if ((where[a] - where[b]).norm() > 3.0 * std::max(spacing[i], spacing[j])) continue;
    near[i].push_back(j);
    near[j].push_back(i);
  }
  LinkGraph graph;
  for (auto& row : near) {
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    graph.add_row(row);
  }
  return graph;
}

std::optional<std::uint32_t> ComponentJoin::first_holding(const LinkGraph& graph,
                                                          const std::vector<std::uint32_t>& order,
                                                          const std::vector<char>& flags, char all) {
  const std::size_t n = graph.nodes();
  parent_.resize(n);
  std::iota(parent_.begin(), parent_.end(), 0u);
  added_.assign(n, 0);
  flags_.assign(flags.begin(), flags.end());
  auto root = [&](std::uint32_t u) {
    while (parent_[u] != u) u = parent_[u] = parent_[parent_[u]];
    return u;
  };
  for (const std::uint32_t u : order) {
    added_[u] = 1;
    // u is new, so its own root until it takes the components it links to.
    for (std::uint32_t e = graph.start[u]; e < graph.start[u + 1]; ++e) {
      const std::uint32_t v = graph.link[e];
      if (!added_[v]) continue;
      const std::uint32_t rv = root(v);
      if (rv == u) continue;
      parent_[rv] = u;
      flags_[u] |= flags_[rv];
    }
    if ((flags_[u] & all) == all) return u;
  }
  return std::nullopt;
}

}  // namespace frostwall::post
