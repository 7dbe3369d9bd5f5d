#include "pipeline/build.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/compare.hpp"
#include "core/io.hpp"
#include "core/timing.hpp"

namespace tripack::pipeline {

// Verified: every claim of the build holds. When the multiprecision certificate identified the
// bonds (docs/certified.md, "The multiprecision certificate"), the geometry's bonds are the ones
// to trust: the builder's bond list comes from long double contact detection, which cannot tell
// a bond from a gap of 1e-11 d. Then the builder's bonds need not equal them but must all be
// contacts of the certified configuration (none open at its precision: the builder built this
// packing, and may only have missed contacts its own polish implies); the builder's d must be
// the certified one (kSameDTolerance); and the catalogue's expected counts apply to the
// certified bonds and rattlers. Otherwise the geometry's bonds and rattlers must equal the
// builder's, and the catalogue's counts apply to the builder's.
bool BuildResult::verified() const {
  if (!analysis || !analysis->certified() || (sqrt3 && !sqrt3->ok)) return false;
  const auto& precise = analysis->precise;
  if (!precise) return counts_match() && bonds_match() && rattlers_match();
  const Pattern& geometry = analysis->pattern;
  const bool counts =
      (!bonds_expected || static_cast<long long>(geometry.bonds.size()) == *bonds_expected) &&
      (!rattlers_expected ||
       static_cast<long long>(geometry.rattlers.size()) == *rattlers_expected);
  const long double d = pattern.packing.d, certified_d = geometry.packing.d;
  return counts && precise->reference_open == 0 &&
         std::fabs(d - certified_d) <= kSameDTolerance * certified_d;
}

namespace {

PackingRecord record_of_build(const BuildResult& b) {
  PackingRecord record;
  if (b.analysis) {
    record = record_of(*b.analysis);
  } else {
    record = PackingRecord::of(b.pattern);
    if (b.multiprecision) apply_multiprecision(record, *b.multiprecision);
    record.verdict = b.certify_error.empty()
                         ? "not certified (certification skipped)"
                         : "not certified: the certificate failed: " + b.certify_error;
    identify(record);
  }
  record.pattern.provenance = b.pattern.provenance;
  record.sources.push_back({PackingSource::Kind::Builder, member_name(b.pattern.provenance)});
  record.seconds = b.seconds();
  return record;
}

}  // namespace

double BuildResult::seconds() const {
  return times.construct + polish_seconds + times.sqrt3 + times.multiprecision +
         (analysis ? analysis->times.total() : 0.0);
}

namespace {

void tell_stage(const JobContext& job, const char* stage) {
  Progress p;
  p.stage = stage;
  job.report(p);
}

// Construct, polish the builder's bonds, the exact check: what every candidate of build --n needs.
BuildResult construct_member(const Catalogue& catalogue, const BuildRequest& request,
                             const BuildSettings& settings, const JobContext& job) {
  // Refused before any allocation: a member of a million disks took 7 to 19 GB
  // (docs/performance.md, "10^6 disks"), so a k far beyond that is one line, not an abort.
  const long long n = catalogue.n_of(catalogue.find(request.class_id), request.k, request.p);
  if (n > kMaxBuildDisks)
    throw std::invalid_argument(fmt::format(
        "{} k={}{} has {} disks; a build handles at most {} (about 20 GB per million disks)",
        request.class_id, request.k, request.p ? fmt::format(" p={}", request.p) : "", n,
        kMaxBuildDisks));
  BuildResult b;
  tell_stage(job, "construct");
  b.pattern = timed(b.times.construct, [&] {
    return build_pattern(catalogue, request,
                         {job.progress, job.cancel, settings.exhaustive, settings.threads});
  });
  throw_if_cancelled(job.cancel);
  if (settings.polish) {
    tell_stage(job, "polish of the builder's bonds");
    b.polish = timed(b.polish_seconds, [&] {
      return polish_bond_system(b.pattern.packing, b.pattern.bonds, b.pattern.rattlers);
    });
    b.polished = true;
    if (!b.polish.converged)
      throw std::runtime_error(
          fmt::format("polish did not converge (residual {:.3g} after {} iterations)",
                      static_cast<double>(b.polish.max_residual), b.polish.iterations));
  }
  if (b.pattern.sqrt3) tell_stage(job, "Q(sqrt3) check");
  if (b.pattern.sqrt3) b.sqrt3 = timed(b.times.sqrt3, [&] { return sqrt3_check(b.pattern); });
  return b;
}

// The rest with `settings`: certificate (or the multiprecision polish alone), counts, record.
void finish_build(const Catalogue& catalogue, BuildResult& b, const BuildSettings& settings,
                  const JobContext& job) {
  b.digits = settings.digits;
  // At any n: the LP-free certificate is near-linear (docs/performance.md: 10^6 disks), and a
  // member it declines is not handed to LPs above AnalysisOptions::lp_limit.
  const bool certify = settings.certify && settings.polish;
  b.certify_skipped = settings.certify && !certify;
  if (certify) {
    AnalysisOptions options;
    options.digits = settings.digits;
    // Where the geometry's bonds differ from these, the multiprecision certificate decides.
    options.reference_bonds = b.pattern.bonds;
    options.reference_rattlers = b.pattern.rattlers;
    // The analysis reports every stage and relax step: there it also stops when cancelled.
    if (job.progress || job.cancel)
      options.progress = [&job](const Progress& p) {
        throw_if_cancelled(job.cancel);
        job.report(p);
      };
    // A certificate that fails (CLP giving up on a relax step: 263's jogged-line winner) leaves
    // the built packing uncertified with the reason, rather than losing it.
    try {
      b.analysis = analyze_packing(b.pattern.packing, options);
    } catch (const std::runtime_error& e) {
      b.certify_error = e.what();
    }
  } else if (settings.digits > kLongDoubleDigits) {
    tell_stage(job, "multiprecision polish");
    b.multiprecision = timed(b.times.multiprecision, [&] {
      return polish_multiprecision(b.pattern.packing, b.pattern.bonds, b.pattern.rattlers,
                                   settings.digits);
    });
  }
  const auto& info = catalogue.find(b.pattern.provenance.class_id);
  const auto& pv = b.pattern.provenance;
  b.bonds_expected = info.rigid ? catalogue.bonds_of(info, pv.k, pv.p, pv.variant) : std::nullopt;
  b.rattlers_expected = catalogue.rattlers_of(info, pv.k, pv.p, pv.variant);
  b.record = record_of_build(b);
}

// Ranks candidates like the atlas's labels (docs/conventions.md): larger d first; the same d
// (relative 1e-15: polished candidates agree to ~1e-19, distinct packings of one n differ by
// 1e-12 or more in the atlas) with more bonds first (twin's full packing over its rattler one).
bool denser_or_more_bonded(const Pattern& a, const Pattern& b) {
  const long double da = a.packing.d, db = b.packing.d;
  if (std::fabs(da - db) <= 1e-15L * db) return a.bonds.size() > b.bonds.size();
  return da > db;
}

}  // namespace

BuildResult build_and_certify(const Catalogue& catalogue, const BuildRequest& request,
                              const BuildSettings& settings, const JobContext& job) {
  BuildResult b = construct_member(catalogue, request, settings, job);
  finish_build(catalogue, b, settings, job);
  return b;
}

BestBuild build_best_for_n(const Catalogue& catalogue, long long n, const BuildSettings& settings,
                           const JobContext& job) {
  const auto members = catalogue.classify(n);
  if (members.empty())
    throw std::runtime_error("no class of the catalogue contains n = " + std::to_string(n));
  BestBuild result;
  // Rank the candidates as built and polished; only the winner is certified (its construction,
  // an enumeration for some classes, is not repeated).
  std::optional<BuildResult> best;
  std::vector<Packing> others;  // every candidate built but the best so far
  // Every variant: the default is not always the best (odd-ripple's other modification wins at
  // k = 2..4, its depressed cage from k = 5); equal d keeps the first (the default).
  for (const auto& m : members) {
    std::vector<std::string> variants = catalogue.variants_at(*m.cls, m.k);
    if (variants.empty()) variants.push_back("");
    const std::string first = catalogue.resolve_variant(*m.cls, m.k, "");
    std::stable_partition(variants.begin(), variants.end(),
                          [&](const std::string& v) { return v == first; });
    for (const auto& v : variants) {
      throw_if_cancelled(job.cancel);
      BuildResult b;
      try {
        b = construct_member(catalogue, {m.cls->id, m.k, m.p, v}, settings, job);
      } catch (const std::runtime_error& e) {
        // A member whose construction fails (an inflated-segment base that does not round onto
        // its lattice) is no candidate; the others still are.
        result.candidates.push_back({{m.cls->id, m.k, m.p, v}, 0, e.what()});
        if (!best && &m == &members.back() && &v == &variants.back()) throw;
        continue;
      }
      result.candidates.push_back({b.pattern.provenance, b.pattern.packing.d, ""});
      if (!best || denser_or_more_bonded(b.pattern, best->pattern)) {
        if (best) others.push_back(best->pattern.packing);
        best = std::move(b);
      } else {
        others.push_back(b.pattern.packing);
      }
    }
  }
  if (!best)
    throw std::runtime_error("no member of the catalogue containing n = " + std::to_string(n) +
                             " could be built");
  std::stable_sort(others.begin(), others.end(),
                   [](const Packing& a, const Packing& b) { return a.d > b.d; });
  if (others.size() > 3) others.resize(3);
  result.runners_up = std::move(others);
  throw_if_cancelled(job.cancel);
  finish_build(catalogue, *best, settings, job);
  result.best = std::move(*best);
  return result;
}

std::string member_file_stem(const Provenance& member) {
  std::string s = member.class_id + "-k" + std::to_string(member.k);
  if (member.p) s += "-p" + std::to_string(member.p);
  if (!member.variant.empty()) s += "-" + member.variant;
  return s;
}

std::string member_name(const Provenance& member) {
  std::string s = member.class_id + " k=" + std::to_string(member.k);
  if (member.p) s += " p=" + std::to_string(member.p);
  if (!member.variant.empty()) s += " variant=" + member.variant;
  return s;
}

BestBuild build_requested(const Catalogue& catalogue, const BuildRequest& member, long long n,
                          const BuildSettings& settings, const JobContext& job) {
  if (n) {
    if (!member.class_id.empty() || member.k != kUnsetK || member.p)
      throw std::invalid_argument("build --n N takes no class, --k or --p");
    return build_best_for_n(catalogue, n, settings, job);
  }
  if (member.class_id.empty()) throw std::invalid_argument("build needs a class (or --n N)");
  if (member.k == kUnsetK) throw std::invalid_argument("build needs --k K");
  BestBuild result;
  result.best = build_and_certify(catalogue, member, settings, job);
  return result;
}

}  // namespace tripack::pipeline
