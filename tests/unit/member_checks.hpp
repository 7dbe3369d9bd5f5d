// What every class member built must satisfy, shared by the test that builds the member: the
// discovered classes' members are built once, by Atlas.NoBuilderBeatsTheCommittedAtlas (their
// enumeration costs seconds each), and checked there as Classes.* checks the others.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "constructors/catalogue.hpp"
#include "constructors/registry.hpp"
#include "core/neighbours.hpp"
#include "polish/polish.hpp"

namespace tripack {

// A valid packing: all pairwise distances >= d (1 - 1e-12) and every centre inside the
// triangle (to 1e-18, a few roundings of the long double coordinates). Returns the smallest
// pairwise distance.
inline long double expect_valid_packing(const Pattern& pat, const std::string& what) {
  const auto& pk = pat.packing;
  const long double md = min_pair_distance(pk.points, pk.d * 1.5L);
  EXPECT_GE(md, pk.d * (1 - 1e-12L)) << what;
  long double worst = 0;
  for (const auto& p : pk.points)
    for (Side s : kSides) worst = std::min(worst, wall_distance(p, s, 1.0L));
  EXPECT_GE(worst, -1e-18L) << what;
  return md;
}

// A built member, polished: n as the catalogue says, valid, bonds and rattlers as the catalogue
// predicts, rattlers without bonds, and at least 3 bonds on every other disk of a rigid class.
inline void expect_member_matches_catalogue(const Catalogue& catalogue, const ClassInfo& c,
                                            const BuildRequest& member, Pattern pat) {
  const std::string what = c.id + " k=" + std::to_string(member.k) +
                           " p=" + std::to_string(member.p) + " " + member.variant;
  const auto polish = polish_bond_system(pat.packing, pat.bonds, pat.rattlers);
  EXPECT_TRUE(polish.converged) << what << " residual " << static_cast<double>(polish.max_residual);
  EXPECT_EQ(static_cast<long long>(pat.packing.size()), catalogue.n_of(c, member.k, member.p))
      << what;
  expect_valid_packing(pat, what);
  if (const auto b = catalogue.bonds_of(c, member.k, member.p, member.variant); b && c.rigid) {
    EXPECT_EQ(static_cast<long long>(pat.bonds.size()), *b) << what;
  }
  if (const auto r = catalogue.rattlers_of(c, member.k, member.p, member.variant)) {
    EXPECT_EQ(static_cast<long long>(pat.rattlers.size()), *r) << what;
  }
  std::vector<int> degree(pat.packing.size(), 0);
  for (const auto& b : pat.bonds) {
    ++degree[static_cast<std::size_t>(b.a)];
    if (!b.is_wall()) ++degree[static_cast<std::size_t>(b.b)];
  }
  for (int r : pat.rattlers) EXPECT_EQ(degree[static_cast<std::size_t>(r)], 0) << what;
  if (c.rigid) {
    std::vector<char> is_r(pat.packing.size(), 0);
    for (int r : pat.rattlers) is_r[static_cast<std::size_t>(r)] = 1;
    for (std::size_t i = 0; i < degree.size(); ++i)
      if (!is_r[i]) {
        EXPECT_GE(degree[i], 3) << what << " disk " << i;
      }
  }
}

}  // namespace tripack
