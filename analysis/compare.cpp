// Contact-graph comparison. The points propose the vertex matching (one near-neighbour pass per
// symmetry), which is then checked bond by bond; VF2 runs only when no symmetry's point matching
// is a graph isomorphism, and then on colour-refined vertex classes so that symmetric graphs
// (Delta(k), 4Delta(k)) do not send it into its exponential worst case.
#include "analysis/compare.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/vf2_sub_graph_iso.hpp>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "core/neighbours.hpp"

namespace tripack {

namespace {

// A pattern with its rattlers removed: the vertices of its contact graph are the non-rattlers
// (0..m-1, in the order of `disks`) and the three walls (m + side).
struct Reduced {
  std::vector<int> disks;      // original index of vertex v < m
  std::vector<int> vertex_of;  // original index -> vertex, -1 for rattlers
  std::vector<Bond> bonds;     // bonds among non-rattlers, original indices, sorted
  std::array<int, 3> wall_count{0, 0, 0};
  std::size_t m() const { return disks.size(); }
};

Reduced reduce(const Pattern& p) {
  const int n = static_cast<int>(p.packing.size());
  std::vector<char> rattler(static_cast<std::size_t>(n), 0);
  for (int r : p.rattlers) {
    if (r < 0 || r >= n) throw std::invalid_argument("compare: rattler index out of range");
    rattler[r] = 1;
  }
  Reduced red;
  std::vector<int> degree(static_cast<std::size_t>(n), 0);
  for (const Bond& bond : p.bonds) {
    if (bond.a < 0 || bond.a >= n || bond.b >= n || (bond.is_wall() && bond.b < -3)) {
      throw std::invalid_argument("compare: bond index out of range");
    }
    if (rattler[bond.a] || (!bond.is_wall() && rattler[bond.b])) continue;
    red.bonds.push_back(bond.is_wall() ? bond : Bond::pair(bond.a, bond.b));
    ++degree[bond.a];
    if (!bond.is_wall()) ++degree[bond.b];
  }
  std::sort(red.bonds.begin(), red.bonds.end());
  red.bonds.erase(std::unique(red.bonds.begin(), red.bonds.end()), red.bonds.end());
  red.vertex_of.assign(static_cast<std::size_t>(n), -1);
  for (int i = 0; i < n; ++i) {
    // A disk without bonds is a rattler whatever the list says: it is not in the graph.
    if (rattler[i] || degree[i] == 0) continue;
    red.vertex_of[i] = static_cast<int>(red.disks.size());
    red.disks.push_back(i);
  }
  for (const Bond& bond : red.bonds) {
    if (bond.is_wall()) ++red.wall_count[static_cast<int>(bond.side())];
  }
  return red;
}

// Adjacency lists of the contact graph (walls at m + side).
std::vector<std::vector<int>> adjacency(const Reduced& red) {
  const int m = static_cast<int>(red.m());
  std::vector<std::vector<int>> adj(red.m() + 3);
  for (const Bond& bond : red.bonds) {
    const int u = red.vertex_of[bond.a];
    const int v = bond.is_wall() ? m + static_cast<int>(bond.side()) : red.vertex_of[bond.b];
    adj[u].push_back(v);
    adj[v].push_back(u);
  }
  return adj;
}

// The cheap invariants; returns why the graphs cannot be isomorphic, or "" when they may be.
std::string quick_graph_rejection(const Reduced& a, const Reduced& b) {
  if (a.m() != b.m()) return fmt::format("{} vs {} non-rattlers", a.m(), b.m());
  if (a.bonds.size() != b.bonds.size()) {
    return fmt::format("{} vs {} bonds", a.bonds.size(), b.bonds.size());
  }
  auto walls_a = a.wall_count, walls_b = b.wall_count;
  std::sort(walls_a.begin(), walls_a.end());
  std::sort(walls_b.begin(), walls_b.end());
  if (walls_a != walls_b) return "wall bond counts differ";
  auto degrees = [](const Reduced& r) {
    std::vector<int> deg(r.m(), 0);
    for (const Bond& bond : r.bonds) {
      ++deg[r.vertex_of[bond.a]];
      if (!bond.is_wall()) ++deg[r.vertex_of[bond.b]];
    }
    std::sort(deg.begin(), deg.end());
    return deg;
  };
  if (degrees(a) != degrees(b)) return "degree sequences differ";
  return "";
}

// A vertex matching proposed by the points of g(a) and b: each non-rattler of a goes to the
// nearest non-rattler of b within `radius`. With radius < d/2 the nearest is the only candidate.
struct PointMatch {
  std::vector<int> phi;  // vertex of a -> vertex of b
  long double max_distance = 0;
};

std::optional<PointMatch> match_points(const Pattern& pa, const Reduced& a, const Pattern& pb,
                                       const Reduced& b, Symmetry g, long double radius) {
  const std::size_t m = a.m();
  if (m != b.m()) return std::nullopt;
  std::vector<Vec2L> pts;
  pts.reserve(2 * m);
  for (int i : a.disks) pts.push_back(apply(g, pa.packing.points[i]));
  for (int j : b.disks) pts.push_back(pb.packing.points[j]);
  PointMatch match;
  match.phi.assign(m, -1);
  std::vector<long double> best(m, std::numeric_limits<long double>::infinity());
  const int mi = static_cast<int>(m);
  for_each_pair_within(pts, radius, [&](int i, int j, long double dist) {
    // Pairs come with i < j, so a cross pair has i in a and j in b.
    if (i < mi && j >= mi && dist < best[i]) {
      best[i] = dist;
      match.phi[i] = j - mi;
    }
  });
  std::vector<char> used(m, 0);
  for (std::size_t i = 0; i < m; ++i) {
    if (match.phi[i] < 0 || used[match.phi[i]]) return std::nullopt;
    used[match.phi[i]] = 1;
    match.max_distance = std::max(match.max_distance, best[i]);
  }
  return match;
}

// Whether phi (with walls permuted by g) maps every bond of a onto a bond of b. The bond counts
// are equal and phi is injective, so this makes it a bijection of the bond sets.
bool maps_bonds(const Reduced& a, const Reduced& b, const std::vector<int>& phi, Symmetry g) {
  for (const Bond& bond : a.bonds) {
    const int u = b.disks[phi[a.vertex_of[bond.a]]];
    const Bond image = bond.is_wall() ? Bond::wall(u, apply(g, bond.side()))
                                      : Bond::pair(u, b.disks[phi[a.vertex_of[bond.b]]]);
    if (!std::binary_search(b.bonds.begin(), b.bonds.end(), image)) return false;
  }
  return true;
}

// Joint colour refinement (1-dimensional Weisfeiler-Leman) of both graphs: disks start with one
// colour and walls with another (any side permutation is a symmetry). Returns false as soon as
// the colour histograms differ, which proves the graphs non-isomorphic.
bool refine_colours(const std::vector<std::vector<int>>& adj_a,
                    const std::vector<std::vector<int>>& adj_b, int m, std::vector<int>& col_a,
                    std::vector<int>& col_b) {
  const std::size_t V = adj_a.size();
  col_a.assign(V, 0);
  col_b.assign(V, 0);
  for (std::size_t v = static_cast<std::size_t>(m); v < V; ++v) col_a[v] = col_b[v] = 1;
  std::size_t classes = 2;
  for (;;) {
    std::map<std::vector<int>, int> ids;
    auto step = [&](const std::vector<std::vector<int>>& adj, const std::vector<int>& col) {
      std::vector<int> next(V);
      std::vector<int> signature;
      for (std::size_t v = 0; v < V; ++v) {
        signature.assign(1, col[v]);
        for (int w : adj[v]) signature.push_back(col[w]);
        std::sort(signature.begin() + 1, signature.end());
        next[v] = ids.emplace(signature, static_cast<int>(ids.size())).first->second;
      }
      return next;
    };
    std::vector<int> next_a = step(adj_a, col_a), next_b = step(adj_b, col_b);
    std::vector<int> hist_a(ids.size(), 0), hist_b(ids.size(), 0);
    for (std::size_t v = 0; v < V; ++v) {
      ++hist_a[next_a[v]];
      ++hist_b[next_b[v]];
    }
    if (hist_a != hist_b) return false;
    col_a = std::move(next_a);
    col_b = std::move(next_b);
    if (ids.size() == classes) return true;  // stable partition
    classes = ids.size();
  }
}

std::uint64_t fnv1a(std::uint64_t hash, std::uint64_t value) {
  for (int byte = 0; byte < 8; ++byte) {
    hash ^= (value >> (8 * byte)) & 0xff;
    hash *= 1099511628211ULL;
  }
  return hash;
}

}  // namespace

std::string contact_graph_hash(const Pattern& pattern) {
  const std::size_t n = pattern.packing.size();
  std::vector<char> held(n, 0);
  for (const auto& b : pattern.bonds) {
    held[static_cast<std::size_t>(b.a)] = 1;
    if (!b.is_wall()) held[static_cast<std::size_t>(b.b)] = 1;
  }
  for (int r : pattern.rattlers) held[static_cast<std::size_t>(r)] = 0;
  // Vertices: disks 0..n-1 (rattlers isolated and left out of the colours), walls n..n+2.
  std::vector<std::vector<int>> adj(n + 3);
  for (const auto& b : pattern.bonds) {
    if (!held[static_cast<std::size_t>(b.a)] ||
        (!b.is_wall() && !held[static_cast<std::size_t>(b.b)]))
      continue;
    const int other = b.is_wall() ? static_cast<int>(n) + static_cast<int>(b.side()) : b.b;
    adj[static_cast<std::size_t>(b.a)].push_back(other);
    adj[static_cast<std::size_t>(other)].push_back(b.a);
  }
  std::vector<std::size_t> vertices;
  for (std::size_t v = 0; v < n + 3; ++v)
    if (v >= n || held[v]) vertices.push_back(v);
  std::vector<std::uint64_t> colour(n + 3, 1);
  for (std::size_t v = n; v < n + 3; ++v) colour[v] = 2;
  auto distinct = [&] {
    std::vector<std::uint64_t> c;
    for (std::size_t v : vertices) c.push_back(colour[v]);
    std::sort(c.begin(), c.end());
    return c;
  };
  std::vector<std::uint64_t> sorted = distinct();
  std::size_t classes = 2, rounds = 0;
  for (; rounds <= vertices.size(); ++rounds) {
    std::vector<std::uint64_t> next(n + 3, 0), neighbours;
    for (std::size_t v : vertices) {
      neighbours.clear();
      for (int w : adj[v]) neighbours.push_back(colour[static_cast<std::size_t>(w)]);
      std::sort(neighbours.begin(), neighbours.end());
      std::uint64_t h = fnv1a(14695981039346656037ULL, colour[v]);
      for (auto c : neighbours) h = fnv1a(h, c);
      next[v] = h;
    }
    colour = std::move(next);
    sorted = distinct();
    const auto count =
        static_cast<std::size_t>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
    sorted = distinct();
    if (count == classes) break;  // stable partition
    classes = count;
  }
  std::uint64_t h = fnv1a(14695981039346656037ULL, vertices.size());
  for (auto c : sorted) h = fnv1a(h, c);
  return fmt::format("{:016x}", h);
}

namespace {

// VF2 on the colour-refined graphs. Returns the symmetry whose side permutation the found
// isomorphism applies to the walls, or nullopt when the graphs are not isomorphic.
std::optional<Symmetry> vf2_isomorphism(const Reduced& a, const Reduced& b, bool& refuted) {
  const int m = static_cast<int>(a.m());
  const auto adj_a = adjacency(a), adj_b = adjacency(b);
  std::vector<int> col_a, col_b;
  refuted = !refine_colours(adj_a, adj_b, m, col_a, col_b);
  if (refuted) return std::nullopt;

  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
  const auto V = adj_a.size();
  Graph ga(V), gb(V);
  for (std::size_t u = 0; u < V; ++u) {
    for (int v : adj_a[u]) {
      if (static_cast<std::size_t>(v) > u) boost::add_edge(u, static_cast<std::size_t>(v), ga);
    }
    for (int v : adj_b[u]) {
      if (static_cast<std::size_t>(v) > u) boost::add_edge(u, static_cast<std::size_t>(v), gb);
    }
  }
  // Match order: breadth first from a vertex of the rarest colour, so every vertex after the
  // first of its component is adjacent to one already matched and has few candidates.
  std::vector<int> class_size(V + 1, 0);
  for (int c : col_a) ++class_size[c];
  std::vector<std::size_t> seeds(V);
  for (std::size_t v = 0; v < V; ++v) seeds[v] = v;
  std::stable_sort(seeds.begin(), seeds.end(), [&](std::size_t x, std::size_t y) {
    return class_size[col_a[x]] < class_size[col_a[y]];
  });
  std::vector<Graph::vertex_descriptor> order;
  order.reserve(V);
  std::vector<char> seen(V, 0);
  for (std::size_t s : seeds) {
    if (seen[s]) continue;
    seen[s] = 1;
    std::size_t head = order.size();
    order.push_back(s);
    for (; head < order.size(); ++head) {
      for (int w : adj_a[order[head]]) {
        if (!seen[w]) {
          seen[w] = 1;
          order.push_back(static_cast<std::size_t>(w));
        }
      }
    }
  }

  std::vector<std::size_t> mapping(V, 0);
  auto callback = [&mapping, V](auto f, auto) {
    for (std::size_t v = 0; v < V; ++v) mapping[v] = boost::get(f, v);
    return false;  // the first isomorphism is enough
  };
  auto same_colour = [&](std::size_t u, std::size_t v) { return col_a[u] == col_b[v]; };
  const bool found = boost::vf2_graph_iso(ga, gb, callback, boost::get(boost::vertex_index, ga),
                                          boost::get(boost::vertex_index, gb), order,
                                          boost::always_equivalent(), same_colour);
  if (!found) return std::nullopt;
  for (Symmetry g : kSymmetries) {
    bool ok = true;
    for (Side s : kSides) {
      const auto image = static_cast<std::size_t>(m + static_cast<int>(apply(g, s)));
      ok = ok && mapping[static_cast<std::size_t>(m + static_cast<int>(s))] == image;
    }
    if (ok) return g;
  }
  return std::nullopt;  // unreachable: colours keep walls on walls and S3 = the 6 symmetries
}

std::string sci(long double x) {
  return fmt::format("{:.2g}", static_cast<double>(x));
}

}  // namespace

Comparison compare_packings(const Pattern& a, const Pattern& b, long double d_relative_tolerance,
                            long double position_tolerance) {
  Comparison c;
  const std::size_t n = a.packing.size();
  c.same_n = n == b.packing.size();
  if (!c.same_n) {
    c.reason = fmt::format("n differs: {} vs {}", n, b.packing.size());
    return c;
  }
  const long double da = a.packing.d, db = b.packing.d;
  const long double d_rel = std::fabs(da - db) / std::max(std::fabs(da), std::fabs(db));
  c.same_d = da == db || d_rel <= d_relative_tolerance;

  const Reduced ra = reduce(a), rb = reduce(b);
  const std::string graph_rejection = quick_graph_rejection(ra, rb);
  const long double d_mean = (da + db) / 2;
  const long double tolerance = position_tolerance * d_mean;
  // Loose enough to pair up perturbed copies (so isomorphism rarely needs VF2), below d/2 so
  // the candidate of each point is unique.
  const long double radius = std::max(0.25L * d_mean, tolerance);

  std::optional<Symmetry> iso_symmetry, geo_symmetry;
  long double iso_displacement = std::numeric_limits<long double>::infinity();
  if (ra.m() == rb.m()) {
    for (Symmetry g : kSymmetries) {
      const auto match = match_points(a, ra, b, rb, g, radius);
      if (!match) continue;
      const bool geometric = match->max_distance <= tolerance;
      bool bonds = graph_rejection.empty();
      for (Side s : kSides) {
        bonds = bonds &&
                ra.wall_count[static_cast<int>(s)] == rb.wall_count[static_cast<int>(apply(g, s))];
      }
      bonds = bonds && maps_bonds(ra, rb, match->phi, g);
      if (geometric && !geo_symmetry) geo_symmetry = g;
      if (bonds && match->max_distance < iso_displacement) {
        iso_symmetry = g;
        iso_displacement = match->max_distance;
      }
      if (geometric && bonds) {
        c.symmetry = g;
        break;
      }
    }
  }
  c.geometric = geo_symmetry.has_value();
  c.isomorphic = iso_symmetry.has_value();
  std::string graph_reason = graph_rejection;
  if (!c.isomorphic && graph_rejection.empty()) {
    bool refuted = false;
    iso_symmetry = vf2_isomorphism(ra, rb, refuted);
    c.isomorphic = iso_symmetry.has_value();
    graph_reason = refuted ? "colour refinement separates them" : "no isomorphism (VF2)";
  }
  const bool matched = c.symmetry.has_value();
  c.same = c.same_d && matched;
  if (!c.same) c.symmetry.reset();

  if (c.same) {
    c.reason = fmt::format("same packing under {}", symmetry_name(*c.symmetry));
  } else if (!c.same_d) {
    c.reason = fmt::format("d differs by {} relative ({} vs {}); contact graphs {}{}", sci(d_rel),
                           sci(da), sci(db), c.isomorphic ? "isomorphic" : "differ",
                           matched ? ", points match" : "");
  } else if (!c.isomorphic) {
    c.reason = "contact graphs differ: " + graph_reason;
  } else if (!c.geometric) {
    c.reason = std::isfinite(iso_displacement)
                   ? fmt::format("isomorphic under {} but points differ by up to {} d",
                                 symmetry_name(*iso_symmetry), sci(iso_displacement / d_mean))
                   : fmt::format("isomorphic under {} but the points do not match",
                                 symmetry_name(*iso_symmetry));
  } else {
    c.reason = fmt::format(
        "isomorphic under {} and points match under {}, but not by the same correspondence",
        symmetry_name(*iso_symmetry), symmetry_name(*geo_symmetry));
  }
  return c;
}

std::vector<int> distinct_packings(const std::vector<Pattern>& patterns,
                                   long double d_relative_tolerance) {
  std::vector<int> ids(patterns.size(), -1);
  std::vector<std::size_t> representatives;
  for (std::size_t i = 0; i < patterns.size(); ++i) {
    for (std::size_t c = 0; c < representatives.size() && ids[i] < 0; ++c) {
      const Pattern& rep = patterns[representatives[c]];
      if (rep.packing.size() != patterns[i].packing.size()) continue;
      if (compare_packings(patterns[i], rep, d_relative_tolerance).same) {
        ids[i] = static_cast<int>(c);
      }
    }
    if (ids[i] < 0) {
      ids[i] = static_cast<int>(representatives.size());
      representatives.push_back(i);
    }
  }
  return ids;
}

void identify(PackingRecord& record) {
  record.graph_hash = contact_graph_hash(record.pattern);
}

}  // namespace tripack
