#include "campaign/atlas.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <thread>
#include <tuple>

#include "analysis/compare.hpp"
#include "campaign/stored.hpp"
#include "core/conventions.hpp"
#include "core/io.hpp"
#include "pipeline/billiards_search.hpp"
#include "pipeline/build.hpp"
#include "pipeline/explore.hpp"
#include "polish/polish_mp.hpp"
#include "store/results_db.hpp"

namespace tripack::campaign {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A packing competing for the atlas rows of its n, certified and polished here.
struct Candidate {
  Pattern pattern;
  std::optional<MultiprecisionPolish> polish;
  bool certified = false;
  std::string verdict;
  std::vector<std::string> builders;
  std::string stored_source;  // "billiards seed S (R runs)" or "import FILE"
  std::uint64_t seed = std::numeric_limits<std::uint64_t>::max();  // ties: first seed first
  long long runs = 0;
  std::string hash;
};

// What one value of n gives: its candidates, the builders' own verdicts, errors.
struct CandidatesOfN {
  std::vector<Candidate> candidates;
  std::vector<AtlasBuilderCheck> builders;
  std::vector<std::string> errors;
};

std::string polished_d(const Candidate& c) {
  if (c.polish && c.polish->converged) return c.polish->d;
  return format_significant(c.pattern.packing.d, 18);
}

// Same packing: the same contact graph (up to the 6 symmetries) and d to 12 digits, the key
// the database deduplicates by.
bool same_packing(const Candidate& a, const Candidate& b) {
  return a.hash == b.hash && std::fabs(a.pattern.packing.d / b.pattern.packing.d - 1) < 1e-12L;
}

void add_candidate(std::vector<Candidate>& all, Candidate c) {
  for (auto& existing : all) {
    if (!same_packing(existing, c)) continue;
    existing.builders.insert(existing.builders.end(), c.builders.begin(), c.builders.end());
    if (existing.stored_source.empty()) {
      existing.stored_source = c.stored_source;
      existing.seed = c.seed;
      existing.runs = c.runs;
    }
    return;
  }
  all.push_back(std::move(c));
}

Candidate analysed(const Pattern& start, int digits) {
  pipeline::AnalysisOptions options;
  options.digits = digits;
  const pipeline::Analysis analysis = pipeline::analyze_packing(start.packing, options);
  Candidate c;
  c.pattern = analysis.pattern;
  c.polish = analysis.multiprecision;
  c.certified = analysis.certified();
  c.verdict = analysis.status();
  c.hash = contact_graph_hash(c.pattern);
  return c;
}

CandidatesOfN candidates_of(const Catalogue& catalogue, long long n,
                            const std::vector<RankedPacking>& stored,
                            const std::vector<BuildRequest>& members, int digits) {
  CandidatesOfN out;
  for (const auto& r : stored) {
    const auto& p = r.packing;
    try {
      Candidate c = analysed(pattern_of(p), digits);
      c.stored_source = p.origin == "import"
                            ? "import " + p.source
                            : fmt::format("billiards seed {} ({} run{})", p.first_seed, p.runs,
                                          p.runs == 1 ? "" : "s");
      if (p.has_seed) c.seed = p.first_seed;
      c.runs = p.runs;
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
      Candidate c;
      if (built.analysis) {
        c.pattern = built.analysis->pattern;
        c.polish = built.analysis->multiprecision;
        c.certified = built.analysis->certified();
        c.verdict = built.analysis->status();
      } else {
        c.pattern = built.pattern;
        c.polish = built.multiprecision;
        c.verdict = "not certified (certification skipped)";
      }
      c.hash = contact_graph_hash(c.pattern);
      c.builders.push_back(name);
      out.builders.push_back({n, name, polished_d(c), c.certified, c.verdict, "", 0});
      add_candidate(out.candidates, std::move(c));
    } catch (const std::exception& e) {
      out.errors.push_back(fmt::format("n = {}: builder {}: {}", n, name, e.what()));
    }
  }
  // The rattlers' places at the polish's digits (their long double places can overlap a
  // neighbour by 1e-15 d when the cage is that narrow).
  for (auto& c : out.candidates)
    if (c.polish && c.polish->converged && !c.pattern.rattlers.empty()) {
      const double room = centre_rattlers_multiprecision(*c.polish, c.pattern.rattlers);
      if (room < -1e-25)
        out.errors.push_back(fmt::format(
            "n = {}: a rattler overlaps its cage by {:.2g} d after centring at {} digits", n, -room,
            digits));
    }
  return out;
}

std::string joined(const std::vector<std::string>& parts, const std::string& separator) {
  std::string s;
  for (const auto& p : parts) s += (s.empty() ? "" : separator) + p;
  return s;
}

// Ranks the certified candidates of n, labels them and keeps the best `keep`.
std::vector<AtlasRow> rows_of(long long n, std::vector<Candidate> candidates, std::size_t keep,
                              std::vector<AtlasBuilderCheck>& builders) {
  std::vector<Candidate> certified;
  for (auto& c : candidates)
    if (c.certified) certified.push_back(std::move(c));
  std::vector<pipeline::RankKey> keys;
  std::vector<std::uint64_t> seeds;
  for (const auto& c : certified) {
    keys.push_back({c.pattern.packing.d, c.pattern.bonds.size()});
    seeds.push_back(c.seed);
  }
  const auto order = pipeline::label_order(keys, seeds);
  std::vector<pipeline::RankKey> sorted;
  for (std::size_t i : order) sorted.push_back(keys[i]);
  const auto labels = pipeline::paper_labels(n, sorted);
  std::vector<AtlasRow> rows;
  for (std::size_t r = 0; r < order.size(); ++r) {
    Candidate& c = certified[order[r]];
    for (auto& b : builders)
      if (std::find(c.builders.begin(), c.builders.end(), b.member) != c.builders.end()) {
        b.label = labels[r];
        b.rank = r + 1;
      }
    if (r >= keep) continue;
    AtlasRow row;
    row.n = n;
    row.rank = r + 1;
    row.label = labels[r];
    row.pattern = c.pattern;
    row.certified = true;
    row.verdict = c.verdict;
    row.builders = c.builders;
    row.runs = c.runs;
    std::vector<std::string> sources;
    if (!c.builders.empty()) sources.push_back("builder " + joined(c.builders, " = "));
    if (!c.stored_source.empty()) sources.push_back(c.stored_source);
    row.source = joined(sources, "; ");
    if (c.polish && c.polish->converged) {
      row.d = c.polish->d;
      row.L = c.polish->L;
      row.points = c.polish->points;
    } else {  // reported by build_atlas as an error: the row has long double digits only
      row.d = format_significant(c.pattern.packing.d, 18);
      row.L = format_significant(1 / c.pattern.packing.d, 18);
    }
    row.delta = oler_delta_from_L(row.L, n);
    row.file = "atlas/" + row.label + ".txt";
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<AtlasGap> gaps_of(const Catalogue& catalogue, const std::vector<AtlasRow>& rows,
                              long long last) {
  std::map<long long, const AtlasRow*> best;
  for (const auto& r : rows)
    if (r.rank == 1) best[r.n] = &r;
  std::vector<AtlasGap> gaps;
  std::set<std::tuple<std::string, long, long>> seen;
  for (const auto& m : pipeline::class_members_up_to(catalogue, last - 1)) {
    const long long n = catalogue.n_of(catalogue.find(m.class_id), m.k, m.p);
    if (!seen.insert({m.class_id, m.p, m.k}).second || !best.count(n) || !best.count(n + 1))
      continue;
    const AtlasRow& a = *best[n];
    const AtlasRow& b = *best[n + 1];
    AtlasGap g;
    g.class_id = m.class_id;
    g.k = m.k;
    g.p = m.p;
    g.n = n;
    g.label_n = a.label;
    g.label_next = b.label;
    g.L_n = std::stold(a.L);
    g.L_next = std::stold(b.L);
    g.delta_difference = std::stold(b.delta) - std::stold(a.delta);
    g.claim_tight = catalogue.find(m.class_id).claim_tight;
    gaps.push_back(g);
  }
  std::stable_sort(gaps.begin(), gaps.end(), [](const AtlasGap& x, const AtlasGap& y) {
    return std::tie(x.class_id, x.p, x.k) < std::tie(y.class_id, y.p, y.k);
  });
  return gaps;
}

}  // namespace

AtlasResult build_atlas(const Catalogue& catalogue, const std::string& db_path,
                        const AtlasSettings& settings, const std::atomic<bool>* cancel,
                        const std::function<void(const AtlasProgress&)>& progress) {
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
  std::map<long long, std::vector<RankedPacking>> stored;
  {
    store::OpenOptions options;
    options.create = false;
    options.allow_read_only = true;
    const store::ResultsDb db = store::ResultsDb::open(db_path, options);
    for (long long n : pending) {
      auto ranked = ranked_packings(db, n);
      if (ranked.size() > keep_of(n) + 4) ranked.resize(keep_of(n) + 4);
      stored[n] = std::move(ranked);
    }
  }
  std::map<long long, std::vector<BuildRequest>> members;
  for (const auto& m : pipeline::class_members_up_to(catalogue, last)) {
    const long long n = catalogue.n_of(catalogue.find(m.class_id), m.k, m.p);
    if (n >= first) members[n].push_back(m);
  }

  std::map<long long, CandidatesOfN> outcomes;
  std::mutex lock;
  std::size_t next = 0;
  long long done = 0;
  auto worker = [&] {
    for (;;) {
      long long n = 0;
      {
        std::lock_guard<std::mutex> guard(lock);
        if (next >= pending.size() || (cancel && *cancel)) return;
        n = pending[next++];
      }
      CandidatesOfN outcome = candidates_of(catalogue, n, stored[n], members[n], settings.digits);
      std::lock_guard<std::mutex> guard(lock);
      outcomes[n] = std::move(outcome);
      ++done;
      if (progress)
        progress({n, done, static_cast<long long>(pending.size()), seconds_since(start)});
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::max(1, settings.threads); ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  result.interrupted = static_cast<std::size_t>(done) < pending.size();

  for (auto& [n, outcome] : outcomes) {
    result.errors.insert(result.errors.end(), outcome.errors.begin(), outcome.errors.end());
    auto rows = rows_of(n, std::move(outcome.candidates), keep_of(n), outcome.builders);
    if (rows.empty()) result.missing.push_back(n);
    for (auto& row : rows) {
      if (row.points.empty())
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

}  // namespace tripack::campaign
