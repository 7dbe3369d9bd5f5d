// The analysis pipeline (docs/certified.md): relax -> bonds (+ polish) -> rattlers -> rigidity ->
// stress
// -> optional multiprecision, with the time of each stage. `build`, `analyze` and the billiards
// search all use it.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analysis/bonds.hpp"
#include "analysis/certify.hpp"
#include "analysis/interior_relax.hpp"
#include "analysis/relax.hpp"
#include "core/conventions.hpp"
#include "core/io.hpp"
#include "core/options.hpp"
#include "core/packing.hpp"
#include "core/progress.hpp"
#include "core/record.hpp"
#include "polish/polish_mp.hpp"

namespace tripack::pipeline {

struct StageTimes {
  double construct = 0, relax = 0, bonds = 0, rigidity = 0, stress = 0, multiprecision = 0,
         sqrt3 = 0;
  double certificate_mp = 0;  // the multiprecision certificate (identification and certificate)
  double total() const {
    return construct + relax + bonds + rigidity + stress + multiprecision + sqrt3 + certificate_mp;
  }
};

struct AnalysisOptions {
  int digits = 15;  // > kLongDoubleDigits: polish in MPFR to this many digits
  // From this many disks, a start that does not certify as it is is first moved by the
  // interior-point relax; the LP relax runs (from the start) only if that result does not
  // certify either. Below it the LP relax is fast (n = 254: 0.1 s) and decides alone.
  std::size_t interior_from = 500;
  InteriorRelaxOptions interior;
  // Above this many disks a state that neither certifies as it is nor after the interior-point
  // relax is not handed to the LPs (a billiards end state at n = 5000: the LP relax took over
  // N min); it is reported "not certified" with the LP-free certificate's reason.
  std::size_t lp_limit = 3000;
  // A long analysis says what it is doing (the pipeline prints nothing): a stage's start and, in
  // relax, every step (Progress::step) with the current d.
  ProgressFn progress;
  // The bonds and rattlers a caller expects (a builder's). When the geometry's differ, the
  // multiprecision certificate decides, and reports which of these bonds are contacts of the
  // configuration it certifies.
  std::optional<std::vector<Bond>> reference_bonds;
  std::optional<std::vector<int>> reference_rattlers;
  // The multiprecision certificate (docs/certified.md) runs when the double-precision one
  // declines or cannot resolve its own margins; false: never.
  bool multiprecision_certificate = true;
};

// The multiprecision certificate's stage (docs/certified.md, "The multiprecision certificate"):
// bonds and rattlers identified on a configuration polished in MPFR, then rigidity and a strictly
// positive stress at that precision, with the margins it resolved.
struct PreciseStage {
  std::string reason;  // why it ran: what double precision could not resolve
  int digits = 0;      // MPFR digits (chosen from the smallest gap double precision saw)
  int attempts = 0;    // 2 when the first digits did not resolve the margins
  // The deep relax first run (LP steps until a step gains less than 1e-18 relative, long
  // double's resolution, instead of relax's 1e-13): where relax stops, contacts with forces of
  // 1e-10 can still be 1e-7 d open.
  RelaxReport deep_relax;
  bool deep_relaxed = false;  // it ran (not above lp_limit disks)
  double deep_relax_seconds = 0;
  PreciseIdentification identification;
  MultiprecisionCertificate certificate;
  long double smallest_gap = 0;  // smallest non-bond gap between held disks, units of d (MPFR)
  Bond smallest_gap_contact;
  long double gap_floor = 0;  // the precision's floor: max(10^-digits, the bonds' own |gap|)
  // Reference (builder's) bonds that are not contacts of the certified configuration (gap above
  // the closed threshold); -1 without a reference.
  int reference_open = -1;
  // Without a bond set: the deep-relaxed state's contacts (the gaps below the widest jump
  // between consecutive gaps), the widest of them and the next gap; 0 when not looked at.
  int contacts = 0;
  long double contact_gap = 0, next_gap = 0;
  double seconds = 0;
  bool certified = false;
  std::string declined;  // why not, when !certified
};

struct Analysis {
  Pattern pattern;  // the polished packing with the identified bonds and rattlers
  RelaxReport relax;
  BondIdentification identification;
  RigidityReport rigidity;
  StressReport stress;
  FastCertificate fast;  // the LP-free certificate of the final state (the LPs ran if declined)
  // The interior-point relax, when it ran (n >= interior_from and the start did not certify).
  // If its result did not certify, the LP relax decided and this keeps what it reached.
  std::optional<InteriorRelaxReport> interior;
  bool lps_skipped = false;  // n > lp_limit: the result is the interior-point relax's
  std::size_t lp_limit = 0;  // (for the verdict's wording)
  std::optional<MultiprecisionPolish> multiprecision;
  std::vector<Gap> gaps;  // the 64 smallest non-bond gaps (near contacts and rattlers' play)
  // The multiprecision certificate, when it ran. Its verdict is the analysis' verdict then, and
  // when it certified, pattern, stress and gaps are its own (pattern.packing its coordinates
  // rounded to long double).
  std::optional<PreciseStage> precise;
  StageTimes times;
  bool certified() const {
    if (precise) return precise->certified;
    return rigidity.rigid && stress.strictly_positive && identification.polish.converged;
  }
  std::string status() const;  // one line: the certificate's verdict
  // d with `digits` significant digits (from MPFR when it ran).
  std::string d_string(int digits) const;
};

Analysis analyze_packing(const Packing& start, const AnalysisOptions& options);

// The analysis as a packing record: the pattern, d and L with every digit known (MPFR's when its
// polish converged), the certificate and the identity; no source, label or rank yet.
PackingRecord record_of(const Analysis& analysis);
// A converged MPFR polish's digits onto a record: d, L and the coordinates (rattlers keep theirs).
void apply_multiprecision(PackingRecord& record, const MultiprecisionPolish& polish);

// `tripack analyze FILE`: points read in any layout, converted to the unit triangle, analysed.
struct AnalyzeRequest {
  std::string file;
  std::optional<Convention> convention;  // none: unit-triangle, or radius for an x y r file
  int digits = 15;
  long long expected_n = 0;  // 0: any
  bool lp_any_size = false;  // lp_limit lifted
  ProgressFn progress;

