// Exact d(n) of one packing file (docs/exact.md): analyse it (bonds, rattlers), polish its bond
// system to 2D digits (MPFR; rattlers centred), find d's minimal polynomial P from D digits and
// confirm it from 2D (exact/algebraic.hpp), then prove statement (I), the exact configuration
// (exact/configuration.hpp). Prints nothing.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/options.hpp"
#include "exact/algebraic.hpp"
#include "exact/configuration.hpp"
#include "exact/optimality.hpp"
#include "pipeline/analyze.hpp"

namespace tripack::pipeline {

struct ExactSettings {
  int digits = 300;  // D: the relation is found from D digits, confirmed from 2D
  // A row that fails at first_digits (0: digits) is tried again at twice as many, up to digits:
  // the polish is done once, to 2 * digits; P found at fewer digits is kept.
  int first_digits = 0;
  int max_degree = 48;    // of P
  bool existence = true;  // also prove statements (I) and (II)

  void declare(OptionList& o) {
    o.option("--digits", digits, "D: digits the relation is found from").range(40, 20000);
    o.option("--first-digits", first_digits,
             "try D = this, twice this, ... up to --digits until the row is proven (0: --digits "
             "only)")
        .range(40, 20000);
    o.option("--max-degree", max_degree, "largest degree of P tried").range(1, 200);
    o.flag("!--no-existence", existence, "only the polynomial, no proof of statement (I)");
  }
};

struct ExactResult {
  std::string file;
  int n = 0;
  std::string label;  // the file's "# label:" line, else its name
  Pattern pattern;    // bonds and rattlers as analysed
  std::string d;      // to 2D digits
  exact::MinimalPolynomial polynomial;
  std::optional<exact::ExactConfiguration> configuration;
  std::optional<exact::StrictOptimality> optimality;  // statement (II), when (I) holds
  exact::ConfigurationInput input;  // what statement (I) was proven for (the certificate's data)
  std::string given_tolerance;      // the claimed distance to the file's points ("1e-25")
  // "exact" (statements I and II), "existence" (I), "none"; reason: what stopped it.
  std::string proof = "none", reason;
  double seconds_polish = 0, seconds_polynomial = 0, seconds_existence = 0, seconds_optimality = 0;
  double seconds() const {
    return seconds_polish + seconds_polynomial + seconds_existence + seconds_optimality;
  }
};

// What `tripack exact` returns: one result per file.
struct ExactRun {
  std::vector<ExactResult> packings;
};

// Throws InputError for a file that cannot be read, std::invalid_argument for bad settings.
ExactResult exact_of_file(const std::string& file, const ExactSettings& settings);

// A packing (e.g. a class member as built); `given`: its coordinates as text when they have 27+
// decimals (else the certificate's given points are the polish's). Progress: each stage's start
// (analysis, polish, polynomial, existence, optimality); cancelled, it throws Cancelled at the
// next stage (a stage itself, an LLL of minutes, is not interrupted).
ExactResult exact_of_packing(const Packing& packing, const std::string& label,
                             const std::vector<std::array<std::string, 2>>& given,
                             const ExactSettings& settings, const JobContext& job = {});

// The given points as a coordinate file in the atlas's layout ("# n:", "# label:", "# d:" and
// "x y" lines with 30 decimals), for a certificate to name when no packing file was read.
std::string coordinates_text(const ExactResult& result, const std::string& label);

}  // namespace tripack::pipeline
