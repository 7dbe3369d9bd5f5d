#include "core/record.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tripack {

std::string PackingSource::describe() const {
  switch (kind) {
    case Kind::Builder:
      return "builder " + name;
    case Kind::Import:
      return "import " + name;
    case Kind::Table:
      return name;
    case Kind::Billiards:
      break;
  }
  return fmt::format("billiards seed {} ({} run{})", seed, runs, runs == 1 ? "" : "s");
}

std::string PackingRecord::origin() const {
  if (sources.empty()) return "";
  switch (sources.front().kind) {
    case PackingSource::Kind::Builder:
      return "builder";
    case PackingSource::Kind::Import:
      return "import";
    case PackingSource::Kind::Table:
      return "table";
    case PackingSource::Kind::Billiards:
      break;
  }
  return "billiards";
}

std::string identity_d_key(long double d) {
  return format_significant(d, kIdentityDigits);
}

bool same_packing(const IdentityFields& a, const IdentityFields& b) {
  if (a.n != b.n || a.graph_hash != b.graph_hash) return false;
  return std::fabs(a.d / b.d - 1) <= kSameDTolerance || identity_d_key(a.d) == identity_d_key(b.d);
}

bool same_packing(const PackingRecord& a, const PackingRecord& b) {
  return same_packing(IdentityFields{a.n(), a.graph_hash, a.d.value()},
                      IdentityFields{b.n(), b.graph_hash, b.d.value()});
}

PackingRecord PackingRecord::of(Pattern pattern) {
  PackingRecord record;
  record.d = PreciseReal(pattern.packing.d);
  record.L = PreciseReal(1 / pattern.packing.d);
  record.pattern = std::move(pattern);
  return record;
}

std::uint64_t PackingRecord::first_seed() const {
  std::uint64_t seed = std::numeric_limits<std::uint64_t>::max();
  for (const auto& s : sources)
    if (s.kind == PackingSource::Kind::Billiards) seed = std::min(seed, s.seed);
  return seed;
}

long long PackingRecord::runs() const {
  long long runs = 0;
  for (const auto& s : sources)
    if (s.kind == PackingSource::Kind::Billiards) runs += s.runs;
  return runs;
}

long long PackingRecord::own_confirmations() const {
  long long count = 0;
  bool builder = false;
  for (const auto& s : sources) {
    if (s.kind == PackingSource::Kind::Billiards) count += s.independent_runs;
    if (s.kind == PackingSource::Kind::Table) count += s.runs;
    builder = builder || s.kind == PackingSource::Kind::Builder;
  }
  return count + (builder ? 1 : 0);
}

std::string PackingRecord::source_text() const {
  // Builders first, named together ("builder A = B": one packing, two builders).
  std::string builders, others;
  for (const auto& s : sources) {
    if (s.kind == PackingSource::Kind::Builder)
      builders += (builders.empty() ? "builder " : " = ") + s.name;
    else
      others += (others.empty() ? "" : "; ") + s.describe();
  }
  if (builders.empty()) return others;
  return others.empty() ? builders : builders + "; " + others;
}

void PackingRecord::merge_sources(const PackingRecord& other) {
  for (const auto& s : other.sources) {
    auto same = std::find_if(sources.begin(), sources.end(), [&](const PackingSource& mine) {
      return mine.kind == s.kind && mine.kind == PackingSource::Kind::Billiards;
    });
    if (same == sources.end()) {
      sources.push_back(s);
    } else {
      same->seed = std::min(same->seed, s.seed);
      same->runs += s.runs;
      same->independent_runs += s.independent_runs;
    }
  }
}

std::vector<PackingRecord> merge_same_packings(std::vector<PackingRecord> records,
                                               std::vector<std::size_t>* group) {
  std::vector<PackingRecord> merged;
  if (group) group->clear();
  for (auto& r : records) {
    std::size_t g = 0;
    while (g < merged.size() && !same_packing(merged[g], r)) ++g;
    if (g == merged.size())
      merged.push_back(std::move(r));
    else
      merged[g].merge_sources(r);
    if (group) group->push_back(g);
  }
  return merged;
}

}  // namespace tripack
