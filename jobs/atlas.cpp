#include "jobs/atlas.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "analysis/compare.hpp"
#include "core/io.hpp"
#include "core/ranking.hpp"
#include "core/timing.hpp"
#include "jobs/stored.hpp"
#include "pipeline/analyze.hpp"
#include "pipeline/build.hpp"
#include "pipeline/catalogue_checks.hpp"
#include "polish/polish_mp.hpp"
#include "runner/runner.hpp"
#include "store/results_db.hpp"

namespace tripack::jobs {

namespace {

// What one value of n gives: its candidates, the builders' own verdicts, errors.
struct CandidatesOfN {
  std::vector<PackingRecord> candidates;
  std::vector<AtlasBuilderCheck> builders;
  std::vector<std::string> errors;
};

// The rattlers' places at the polish's digits (their long double places can overlap a neighbour
// by 1e-15 d when the cage is that narrow), then the polish's digits onto the record.
void centre_and_apply(PackingRecord& record, MultiprecisionPolish polish, long long n, int digits,
                      std::vector<std::string>& errors) {
  if (polish.converged && !record.pattern.rattlers.empty()) {
    const double room = centre_rattlers_multiprecision(polish, record.pattern.rattlers);
    if (room < -1e-25)
      errors.push_back(
          fmt::format("n = {}: a rattler overlaps its cage by {:.2g} d after centring at {} digits",
                      n, -room, digits));
  }
  pipeline::apply_multiprecision(record, polish);
}

void add_candidate(std::vector<PackingRecord>& all, PackingRecord c) {
  for (auto& existing : all)
    if (same_packing(existing, c)) return existing.merge_sources(c);
  all.push_back(std::move(c));
}

CandidatesOfN candidates_of(const Catalogue& catalogue, long long n,
                            const std::vector<PackingRecord>& stored,
                            const std::vector<BuildRequest>& members, int digits) {
  CandidatesOfN out;
  for (const auto& r : stored) {
    try {
      pipeline::AnalysisOptions options;
      options.digits = digits;
      const pipeline::Analysis analysis = pipeline::analyze_packing(r.pattern.packing, options);
      PackingRecord c = pipeline::record_of(analysis);
      c.sources = r.sources;
      if (analysis.multiprecision)
        centre_and_apply(c, *analysis.multiprecision, n, digits, out.errors);
      add_candidate(out.candidates, std::move(c));
    } catch (const std::exception& e) {
      out.errors.push_back(fmt::format("n = {}: stored packing {}: {}", n, r.label, e.what()));
    }
  }
  for (const auto& member : members) {
    const std::string name =
        pipeline::member_name({member.class_id, member.k, member.p, member.variant});
    try {
      pipeline::BuildSettings settings;
      settings.digits = digits;
      const pipeline::BuildResult built = pipeline::build_and_certify(catalogue, member, settings);
      PackingRecord c = built.record;
      const auto& polish = built.analysis ? built.analysis->multiprecision : built.multiprecision;
      out.builders.push_back({n, name, c.d.str(digits), c.certified, c.verdict, "", 0});
      if (polish) centre_and_apply(c, *polish, n, digits, out.errors);
      add_candidate(out.candidates, std::move(c));
    } catch (const std::exception& e) {
      out.errors.push_back(fmt::format("n = {}: builder {}: {}", n, name, e.what()));
    }
  }
  return out;
}

std::vector<std::string> builders_of(const PackingRecord& r) {
  std::vector<std::string> names;
  for (const auto& s : r.sources)
    if (s.kind == PackingSource::Kind::Builder) names.push_back(s.name);
  return names;
}

// What the database says of n: which independent unit ended in which stored packing, and the
// stored packings' d (read once, before the threads start).
struct UnitsOfN {
  std::vector<store::UnitOfPacking> units;
  std::map<long long, long double> d_of_packing;  // by packing id
};

// The provenance of a value of d: the builders and imported files of the candidates of that
// value, and the independent units that ended in a stored packing of it, by method ("search 20
// s: 2 (seeds 20002, 20007)"). Stored d carry fewer digits than the 30 of the polished
// candidates, so a stored packing is of the value within 1e-14 relative (distinct values of one n
// have never come closer than 8e-12: docs/atlas.md, "Confirmations").
std::string provenance_of(long double value, const std::vector<PackingRecord>& candidates,
                          const UnitsOfN& db) {
  const auto same = [&](long double d, long double tolerance) {
    return std::fabs(d - value) <= tolerance * value;
  };
  std::set<std::string> builders, imports;
  for (const auto& c : candidates)
    if (same(c.d.value(), kSameValueTolerance))
      for (const auto& source : c.sources) {
        if (source.kind == PackingSource::Kind::Builder) builders.insert(source.name);
        if (source.kind == PackingSource::Kind::Import) imports.insert(source.name);
      }
  std::vector<std::string> parts;
  for (const auto& b : builders) parts.push_back("builder " + b);
  for (const auto& i : imports) parts.push_back("import " + i);
  std::map<std::string, std::vector<std::uint64_t>> seeds;  // by method
  for (const auto& u : db.units) {
    const auto d = db.d_of_packing.find(u.packing_id);
    if (d != db.d_of_packing.end() && same(d->second, 1e-14L)) seeds[u.method].push_back(u.seed);
  }
  for (const auto& [method, list] : seeds) {
    std::string part =
        fmt::format("{}: {} (seed{} ", method, list.size(), list.size() == 1 ? "" : "s");
    for (std::size_t i = 0; i < std::min<std::size_t>(4, list.size()); ++i)
      part += (i ? ", " : "") + std::to_string(list[i]);
    parts.push_back(part + (list.size() > 4 ? ", ...)" : ")"));
  }
  std::string text;
  for (const auto& part : parts) text += (text.empty() ? "" : "; ") + part;
  return text;
}

// Ranks the certified candidates of n, labels them and keeps the best `keep`, each with the
// provenance of its value.
std::vector<PackingRecord> rows_of(long long n, std::vector<PackingRecord> candidates,
                                   std::size_t keep, std::vector<AtlasBuilderCheck>& builders,
                                   const UnitsOfN& db,
                                   std::map<std::string, std::string>& provenance) {
  std::vector<PackingRecord> certified;
  for (auto& c : candidates)
    if (c.certified) certified.push_back(std::move(c));
  rank_records(n, certified);
  count_value_confirmations(certified);  // d(n)'s, over every packing that has it
  std::vector<PackingRecord> rows;
  for (auto& c : certified) {
    const auto names = builders_of(c);
    for (auto& b : builders)
      if (std::find(names.begin(), names.end(), b.member) != names.end()) {
        b.label = c.label;
        b.rank = c.rank;
      }
    if (c.rank > keep) continue;
    c.file = "atlas/" + c.label + ".txt";
    rows.push_back(c);
  }
  for (const auto& row : rows) provenance[row.label] = provenance_of(row.d.value(), certified, db);
  return rows;
}

std::vector<AtlasGap> gaps_of(const Catalogue& catalogue, const std::vector<PackingRecord>& rows,
                              long long last) {
  std::map<long long, const PackingRecord*> best;
  for (const auto& r : rows)
    if (r.rank == 1) best[r.n()] = &r;
  std::vector<AtlasGap> gaps;
  std::set<std::tuple<std::string, long, long>> seen;
  for (const auto& m : pipeline::class_members_up_to(catalogue, last - 1)) {
    const long long n = catalogue.n_of(catalogue.find(m.class_id), m.k, m.p);
    if (!seen.insert({m.class_id, m.p, m.k}).second || !best.count(n) || !best.count(n + 1))
      continue;
    const PackingRecord& a = *best[n];
    const PackingRecord& b = *best[n + 1];
    AtlasGap g;
    g.class_id = m.class_id;
    g.k = m.k;
    g.p = m.p;
    g.n = n;
    g.label_n = a.label;
    g.label_next = b.label;
    g.L_n = a.L.value();
    g.L_next = b.L.value();
    g.delta_difference = std::stold(atlas_delta(b)) - std::stold(atlas_delta(a));
    g.claim_tight = catalogue.find(m.class_id).claim_tight;
    gaps.push_back(g);
  }
  std::stable_sort(gaps.begin(), gaps.end(), [](const AtlasGap& x, const AtlasGap& y) {
    return std::tie(x.class_id, x.p, x.k) < std::tie(y.class_id, y.p, y.k);
  });
  return gaps;
}

}  // namespace

std::string atlas_delta(const PackingRecord& row) {
  return oler_delta_from_L(row.L.str(), row.n());
}

AtlasResult build_atlas(const Catalogue& catalogue, const std::string& db_path,
                        const AtlasSettings& settings, const JobContext& job) {
  const auto start = Clock::now();
  AtlasResult result;
  result.settings = settings;
  result.db = db_path;
  const long long first = std::max(2LL, settings.n_first), last = settings.n_last;
  auto keep_of = [&](long long n) -> std::size_t {
    return n >= settings.ranked_first && n <= settings.ranked_last
               ? static_cast<std::size_t>(std::max(1, settings.ranked_count))
               : 1;
  };

  // Values of n on threads, largest first (the slowest start early), results by n.
  std::vector<long long> pending;
  for (long long n = last; n >= first; --n)
    if (settings.n_values.empty() ||
        std::find(settings.n_values.begin(), settings.n_values.end(), n) != settings.n_values.end())
      pending.push_back(n);

  // Everything read from the database first (one connection, one thread): the best few stored
  // packings of each n. Builders may add packings above them, so a few more than kept.
  std::map<long long, std::vector<PackingRecord>> stored;
  std::map<long long, UnitsOfN> units;
  {
    store::OpenOptions options;
    options.create = false;
    options.allow_read_only = true;
    const store::ResultsDb db = store::ResultsDb::open(db_path, options);
    for (long long n : pending) {
      auto ranked = ranked_packings(db, n);
      if (ranked.size() > keep_of(n) + 4) ranked.resize(keep_of(n) + 4);
      stored[n] = std::move(ranked);
      units[n].units = db.independent_units(n);
      for (const auto& p : db.packings(n)) units[n].d_of_packing[p.id] = std::stold(p.d);
    }
  }
  std::map<long long, std::vector<BuildRequest>> members;
  for (const auto& m : pipeline::class_members_up_to(catalogue, last)) {
    const long long n = catalogue.n_of(catalogue.find(m.class_id), m.k, m.p);
    if (n >= first) members[n].push_back(m);
  }

  // Values of n on the runner's threads, largest first (the slowest start early), results by n.
  std::map<long long, CandidatesOfN> outcomes;
  std::vector<CandidatesOfN> found(pending.size());
  ProgressCounter counter("atlas", static_cast<long long>(pending.size()));
  JobItems items;
  items.count = pending.size();
  items.run = [&](std::size_t i) {
    const long long n = pending[i];
    const auto m = members.find(n);  // (no operator[]: the map is shared by the threads)
    found[i] = candidates_of(catalogue, n, stored.at(n),
                             m == members.end() ? std::vector<BuildRequest>{} : m->second,
                             settings.digits);
    return std::string();
  };
  items.finished = [&](std::size_t i, const std::string&) {
    outcomes[pending[i]] = std::move(found[i]);
    job.report(counter.finished(fmt::format("n = {}", pending[i])));
  };
  result.cancelled = ThreadExecutor(settings.threads).run_items(items, job.cancel).cancelled;

  for (auto& [n, outcome] : outcomes) {
    result.errors.insert(result.errors.end(), outcome.errors.begin(), outcome.errors.end());
    auto rows = rows_of(n, std::move(outcome.candidates), keep_of(n), outcome.builders, units.at(n),
                        result.provenance);
    if (rows.empty()) result.missing.push_back(n);
    for (auto& row : rows) {
      if (!row.d.multiprecision())
        result.errors.push_back(fmt::format("n = {}: {}: the {}-digit polish did not converge", n,
                                            row.label, settings.digits));
      result.rows.push_back(std::move(row));
    }
    result.builders.insert(result.builders.end(), outcome.builders.begin(), outcome.builders.end());
  }
  result.gaps = gaps_of(catalogue, result.rows, last);
  result.seconds = seconds_since(start);
  return result;
}

}  // namespace tripack::jobs
