#include "analysis/bonds.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/neighbours.hpp"

namespace tripack {

namespace {

// The angle of the contact direction from disk i towards the contact point (atan2 needs no unit
// vector). In double: the surround test's margin (1e-9 rad) is far above its rounding.
double contact_angle(const Packing& pk, const Bond& b, int i) {
  Vec2L v;
  if (b.is_wall()) {
    v = -wall_normal<long double>(b.side());
  } else {
    const int j = b.a == i ? b.b : b.a;
    v = pk.points[static_cast<std::size_t>(j)] - pk.points[static_cast<std::size_t>(i)];
  }
  return std::atan2(static_cast<double>(v.y), static_cast<double>(v.x));
}

// True if the directions surround the origin strictly: every angular gap below pi.
bool surrounds(std::vector<double>& angles) {
  if (angles.size() < 3) return false;
  std::sort(angles.begin(), angles.end());
  double widest = angles.front() + 2 * std::numbers::pi - angles.back();
  for (std::size_t a = 1; a < angles.size(); ++a)
    widest = std::max(widest, angles[a] - angles[a - 1]);
  return widest < std::numbers::pi - 1e-9;
}

}  // namespace

// The rattlers are the largest set whose removal leaves every other disk surrounded by its
// remaining contacts; removing bonds only fails more tests, so that set is one fixed point, found
// here by a work list: a disk is tested again only when it lost a contact.
std::vector<int> find_rattlers(const Packing& pk, std::vector<Bond>& bonds) {
  const std::size_t n = pk.size();
  std::vector<std::vector<std::pair<std::size_t, double>>> contacts(n);  // (bond, angle)
  for (std::size_t k = 0; k < bonds.size(); ++k)
    for (int i : {bonds[k].a, bonds[k].b})
      if (i >= 0)
        contacts[static_cast<std::size_t>(i)].emplace_back(k, contact_angle(pk, bonds[k], i));
  std::vector<char> rattler(n, 0), alive(bonds.size(), 1), queued(n, 1);
  std::vector<std::size_t> work(n);
  for (std::size_t i = 0; i < n; ++i) work[i] = n - 1 - i;  // disk 0 first
  std::vector<double> angles;
  while (!work.empty()) {
    const std::size_t i = work.back();
    work.pop_back();
    queued[i] = 0;
    angles.clear();
    for (const auto& [k, angle] : contacts[i])
      if (alive[k]) angles.push_back(angle);
    if (surrounds(angles)) continue;
    rattler[i] = 1;
    for (const auto& [k, angle] : contacts[i]) {
      if (!alive[k]) continue;
      alive[k] = 0;
      const Bond& b = bonds[k];
      const int other = b.is_wall() ? -1 : (static_cast<std::size_t>(b.a) == i ? b.b : b.a);
      if (other >= 0 && !rattler[static_cast<std::size_t>(other)] &&
          !queued[static_cast<std::size_t>(other)]) {
        queued[static_cast<std::size_t>(other)] = 1;
        work.push_back(static_cast<std::size_t>(other));
      }
    }
  }
  std::size_t kept = 0;
  for (std::size_t k = 0; k < bonds.size(); ++k)
    if (alive[k]) bonds[kept++] = bonds[k];
  bonds.resize(kept);
  std::vector<int> out;
  for (std::size_t i = 0; i < n; ++i)
    if (rattler[i]) out.push_back(static_cast<int>(i));
  return out;
}

std::vector<Gap> smallest_gaps(const Packing& pk, const std::vector<Bond>& bonds,
                               std::size_t count) {
  std::vector<char> bonded_rattler(pk.size(), 1);  // a disk with no bonds at all is a rattler here
  for (const auto& b : bonds) {
    bonded_rattler[static_cast<std::size_t>(b.a)] = 0;
    if (!b.is_wall()) bonded_rattler[static_cast<std::size_t>(b.b)] = 0;
  }
  std::vector<Gap> gaps;
  for_each_pair_within(pk.points, pk.d * 1.25L, [&](int i, int j, long double r) {
    const Bond b = Bond::pair(i, j);
    if (std::binary_search(bonds.begin(), bonds.end(), b)) return;
    gaps.push_back({b, r / pk.d - 1,
                    bonded_rattler[static_cast<std::size_t>(i)] ||
                        bonded_rattler[static_cast<std::size_t>(j)]});
  });
  for (std::size_t i = 0; i < pk.size(); ++i) {
    for (Side s : kSides) {
      const long double w = wall_distance(pk.points[i], s, 1.0L);
      const Bond b = Bond::wall(static_cast<int>(i), s);
      if (w > 0.25L * pk.d || std::binary_search(bonds.begin(), bonds.end(), b)) continue;
      gaps.push_back({b, w / pk.d, static_cast<bool>(bonded_rattler[i])});
    }
  }
  std::sort(gaps.begin(), gaps.end(), [](const Gap& a, const Gap& b) { return a.gap < b.gap; });
  if (gaps.size() > count) gaps.resize(count);
  return gaps;
}

BondIdentification identify_bonds(Packing& pk, const std::vector<Bond>& loaded,
                                  long double gap_threshold, std::size_t max_rejections) {
  BondIdentification out;
  // Candidates: loaded contacts plus near-exact contacts; remember each one's gap.
  std::vector<std::pair<Bond, long double>> gap_only;
  std::vector<Bond> cand = loaded;
  for_each_pair_within(pk.points, pk.d * (1 + gap_threshold), [&](int i, int j, long double r) {
    cand.push_back(Bond::pair(i, j));
    gap_only.emplace_back(Bond::pair(i, j), r / pk.d - 1);
  });
  for (std::size_t i = 0; i < pk.size(); ++i)
    for (Side s : kSides) {
      const long double w = wall_distance(pk.points[i], s, 1.0L);
      if (w <= gap_threshold * pk.d) {
        cand.push_back(Bond::wall(static_cast<int>(i), s));
        gap_only.emplace_back(Bond::wall(static_cast<int>(i), s), w / pk.d);
      }
    }
  std::sort(cand.begin(), cand.end());
  cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  std::erase_if(gap_only, [&](const auto& g) {
    return std::binary_search(loaded.begin(), loaded.end(), g.first);
  });
  std::sort(gap_only.begin(), gap_only.end(),
            [](const auto& a, const auto& b) { return a.second > b.second; });
  out.candidates = static_cast<int>(cand.size());

  const Packing start = pk;
  for (std::size_t drop = 0;; ++drop) {
    std::vector<Bond> bonds = cand;
    out.rattlers = find_rattlers(start, bonds);
    pk = start;
    out.polish = polish_bond_system(pk, bonds, out.rattlers);
    out.bonds = std::move(bonds);
    if (out.polish.converged || drop >= gap_only.size() || drop >= max_rejections) break;
    // Inconsistent: the widest gap-only candidate is the likeliest false contact.
    std::erase(cand, gap_only[drop].first);
    ++out.rejected;
  }
  return out;
}

namespace {

// Gap of bond b in units of d at pk (long double).
long double gap_of(const Packing& pk, const Bond& b) {
  const Vec2L& p = pk.points[static_cast<std::size_t>(b.a)];
  if (b.is_wall()) return wall_distance(p, b.side(), 1.0L) / pk.d;
  return norm(p - pk.points[static_cast<std::size_t>(b.b)]) / pk.d - 1;
}

}  // namespace

PreciseIdentification identify_bonds_multiprecision(const Packing& start,
                                                    const std::vector<Bond>& hints,
                                                    long double gap_threshold, int digits,
                                                    DropRule rule, std::size_t max_drops) {
  PreciseIdentification out;
  out.rule = rule;
  std::vector<Bond> cand = hints;
  for_each_pair_within(start.points, start.d * (1 + gap_threshold),
                       [&](int i, int j, long double) { cand.push_back(Bond::pair(i, j)); });
  for (std::size_t i = 0; i < start.size(); ++i)
    for (Side s : kSides)
      if (wall_distance(start.points[i], s, 1.0L) <= gap_threshold * start.d)
        cand.push_back(Bond::wall(static_cast<int>(i), s));
  std::sort(cand.begin(), cand.end());
  cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  out.candidates = static_cast<int>(cand.size());
  // The floor below which a gap is not resolved: 10^-digits, or what the polish measurably left
  // of the bond equations if more; 10^6 times it counts as closed.
  const long double precision = std::pow(10.0L, -static_cast<long double>(digits));
  for (std::size_t round = 0; round < max_drops + cand.size() + 8; ++round) {
    std::vector<Bond> bonds = cand;
    std::vector<int> rattlers = find_rattlers(start, bonds);
    if (bonds.empty()) {
      out.failure = "every disk is a rattler by the surround test with the contacts that remain";
      return out;
    }
    Packing compromise = start;
    const PolishReport ld = polish_bond_system(compromise, bonds, rattlers);
    ++out.polishes;
    if (ld.converged) {
      MultiprecisionPolish mp = polish_multiprecision(start, bonds, rattlers, digits);
      ++out.polishes;
      if (mp.converged) {
        const double clearance = centre_rattlers_multiprecision(mp, rattlers);
        PreciseGaps gaps = precise_gaps(mp, bonds, rattlers);
        const long double closed = 1e6L * std::max(precision, gaps.bond_floor);
        std::vector<Bond> join;
        for (const auto& g : gaps.gaps)
          if (!g.rattler && g.gap <= closed) join.push_back(g.contact);
        if (join.empty()) {
          out.bonds = std::move(bonds);
          out.rattlers = std::move(rattlers);
          out.polish = std::move(mp);
          out.gaps = std::move(gaps);
          out.rattler_clearance = clearance;
          out.found = true;
          return out;
        }
        // Contacts the bond system closes (or overlaps it makes): bonds too.
        out.implied += static_cast<int>(join.size());
        cand.insert(cand.end(), join.begin(), join.end());
        std::sort(cand.begin(), cand.end());
        cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
        continue;
      }
    }
    // No solution: drop a candidate, by `rule`, among those whose removal leaves every held
    // disk held: in a lattice region the surround test needs every contact (they are collinear
    // in pairs), and dropping a true one there turns disks into rattlers in a cascade, often to
    // the whole packing.
    if (static_cast<std::size_t>(out.dropped) >= max_drops) break;
    const Packing& at = rule == DropRule::Widest ? start : compromise;
    std::vector<std::pair<long double, Bond>> ranked;
    for (const Bond& b : bonds) ranked.emplace_back(gap_of(at, b), b);
    std::sort(ranked.begin(), ranked.end(),
              [](const auto& x, const auto& y) { return x.first > y.first; });
    // The first few of the ranking only (each trial is a surround test over every bond).
    constexpr std::size_t kTries = 32;
    Bond drop = ranked.front().second;  // if every drop tried frees disks
    for (std::size_t k = 0; k < std::min(kTries, ranked.size()); ++k) {
      const Bond& b = ranked[k].second;
      std::vector<Bond> trial = cand;
      std::erase(trial, b);
      if (find_rattlers(start, trial).size() <= rattlers.size()) {
        drop = b;
        break;
      }
    }
    std::erase(cand, drop);
    ++out.dropped;
  }
  out.failure = fmt::format("no consistent bond set after dropping {} of {} candidates",
                            out.dropped, out.candidates);
  return out;
}

}  // namespace tripack
