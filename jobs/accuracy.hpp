// "Accuracy costs time" as data (docs/accuracy.md): how many correct digits of d billiards alone
// reaches, and at what cost, against the polishers (long double, MPFR); and the hard cases that
// must stay stable (tight cages, near contacts, near-equal gaps, large n, near-degenerate contacts,
// corner disks, two packings of 33 disks 1e-8 apart). Returns results; prints nothing.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "constructors/catalogue.hpp"
#include "core/progress.hpp"

namespace tripack::jobs {

struct AccuracyRow {
  long long n = 0;
  std::string label;   // packing reached (t22a, ...)
  std::string method;  // "billiards", "polish (long double)", "mpfr"
  // "gap 1e-3", ..., "gap 1e-12", "double", "30 digits", "50 digits", "100 digits"
  std::string target;
  double seconds = 0;  // wall time of that step (billiards: from the random start; polish: from the
                       // billiards end state; mpfr: from the long double polish)
  double digits = 0;   // correct significant digits of d, against a 110-digit MPFR reference of
                       // the same packing's bond system; NaN when no bond system pins d there
  std::string reference;  // that reference d to 20 decimals ("" when there is none)
};

struct HardCase {
  std::string name;      // "t33c tight cage", ...
  std::string what;      // one line: what makes it hard (from docs/accuracy.md)
  bool stable = false;   // the pipeline gives the same d, bonds, rattlers and verdict every time
  std::string evidence;  // one line: how we know (e.g. "5 perturbed starts (1e-9 d): same d to
                         // 1e-15, 62 bonds, 1 rattler, certified")
};

struct AccuracyStudy {
  std::vector<AccuracyRow> rows;
  std::vector<HardCase> hard_cases;
  bool cancelled = false;  // stopped before every item ran
  double seconds = 0;
};

struct AccuracySettings {
  // The large n is 500, not 1000: at 1000 one relax of a random billiards end state takes ~47 s
  // here (four of them per n) and its bond identification loses the contact network.
  std::vector<long long> n{22, 79, 254, 500};
  std::uint64_t seed = 1;  // of every billiards run (one trajectory per n, stopped at each gap)
  bool hard_cases = true;
  // The hard cases' coordinate files (t18a.txt, ...); empty: the installed data's hard/
  // (core/data_directory.hpp).
  std::string hard_case_dir;
};

// The rows and hard cases one item at a time on the job runner (stage "accuracy"); stops between
// items when cancelled (`cancelled` in the result).
AccuracyStudy measure_accuracy(const Catalogue& catalogue, const AccuracySettings& settings,
                               const JobContext& job = {});

// Correct significant digits of `value` against `reference`, -log10(|value - reference| /
// |reference|), both positive decimal strings in fixed notation, computed from their digits (a
// subtraction in double would stop at ~16); `cap` when they agree to every digit, and at most cap.
double correct_digits(const std::string& value, const std::string& reference, double cap);

}  // namespace tripack::jobs
