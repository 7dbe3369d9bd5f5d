// Build + polish + certify a class member (docs/certified.md steps 1-4), and the catalogue's best
// member for a given n. Returns results; prints nothing.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/sqrt3_check.hpp"
#include "constructors/catalogue.hpp"
#include "constructors/registry.hpp"
#include "core/options.hpp"
#include "pipeline/analyze.hpp"
#include "polish/polish.hpp"
#include "polish/polish_mp.hpp"

namespace tripack::pipeline {

struct BuildSettings {
  int digits = 15;          // > kLongDoubleDigits: MPFR polish to this many digits
  bool polish = true;       // Newton on the builder's bond system
  bool certify = true;      // relax, bonds, rigidity, stress from the geometry (needs the polish)
  bool exhaustive = false;  // enumerating builders relax every candidate (BuildControl)
  int threads = 2;          // an enumeration's candidates relaxed at once (BuildControl)

  void declare(OptionList& o) {
    o.option("--digits", digits, "significant digits of d (above 18: MPFR polish)")
        .range(1, 100000);
    o.flag("!--no-polish", polish, "skip the Newton polish of the bond system");
    o.flag("!--no-certify", certify, "skip relax/bonds/rigidity/stress from the geometry");
    o.flag("--exhaustive", exhaustive,
           "relax every candidate of an enumerating class (vacancy segments) fully, not only "
           "those its fast ranking keeps");
    o.option("--threads", threads, "candidates of an enumerating class relaxed at once")
        .range(1, 256);
  }
};

inline constexpr long kUnsetK = -1000000000;  // --k not given (0 and negatives are user errors)

// A class member's options: the class, --k, --p, --variant (the commands' and the Python
// module's).
inline void declare_member(OptionList& o, BuildRequest& member, bool class_required) {
  auto& c = o.option("class", member.class_id, "class id (see 'tripack classes')");
  if (class_required) c.required();
  o.option("--k", member.k, "class index k").shown_default("");
  o.option("--p", member.p, "matrix row p").range(1, 1e9);
  o.option("--variant", member.variant, "variant (e.g. rattler, cavity-1, full)");
}

// The whole pipeline on a class member: construct, polish the builder's bond system, verify
// closed forms exactly, then certify from the geometry alone and compare with what the builder
// intended.
// The largest member a build takes on (memory: docs/performance.md, "10^6 disks").
inline constexpr long long kMaxBuildDisks = 2'000'000;

struct BuildResult {
  Pattern pattern;  // as constructed, polished with the builder's bonds
  PolishReport polish;
  bool polished = false;
  std::optional<Sqrt3CheckReport> sqrt3;
  std::optional<Analysis> analysis;
  std::optional<MultiprecisionPolish> multiprecision;  // of the builder's bond system
  StageTimes times;  // construct, exact and (without analysis) multiprecision
  double polish_seconds = 0;
  std::optional<long long> bonds_expected, rattlers_expected;  // the catalogue's counts
  bool certify_skipped = false;
  std::string certify_error;  // why the certificate failed (then no analysis); empty: it did not
  int digits = 15;
  // What the build gives, whichever stages ran: the certified geometry when certified (else the
  // builder's pattern), d and the coordinates to every digit known, the builder as its source.
  // Callers use this, not the stages' own patterns and polishes.
  PackingRecord record;

  bool bonds_match() const { return analysis && analysis->pattern.bonds == pattern.bonds; }
  bool rattlers_match() const { return analysis && analysis->pattern.rattlers == pattern.rattlers; }
  bool counts_match() const {
    return !bonds_expected || static_cast<long long>(pattern.bonds.size()) == *bonds_expected;
  }
  // Everything this build claims holds: catalogue counts, geometry equals the builder's, the
  // certificate, the exact check where one ran.
  bool verified() const;
  std::string d_string(int digits) const { return record.d.str(digits); }
  double seconds() const;  // every stage
};

// A build is one item: progress reports each stage's start (construct, polish, exact check, the
// analysis'); cancelled, it stops at its next check (between a construction's relaxes, between
// build --n's candidates and stages) by throwing Cancelled, and nothing is built.
BuildResult build_and_certify(const Catalogue& catalogue, const BuildRequest& request,
                              const BuildSettings& settings, const JobContext& job = {});

// A candidate of `build --n`: a catalogue member containing n, built and polished.
struct BuildCandidate {
  Provenance member;
  long double d = 0;
  std::string error;  // why its construction failed (then d = 0 and it is not ranked)
};
struct BestBuild {
  BuildResult best;
  std::vector<BuildCandidate>
      candidates;  // every member and variant containing n, in catalogue order
  // The next densest candidates' packings as built and polished (at most 3), densest first:
  // where a search starts besides the winner (search/search.hpp).
  std::vector<Packing> runners_up;
};
// Builds every member of the catalogue containing n without certificates, then the one with the
// largest d with `settings`. Throws std::runtime_error when no class contains n.
BestBuild build_best_for_n(const Catalogue& catalogue, long long n, const BuildSettings& settings,
                           const JobContext& job = {});

// `tripack build`: the member asked for, or with n > 0 the best for n. Throws
// std::invalid_argument for a request that is neither (no class, no --k) or both.
BestBuild build_requested(const Catalogue& catalogue, const BuildRequest& member, long long n,
                          const BuildSettings& settings, const JobContext& job = {});

std::string member_name(const Provenance& member);  // "matrix k=2 p=7 variant=..."
// The same in a file name: "matrix-k2-p7-..." (docs/conventions.md, "Names").
std::string member_file_stem(const Provenance& member);

}  // namespace tripack::pipeline
