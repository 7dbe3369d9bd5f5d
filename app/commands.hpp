// The tripack subcommands. Each returns the process exit code; errors are thrown as exceptions
// and turned into one line by main().
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace tripack::app {

struct GlobalOptions {
  std::string catalogue;  // empty: Catalogue::default_path()
};

inline constexpr long kUnsetK = -1000000000;  // --k not given (0 and negatives are user errors)

struct BuildOptions {
  std::string class_id;
  long k = kUnsetK, p = 0;
  long long n = 0;  // --n: choose the best builder for n
  std::string variant;
  int digits = 15;
  std::string output;  // -o FILE
  bool json = false;
  bool polish = true;
  bool certify = true;  // relax, bonds, rigidity, stress from the geometry (n <= kCertifyLimit)
};

// Above this many disks `build` skips the LP-based certification unless asked explicitly.
inline constexpr std::size_t kCertifyLimit = 20000;

struct AnalyzeOptions {
  std::string file;
  std::string convention = "unit-triangle";
  int digits = 15;
  long long n = 0;     // expected number of points (0: any)
  std::string output;  // -o FILE: the certified packing (unit triangle)
  bool json = false;
};

struct CheckFormulaOptions {
  std::string class_id;
  std::string k_range;  // "A..B" or "K"
  long p = 0;
  bool json = false;
};

int cmd_classes(const GlobalOptions& g, bool json);
int cmd_classify(const GlobalOptions& g, long long n, bool json);
int cmd_build(const GlobalOptions& g, const BuildOptions& o);
int cmd_check_formula(const GlobalOptions& g, const CheckFormulaOptions& o);
int cmd_table(const GlobalOptions& g, long k_max);
int cmd_analyze(const AnalyzeOptions& o);

struct BilliardsCommandOptions {
  long long n = 0;  // 0: the scene's n
  int runs = 10;
  std::uint64_t seed = 1;  // run r uses seed + r, so every run is reproducible on its own
  int threads = 1;
  std::string scene;  // YAML file; empty: the built-in scene
  bool json = false;
  bool certify = true;
};
int cmd_billiards(const GlobalOptions& g, const BilliardsCommandOptions& o);

}  // namespace tripack::app
