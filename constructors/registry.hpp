// build_pattern(catalogue, request): validates a request against the catalogue and runs the
// builder that classes.yaml names for its class. Builders are looked up by that name in a table
// each builder file adds itself to (BuilderRegistration), so a new builder is its own .cpp file
// plus its classes.yaml entry (docs/extending.md).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "constructors/catalogue.hpp"
#include "core/packing.hpp"
#include "core/progress.hpp"

namespace tripack {

struct BuildRequest {
  std::string class_id;
  long k = 0;
  long p = 0;
  std::string variant;  // empty: the class's default
};

// What a long construction (an enumeration of candidates) reports and how it is stopped: stage
// "construct" with items done of total, and Cancelled thrown at its next check once the token is
// cancelled. Both optional; a quick builder ignores them.
struct BuildControl {
  ProgressFn progress;
  const CancelToken* cancel = nullptr;
  // An enumerating builder relaxes every candidate fully instead of its fast ranking (the check
  // of that ranking: docs/classes.md, "Vacancy segments").
  bool exhaustive = false;
  int threads = 1;  // an enumeration's candidates relaxed at once
};

// Throws CatalogueError for a request outside the catalogue (unknown class, k or p out of range,
// bad variant, a builder name nothing registered) and std::runtime_error if the construction
// itself fails.
Pattern build_pattern(const Catalogue& catalogue, const BuildRequest& request,
                      const BuildControl& control = {});

// What a builder is called with: the member (k, p), its variant (already resolved: the class's
// default when the request named none; empty for a class without variants) and its class.
struct BuilderCall {
  const ClassInfo& cls;
  long k = 0, p = 0;
  std::string variant;
  // The builder argument `name` of classes.yaml (`builder: {name: chain-family, q: "p", ...}`)
  // evaluated at (k, p). Throws CatalogueError when the class does not give it.
  long arg(const std::string& name) const;
  const BuildControl* control = nullptr;  // never null when called by build_pattern
};
using BuilderFunction = Pattern (*)(const BuilderCall&);

// Adds a builder to the table under its classes.yaml name during static initialisation; a
// builder file ends with one constant per name it serves:
//   const BuilderRegistration kFourDelta{"four-delta",
//                                        [](const BuilderCall& c) { return build_four_delta(c.k);
//                                        }};
// The table is complete when main() starts and read-only from the first lookup on: registering
// a name twice, or after a lookup, throws std::logic_error (at static initialisation that ends
// the program with the message). The constructors library is linked whole (CMakeLists.txt): a
// linker would otherwise leave out a builder file that nothing refers to by name.
class BuilderRegistration {
 public:
  BuilderRegistration(std::string_view name, BuilderFunction build);
};

// The builder registered under `name`, or nullptr.
BuilderFunction find_builder(std::string_view name);
// Every registered name, sorted.
std::vector<std::string> registered_builders();

}  // namespace tripack
