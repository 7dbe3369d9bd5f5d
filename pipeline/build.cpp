#include "pipeline/build.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "core/io.hpp"
#include "core/timing.hpp"
#include "analysis/compare.hpp"

namespace tripack::pipeline {

bool BuildResult::verified() const {
  return analysis && counts_match() && bonds_match() && rattlers_match() && analysis->certified() &&
         (!exact || exact->ok);
}

namespace {

PackingRecord record_of_build(const BuildResult& b) {
  PackingRecord record;
  if (b.analysis) {
    record = record_of(*b.analysis);
  } else {
    record = PackingRecord::of(b.pattern);
    if (b.multiprecision) apply_multiprecision(record, *b.multiprecision);
    record.verdict = "not certified (certification skipped)";
    identify(record);
  }
  record.pattern.provenance = b.pattern.provenance;
  record.sources.push_back({PackingSource::Kind::Builder, member_name(b.pattern.provenance)});
  record.seconds = b.seconds();
  return record;
}

}  // namespace

double BuildResult::seconds() const {
  return times.construct + polish_seconds + times.exact + times.multiprecision +
         (analysis ? analysis->times.total() : 0.0);
}

BuildResult build_and_certify(const Catalogue& catalogue, const BuildRequest& request,
                              const BuildSettings& settings) {
  BuildResult b;
  b.digits = settings.digits;
  auto tell = [&](const char* stage) {
    if (!settings.progress) return;
    Progress p;
    p.stage = stage;
    settings.progress(p);
  };
  tell("construct");
  b.pattern = timed(b.times.construct, [&] { return build_pattern(catalogue, request); });
  if (settings.polish) {
    tell("polish of the builder's bonds");
    b.polish = timed(b.polish_seconds, [&] {
      return polish_bond_system(b.pattern.packing, b.pattern.bonds, b.pattern.rattlers);
    });
    b.polished = true;
    if (!b.polish.converged)
      throw std::runtime_error(
          fmt::format("polish did not converge (residual {:.3g} after {} iterations)",
                      static_cast<double>(b.polish.max_residual), b.polish.iterations));
  }
  if (b.pattern.exact) tell("exact check");
  if (b.pattern.exact) b.exact = timed(b.times.exact, [&] { return exact_check(b.pattern); });
  const bool certify =
      settings.certify && settings.polish && b.pattern.packing.size() <= kCertifyLimit;
  b.certify_skipped = settings.certify && !certify;
  if (certify) {
    AnalysisOptions options;
    options.digits = settings.digits;
    options.progress = settings.progress;
    b.analysis = analyze_packing(b.pattern.packing, options);
  } else if (settings.digits > kLongDoubleDigits) {
    tell("multiprecision polish");
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
  return b;
}

BestBuild build_best_for_n(const Catalogue& catalogue, long long n, const BuildSettings& settings) {
  const auto members = catalogue.classify(n);
  if (members.empty())
    throw std::runtime_error("no class of the catalogue contains n = " + std::to_string(n));
  BestBuild result;
  BuildSettings quick = settings;
  quick.certify = false;  // rank the candidates first, certify only the winner
  quick.digits = 15;
  std::optional<BuildCandidate> best;
  // Every variant: the default is not always the best (odd-ripple's other modification wins at
  // k = 2..4, its depressed cage from k = 5); equal d keeps the first (the default).
  for (const auto& m : members) {
    std::vector<std::string> variants = catalogue.variants_at(*m.cls, m.k);
    if (variants.empty()) variants.push_back("");
    const std::string first = catalogue.resolve_variant(*m.cls, m.k, "");
    std::stable_partition(variants.begin(), variants.end(),
                          [&](const std::string& v) { return v == first; });
    for (const auto& v : variants) {
      const BuildResult b = build_and_certify(catalogue, {m.cls->id, m.k, m.p, v}, quick);
      result.candidates.push_back({b.pattern.provenance, b.pattern.packing.d});
      if (!best || b.pattern.packing.d > best->d) best = result.candidates.back();
    }
  }
  const Provenance& win = best->member;
  result.best = build_and_certify(catalogue, {win.class_id, win.k, win.p, win.variant}, settings);
  return result;
}

std::string member_name(const Provenance& member) {
  std::string s = member.class_id + " k=" + std::to_string(member.k);
  if (member.p) s += " p=" + std::to_string(member.p);
  if (!member.variant.empty()) s += " variant=" + member.variant;
  return s;
}

}  // namespace tripack::pipeline
