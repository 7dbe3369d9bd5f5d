#include "patterns/vacancy_lattice.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include "analysis/bonds.hpp"
#include "analysis/interior_relax.hpp"
#include "analysis/relax.hpp"

namespace tripack::patterns {

namespace {

// The 6 symmetries act on a site's barycentric coordinates (i, j, l = rows - 1 - i - j) by
// permuting them.
Site permuted(long rows, const Site& s, int symmetry) {
  const std::array<long, 3> c{s.i, s.j, rows - 1 - s.i - s.j};
  static constexpr int kPerm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                      {1, 0, 2}, {0, 2, 1}, {2, 1, 0}};
  return {c[static_cast<std::size_t>(kPerm[symmetry][0])],
          c[static_cast<std::size_t>(kPerm[symmetry][1])]};
}

}  // namespace

Packing lattice_with_vacancies(long rows, const std::vector<Site>& vacancies) {
  if (rows < 2) throw std::invalid_argument("a lattice with vacancies needs at least 2 rows");
  std::set<Site> empty;
  for (const Site& s : vacancies) {
    if (s.i < 0 || s.j < 0 || s.i + s.j >= rows)
      throw std::invalid_argument("vacancy (" + std::to_string(s.i) + ", " + std::to_string(s.j) +
                                  ") is not a site of the " + std::to_string(rows) +
                                  "-row lattice");
    empty.insert(s);
  }
  const long double spacing = 1.0L / static_cast<long double>(rows - 1);
  Packing p;
  for (long j = 0; j < rows; ++j)
    for (long i = 0; i + j < rows; ++i)
      if (!empty.count({i, j}))
        p.points.push_back(
            {(static_cast<long double>(i) + static_cast<long double>(j) / 2) * spacing,
             static_cast<long double>(j) * kSqrt3 / 2 * spacing});
  p.d = spacing;
  return p;
}

std::vector<Site> canonical_vacancies(long rows, std::vector<Site> vacancies) {
  std::vector<Site> best;
  for (int s = 0; s < 6; ++s) {
    std::vector<Site> image;
    for (const Site& v : vacancies) image.push_back(permuted(rows, v, s));
    std::sort(image.begin(), image.end());
    if (best.empty() || image < best) best = image;
  }
  return best;
}

std::vector<std::vector<Site>> straight_segments(long rows, long length) {
  std::vector<std::vector<Site>> out;
  if (length < 1 || length > rows) return out;
  std::set<std::vector<Site>> seen;
  // Along rows only: the rotations carry the other two line directions onto rows.
  for (long j = 0; j + length <= rows; ++j)
    for (long i = 0; i + j + length <= rows; ++i) {
      std::vector<Site> seg;
      for (long t = 0; t < length; ++t) seg.push_back({i + t, j});
      if (seen.insert(canonical_vacancies(rows, seg)).second) out.push_back(seg);
    }
  return out;
}

Pattern relax_to_pattern(const Packing& start) {
  Packing p = start;
  interior_relax(p);
  const RelaxReport lp = relax_packing(p);
  BondIdentification id = identify_bonds(p, lp.active);
  Pattern out;
  out.packing = std::move(p);
  out.bonds = std::move(id.bonds);
  out.rattlers = std::move(id.rattlers);
  return out;
}

SegmentChoice best_vacancy_segment(long rows, long vacancies) {
  if (vacancies < 1 || vacancies >= rows)
    throw std::invalid_argument("a vacancy segment of " + std::to_string(vacancies) +
                                " sites does not fit a lattice line of " + std::to_string(rows) +
                                " rows with a disk left on it");
  SegmentChoice best;
  Packing best_packing;
  RelaxReport best_relax;
  for (const auto& seg : straight_segments(rows, vacancies)) {
    Packing p = lattice_with_vacancies(rows, seg);
    interior_relax(p);
    RelaxReport lp = relax_packing(p);
    ++best.segments;
    // Distinct packings of one n differ by 1e-12 relative at least in the atlas; below 1e-14
    // two segments are the same packing (or the same d), and the first is kept.
    if (best.vacancies.empty() || p.d > best_packing.d * (1 + 1e-14L)) {
      best_packing = std::move(p);
      best_relax = std::move(lp);
      best.vacancies = seg;
    }
  }
  // The winner's bonds from its own relax: relax_to_pattern's steps, without relaxing it again.
  BondIdentification id = identify_bonds(best_packing, best_relax.active);
  best.pattern.packing = std::move(best_packing);
  best.pattern.bonds = std::move(id.bonds);
  best.pattern.rattlers = std::move(id.rattlers);
  return best;
}

}  // namespace tripack::patterns
