// The atlas: for every n of a range, the best certified packings known here, merged
// from a campaign's database and every catalogue builder whose class contains n, each certified
// anew from its coordinates and polished in MPFR to 30 digits. The atlas is data (data/atlas.csv
// and one coordinates file per row, written by jobs/atlas_files.hpp) that anyone can check.
#pragma once

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "constructors/catalogue.hpp"
#include "core/option_values.hpp"
#include "core/options.hpp"
#include "core/progress.hpp"
#include "core/record.hpp"

namespace tripack::jobs {

struct AtlasSettings {
  long long n_first = 2, n_last = 300;  // every n of this range, or:
  std::vector<long long> n_values;      // when not empty, these n only (in [n_first, n_last])
  // These n keep their best `ranked_count` distinct packings (the paper's rankings to check);
  // every other n keeps its best one.
  long long ranked_first = 16, ranked_last = 34;
  int ranked_count = 20;
  int digits = 30;  // MPFR polish of d and the coordinates
  int threads = 2;

  void declare(OptionList& o) {
    o.parsed(
        "--n",
        [this](const std::string& s) {
          n_values = parse_range_list(s, "--n");
          n_first = *std::min_element(n_values.begin(), n_values.end());
          n_last = *std::max_element(n_values.begin(), n_values.end());
        },
        "2..300", "A..B, N, or a list of them: 254,255,256");
    o.parsed(
        "--ranked",
        [this](const std::string& s) {
          std::tie(ranked_first, ranked_last) = parse_range(s, "--ranked");
        },
        "16..34", "these n keep --ranked-count packings");
    o.option("--ranked-count", ranked_count, "packings kept for --ranked n").range(1, 1000);
    o.option("--digits", digits, "significant digits of d and the coordinates").range(19, 1000);
    o.option("--threads", threads, "parallel values of n").range(1, 256);
  }
};

// The atlas's rows are packing records (core/record.hpp): d and L to `digits` (MPFR), the
// coordinates to `digits` in precise_points (rattlers keep their long double place), every source
// (the builders giving it, the billiards seed or import of the database), label and rank among
// the certified packings of n, and `file` (atlas/LABEL.txt, relative to the data directory).
// delta (the L - t(n) column) is derived from L with atlas_delta.
std::string atlas_delta(const PackingRecord& row);

// A builder member of n, whether or not it made the atlas (findings compare it with the best).
struct AtlasBuilderCheck {
  long long n = 0;
  std::string member;  // pipeline::member_name
  std::string d;       // 30 digits (long double digits when the polish failed)
  bool certified = false;
  std::string verdict;
  std::string label;     // its label among the certified packings of n ("" if not certified)
  std::size_t rank = 0;  // its rank there (1 = the atlas's best; 0: not certified)
};

// The paper's tight/loose measure (GL1995 sec. 6) from the atlas: for a class member n(k) with
// n(k)+1 in the atlas, L(n(k)+1) - L(n(k)) (and the same for delta) between the atlas's best
// packings of n(k) and n(k)+1. A class is tight when it stays away from 0 as k grows.
struct AtlasGap {
  std::string class_id;
  long k = 0, p = 0;
  long long n = 0;
  std::string label_n, label_next;  // the atlas rows used (rank 1 of n and of n+1)
  long double L_n = 0, L_next = 0;
  long double delta_difference = 0;  // delta(n+1) - delta(n)
  std::string claim_tight;           // the paper's conjecture (classes.yaml claim.tight)
};

struct AtlasResult {
  AtlasSettings settings;
  std::string db;
  std::vector<PackingRecord> rows;  // by n, then rank
  // By label: the builders, imports and independent units (method, seeds) that reached the
  // row's value of d, what its confirmations count (the table's provenance column).
  std::map<std::string, std::string> provenance;
  std::vector<AtlasBuilderCheck> builders;
  std::vector<AtlasGap> gaps;       // by class, then p, then k
  std::vector<long long> missing;   // n in the range without any certified packing
  std::vector<std::string> errors;  // one line each: a candidate that failed (the rest went on)
  bool cancelled = false;
  double seconds = 0;
};

// Reads the database (read-only), builds every catalogue member of each n, certifies and polishes
// every candidate, ranks and labels them like `tripack billiards`. Throws store::StoreError for
// the database. The values of n are the job runner's items (stage "atlas", one report per n);
// stops between them when its job is cancelled (`cancelled` in the result).
AtlasResult build_atlas(const Catalogue& catalogue, const std::string& db_path,
                        const AtlasSettings& settings, const JobContext& job = {});

}  // namespace tripack::jobs
