// Ranking and labels, defined once (docs/conventions.md, "Labels"): the packings of one n ordered
// by decreasing d and named like the paper (t22a, t22b, ...). The billiards runs, the store's
// read commands, the atlas and the explorer all rank through rank_records.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/record.hpp"

namespace tripack {

// The rank letters of the paper extended past z: 0 -> a, 25 -> z, 26 -> aa, 27 -> ab, ... (a
// bijective base-26 numeral, so every rank has a label and labels sort by length then letters).
std::string rank_letters(std::size_t rank);

struct RankKey {
  long double d = 0;
  std::size_t bonds = 0;
};
// Labels for packings sorted by decreasing d: tN + rank letters, where packings whose d agree to
// `d_relative_tolerance` share a rank and get their bond count appended (t17a40), and those that
// share the bond count too get .1, .2, ... (t31a81.1).
std::vector<std::string> paper_labels(long long n, const std::vector<RankKey>& sorted,
                                      long double d_relative_tolerance = kSameDTolerance);
// The order packings are labelled in (indices into `keys`): d decreasing; where d agree to the
// tolerance, more bonds first, then the smaller `tie` (the first seed), then the given order.
std::vector<std::size_t> label_order(const std::vector<RankKey>& keys,
                                     const std::vector<std::uint64_t>& tie,
                                     long double d_relative_tolerance = kSameDTolerance);

// Sorts the records of one n into label order (ties by first seed; records without a seed after
// those with one) and sets each one's label and 1-based rank. Returns where each came from: the
// record now at position r was records[order[r]].
std::vector<std::size_t> rank_records(long long n, std::vector<PackingRecord>& records);

// Sets each record's d_confirmations: the own_confirmations() of every record of the
// list (one n) whose d agrees with its own to kSameValueTolerance, itself included.
void count_value_confirmations(std::vector<PackingRecord>& records);

}  // namespace tripack
