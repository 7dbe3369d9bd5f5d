#include "campaign/stored.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "pipeline/billiards_search.hpp"

namespace tripack::campaign {

namespace {

store::OpenOptions for_reading() {
  store::OpenOptions options;
  options.create = false;
  options.allow_read_only = true;
  return options;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::vector<RankedPacking> ranked_packings(const store::ResultsDb& db, long long n) {
  std::vector<store::StoredPacking> stored = db.packings(n);
  std::vector<pipeline::RankKey> keys;
  std::vector<std::uint64_t> seeds;
  for (const auto& p : stored) {
    keys.push_back({std::stold(p.d), p.bonds.size()});
    seeds.push_back(p.has_seed ? p.first_seed : std::numeric_limits<std::uint64_t>::max());
  }
  const auto order = pipeline::label_order(keys, seeds);
  std::vector<pipeline::RankKey> sorted;
  for (std::size_t i : order) sorted.push_back(keys[i]);
  const auto labels = pipeline::paper_labels(n, sorted);
  std::vector<RankedPacking> ranked;
  for (std::size_t r = 0; r < order.size(); ++r)
    ranked.push_back({std::move(stored[order[r]]), labels[r], r + 1});
  return ranked;
}

Pattern pattern_of(const store::StoredPacking& packing) {
  Pattern pattern;
  pattern.packing.points = packing.points;
  pattern.packing.d = std::stold(packing.d);
  pattern.bonds = packing.bonds;
  pattern.rattlers = packing.rattlers;
  return pattern;
}

BestTable best_table(const store::ResultsDb& db, long long n_first, long long n_last) {
  const auto start = std::chrono::steady_clock::now();
  BestTable table;
  table.db = db.path();
  for (const auto& best : db.best_per_n())
    if (best.n >= n_first && best.n <= n_last)
      table.rows.push_back(ranked_packings(db, best.n).front());
  table.seconds = seconds_since(start);
  return table;
}

BestTable best_table(const std::string& path, long long n_first, long long n_last) {
  const auto start = std::chrono::steady_clock::now();
  BestTable table = best_table(store::ResultsDb::open(path, for_reading()), n_first, n_last);
  table.seconds = seconds_since(start);
  return table;
}

DbCheck check_database(const std::string& path) {
  const auto start = std::chrono::steady_clock::now();
  DbCheck check;
  check.db = path;
  check.stats = store::ResultsDb::open(path, for_reading()).statistics();
  check.seconds = seconds_since(start);
  return check;
}

std::vector<RankedPacking> select_packings(const std::string& path, long long n, long long rank,
                                           bool all) {
  const store::ResultsDb db = store::ResultsDb::open(path, for_reading());
  std::vector<RankedPacking> ranked = ranked_packings(db, n);
  if (ranked.empty())
    throw std::invalid_argument(fmt::format("no packings of n = {} in {}", n, path));
  if (all) return ranked;
  if (rank < 1 || rank > static_cast<long long>(ranked.size()))
    throw std::invalid_argument(fmt::format(
        "rank {} is out of range: n = {} has {} stored packing{} in {} (ranks 1..{}: {} .. {})",
        rank, n, ranked.size(), ranked.size() == 1 ? "" : "s", path, ranked.size(),
        ranked.front().label, ranked.back().label));
  return {std::move(ranked[static_cast<std::size_t>(rank - 1)])};
}

namespace {

std::uintmax_t file_bytes(const std::string& path) {
  std::uintmax_t bytes = 0;
  for (const char* suffix : {"", "-wal"}) {
    std::error_code error;
    const auto size = std::filesystem::file_size(path + suffix, error);
    if (!error) bytes += size;
  }
  return bytes;
}

}  // namespace

PruneResult prune_database(const std::string& path, long long keep, long long n_first,
                           long long n_last) {
  if (keep < 1) throw std::invalid_argument("--keep must be at least 1");
  const auto start = std::chrono::steady_clock::now();
  PruneResult result;
  result.db = path;
  result.keep = keep;
  store::OpenOptions options;
  options.create = false;
  store::ResultsDb db = store::ResultsDb::open(path, options);
  result.bytes_before = file_bytes(path);
  std::vector<long long> doomed;
  for (const auto& best : db.best_per_n()) {
    if (best.n < n_first || best.n > n_last) continue;
    ++result.n_values;
    const auto ranked = ranked_packings(db, best.n);
    for (const auto& r : ranked) {
      if (static_cast<long long>(r.rank) <= keep)
        ++result.kept;
      else
        doomed.push_back(r.packing.id);
    }
  }
  result.removed = static_cast<long long>(doomed.size());
  db.remove_packings(doomed);
  try {
    db.compact();
  } catch (const store::StoreError& e) {
    result.not_compacted = e.what();
  }
  result.bytes_after = file_bytes(path);
  result.seconds = seconds_since(start);
  return result;
}

}  // namespace tripack::campaign
