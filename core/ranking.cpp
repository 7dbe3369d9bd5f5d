#include "core/ranking.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace tripack {

std::string rank_letters(std::size_t rank) {
  std::string letters;
  for (std::size_t r = rank + 1; r > 0; r = (r - 1) / 26)
    letters.insert(letters.begin(), static_cast<char>('a' + (r - 1) % 26));
  return letters;
}

std::vector<std::size_t> label_order(const std::vector<RankKey>& keys,
                                     const std::vector<std::uint64_t>& tie,
                                     long double d_relative_tolerance) {
  std::vector<std::size_t> order(keys.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  auto d_of = [&](std::size_t i) { return keys[i].d; };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return d_of(a) != d_of(b) ? d_of(a) > d_of(b) : tie[a] < tie[b];
  });
  // Packings whose d agree to the labelling tolerance share a rank: order them by bonds (then
  // the tie key), not by d's last bits, which vary from run to run.
  for (std::size_t lo = 0, hi = 0; lo < order.size(); lo = hi) {
    for (hi = lo + 1; hi < order.size() &&
                      std::fabs(d_of(order[hi]) / d_of(order[hi - 1]) - 1) <= d_relative_tolerance;
         ++hi) {
    }
    std::stable_sort(order.begin() + static_cast<long>(lo), order.begin() + static_cast<long>(hi),
                     [&](std::size_t a, std::size_t b) { return keys[a].bonds > keys[b].bonds; });
  }
  return order;
}

std::vector<std::string> paper_labels(long long n, const std::vector<RankKey>& sorted,
                                      long double d_relative_tolerance) {
  auto same_d = [&](std::size_t i, std::size_t j) {
    return std::fabs(sorted[i].d / sorted[j].d - 1) <= d_relative_tolerance;
  };
  std::vector<std::string> labels(sorted.size());
  std::size_t rank = 0;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    if (i > 0 && !same_d(i, i - 1)) ++rank;
    const bool shared = (i > 0 && same_d(i, i - 1)) || (i + 1 < sorted.size() && same_d(i, i + 1));
    labels[i] = fmt::format("t{}{}{}", n, rank_letters(rank),
                            shared ? std::to_string(sorted[i].bonds) : "");
  }
  std::map<std::string, int> uses, seen;
  for (const auto& label : labels) ++uses[label];
  for (auto& label : labels)
    if (uses[label] > 1) label += fmt::format(".{}", ++seen[label]);
  return labels;
}

std::vector<std::size_t> rank_records(long long n, std::vector<PackingRecord>& records) {
  std::vector<RankKey> keys;
  std::vector<std::uint64_t> seeds;
  for (const auto& r : records) {
    keys.push_back({r.d.value(), r.bonds()});
    seeds.push_back(r.first_seed());
  }
  const auto order = label_order(keys, seeds);
  std::vector<RankKey> sorted;
  std::vector<PackingRecord> ranked;
  for (std::size_t i : order) {
    sorted.push_back(keys[i]);
    ranked.push_back(std::move(records[i]));
  }
  const auto labels = paper_labels(n, sorted);
  for (std::size_t r = 0; r < ranked.size(); ++r) {
    ranked[r].label = labels[r];
    ranked[r].rank = r + 1;
  }
  records = std::move(ranked);
  return order;
}

void count_value_confirmations(std::vector<PackingRecord>& records) {
  std::vector<long long> of_value(records.size(), 0);
  for (std::size_t i = 0; i < records.size(); ++i)
    for (const auto& other : records)
      if (std::fabs(other.d.value() - records[i].d.value()) <=
          kSameValueTolerance * records[i].d.value())
        of_value[i] += other.own_confirmations();
  for (std::size_t i = 0; i < records.size(); ++i) records[i].d_confirmations = of_value[i];
}

}  // namespace tripack