  void declare(OptionList& o) {
    o.option("file", file, "the points file").required();
    o.parsed(
        "--convention", [this](const std::string& s) { convention = convention_from_option(s); },
        "unit-triangle, or radius for an x y r file", kConventionHelp);
    o.option("--digits", digits, "significant digits of d, r, S (above 18: MPFR polish)")
        .range(1, 100000);
    o.option("--n", expected_n, "expected number of points (0: any)").range(0, 100000000);
    o.flag("--lp-any-size", lp_any_size,
           "run the LP relax and certificates however large n is (above 3000 disks they can "
           "take hours; by default a state the LP-free path cannot certify is then reported "
           "not certified)");
  }
};
struct FileAnalysis {
  std::string file;
  std::string layout;  // how the file was read ("x y", "i x y", "csv", ...)
  std::string label;   // the file's own "# label:" (JSON "label"); written again by analyze -o
  Convention convention = Convention::UnitTriangle;
  std::vector<std::string> warnings;  // one line each (rounded input, orientation)
  Analysis analysis;
  int digits = 15;  // requested; above kLongDoubleDigits the MPFR polish ran to this many
  double read_seconds = 0;
  // d, L and r or S (d for unit-triangle) with `wanted` significant digits: MPFR's digits when
  // it ran and more than kLongDoubleDigits are wanted, else long double's.
  std::string d_string(int wanted) const;
  std::string L_string(int wanted) const;
  std::string value_string(int wanted) const;
  std::string mp_value_in_convention;  // set when MPFR ran and converged
  double seconds() const { return read_seconds + analysis.times.total(); }
};
FileAnalysis analyze_file(const AnalyzeRequest& request);
// The same on points already read (request.file only names them; the Python module's arrays):
// converted from their convention, checked against expected_n, analysed.
FileAnalysis analyze_points(PointsFile points, const AnalyzeRequest& request,
                            double read_seconds = 0);

}  // namespace tripack::pipeline
