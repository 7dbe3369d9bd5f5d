#include "constructors/blocks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/neighbours.hpp"

namespace tripack {

void DiskUnitsPattern::set_side(long double side) {
  if (tracks_sqrt3_) throw std::logic_error("set_side on an exact pattern");
  L_ = side;
}

void DiskUnitsPattern::reserve(std::size_t n) {
  pts_.reserve(n);
  if (tracks_sqrt3_) {
    ex_.reserve(n);
    known_.reserve(n);
  }
}

int DiskUnitsPattern::add_sqrt3(const Sqrt3Point& p) {
  if (!tracks_sqrt3_) throw std::logic_error("exact disk added to an inexact pattern");
  pts_.push_back(p.value());
  ex_.push_back(p);
  known_.push_back(1);
  return static_cast<int>(pts_.size()) - 1;
}

void DiskUnitsPattern::move_sqrt3(int i, const Sqrt3Point& p) {
  if (!tracks_sqrt3_) throw std::logic_error("exact move in an inexact pattern");
  const auto u = static_cast<std::size_t>(i);
  pts_.at(u) = p.value();
  ex_[u] = p;
  known_[u] = 1;
}

void DiskUnitsPattern::erase(int i) {
  if (i < 0 || static_cast<std::size_t>(i) >= pts_.size())
    throw std::out_of_range("DiskUnitsPattern::erase");
  pts_.erase(pts_.begin() + i);
  if (tracks_sqrt3_) {
    ex_.erase(ex_.begin() + i);
    known_.erase(known_.begin() + i);
  }
  auto shift = [i](int j) { return j > i ? j - 1 : j; };
  std::erase(rattlers_, i);
  for (int& r : rattlers_) r = shift(r);
  std::erase_if(recorded_, [i](const Bond& b) { return b.a == i || b.b == i; });
  for (Bond& b : recorded_)
    b = b.is_wall() ? Bond{shift(b.a), b.b} : Bond::pair(shift(b.a), shift(b.b));
}

int DiskUnitsPattern::add_triangle(const Vec2L& corner, const Vec2L& a, const Vec2L& b, long k) {
  const int first = static_cast<int>(pts_.size());
  for (long i = 0; i < k; ++i)
    for (long j = 0; i + j < k; ++j)
      pts_.push_back(corner + a * static_cast<long double>(i) + b * static_cast<long double>(j));
  sync_sqrt3();
  record_triangle_bonds(first, k);
  return first;
}

int DiskUnitsPattern::add_triangle(const Sqrt3Point& corner, const Sqrt3Point& a,
                                   const Sqrt3Point& b, long k) {
  if (!tracks_sqrt3_) throw std::logic_error("exact triangle added to an inexact pattern");
  const int first = static_cast<int>(pts_.size());
  for (long i = 0; i < k; ++i) {
    const Sqrt3Point row = corner + a * i;
    for (long j = 0; i + j < k; ++j) {
      const Sqrt3Point p = row + b * j;
      pts_.push_back(p.value());
      ex_.push_back(p);
      known_.push_back(1);
    }
  }
  record_triangle_bonds(first, k);
  return first;
}

void DiskUnitsPattern::record_triangle_bonds(int first, long k) {
  // Lattice neighbours of (i, j): (i+1, j), (i, j+1) and (i-1, j+1) (|b - a| = 1).
  auto id = [&](long i, long j) { return first + static_cast<int>(index_in_triangle(k, i, j)); };
  for (long i = 0; i < k; ++i) {
    for (long j = 0; i + j < k; ++j) {
      if (i + j + 1 < k) {
        recorded_.push_back(Bond::pair(id(i, j), id(i + 1, j)));
        recorded_.push_back(Bond::pair(id(i, j), id(i, j + 1)));
      }
      if (i >= 1) recorded_.push_back(Bond::pair(id(i, j), id(i - 1, j + 1)));
    }
  }
}

std::vector<int> DiskUnitsPattern::triangle_edge(int first, long k, Edge e) {
  std::vector<int> out;
  for (long t = 0; t < k; ++t) {
    long i = 0, j = 0;
    switch (e) {
      case Edge::A:
        i = t;
        j = 0;
        break;
      case Edge::B:
        i = 0;
        j = t;
        break;
      case Edge::Far:
        i = k - 1 - t;
        j = t;
        break;
    }
    out.push_back(first + static_cast<int>(index_in_triangle(k, i, j)));
  }
  return out;
}

long DiskUnitsPattern::index_in_triangle(long k, long i, long j) {
  // Rows of constant i hold k - i disks.
  return i * k - i * (i - 1) / 2 + j;
}

namespace {}  // namespace

Pattern DiskUnitsPattern::finish(Provenance provenance) {
  const std::size_t n = pts_.size();
  std::sort(rattlers_.begin(), rattlers_.end());
  std::vector<char> is_rattler(n, 0);
  for (int r : rattlers_) is_rattler[static_cast<std::size_t>(r)] = 1;

  // Rattlers: each to the centre of its cage; there must be room.
  if (!rattlers_.empty()) {
    const long double room = centre_rattlers(pts_, L_, rattlers_);
    if (!(room > 1e-6L)) throw std::runtime_error("a rattler has no room in its cage");
  }

  // One pass over near pairs: the worst overlap (validity) and, when detecting, the contacts.
  Pattern out;
  long double worst_overlap = 0;
  for_each_pair_within(pts_, 1.0L + kBondTolerance, [&](int i, int j, long double dist) {
    worst_overlap = std::max(worst_overlap, 1 - dist);
    if (mode_ == BondMode::Detect && std::fabs(dist - 1) <= kBondTolerance &&
        !is_rattler[static_cast<std::size_t>(i)] && !is_rattler[static_cast<std::size_t>(j)])
      out.bonds.push_back(Bond::pair(i, j));
  });
  if (worst_overlap > kBondTolerance)
    throw std::runtime_error("constructed pattern overlaps by " +
                             std::to_string(static_cast<double>(worst_overlap)));
  for (std::size_t i = 0; i < n; ++i) {
    for (Side s : kSides) {
      const long double w = wall_distance(pts_[i], s, L_);
      if (w < -kBondTolerance)
        throw std::runtime_error("constructed pattern has a centre outside the triangle");
      if (mode_ == BondMode::Detect && w <= kBondTolerance && !is_rattler[i])
        out.bonds.push_back(Bond::wall(static_cast<int>(i), s));
    }
  }
  switch (mode_) {
    case BondMode::Detect:
      break;
    case BondMode::Set:
      out.bonds = bonds_;
      break;
    case BondMode::Recorded:
      for (const auto& b : recorded_)
        if (!is_rattler[static_cast<std::size_t>(b.a)] &&
            (b.is_wall() || !is_rattler[static_cast<std::size_t>(b.b)]))
          out.bonds.push_back(b);
      break;
  }
  std::sort(out.bonds.begin(), out.bonds.end());
  out.bonds.erase(std::unique(out.bonds.begin(), out.bonds.end()), out.bonds.end());
  // Recorded or set bonds must be contacts of the constructed geometry.
  for (const auto& b : out.bonds) {
    const auto& p = pts_[static_cast<std::size_t>(b.a)];
    const long double gap = b.is_wall() ? wall_distance(p, b.side(), L_)
                                        : norm(p - pts_[static_cast<std::size_t>(b.b)]) - 1;
    if (std::fabs(gap) > kBondTolerance)
      throw std::logic_error("intended bond " + std::to_string(b.a) + "-" + std::to_string(b.b) +
                             " is not a contact (gap " + std::to_string(static_cast<double>(gap)) +
                             ")");
  }
  out.rattlers = rattlers_;
  out.provenance = std::move(provenance);
  out.packing.d = 1.0L / L_;
  if (tracks_sqrt3_) {
    // Points pushed through points() have no exact data; rattlers were moved numerically. A known
    // disk must still be where its exact coordinates say (nobody moved it through points()).
    sync_sqrt3();
    for (int r : rattlers_) known_[static_cast<std::size_t>(r)] = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!known_[i]) continue;
      const Vec2L v = ex_[i].value() - pts_[i];
      if (std::fabs(v.x) > kBondTolerance || std::fabs(v.y) > kBondTolerance)
        throw std::logic_error("disk " + std::to_string(i) + " moved away from its exact position");
    }
    out.sqrt3 = Sqrt3DiskUnits{sqrt3_L_, std::move(ex_), std::move(known_)};
    tracks_sqrt3_ = false;  // the exact data have moved out
  }
  out.packing.points.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    // Floor disks may sit a rounding below y = 0: clamp them onto the floor.
    Vec2L p = pts_[i] / L_;
    p.y = std::max(p.y, 0.0L);
    out.packing.points[i] = p;
  }
  return out;
}

}  // namespace tripack
