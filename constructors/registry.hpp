// build(class, k, p, variant): validates against the catalogue and dispatches to the builder
// named in classes.yaml.
#pragma once

#include <string>

#include "constructors/catalogue.hpp"
#include "core/packing.hpp"

namespace tripack {

struct BuildRequest {
  std::string class_id;
  long k = 0;
  long p = 0;
  std::string variant;  // empty: the class's default
};

// Throws CatalogueError for a request outside the catalogue (unknown class, k or p out of range,
// bad variant) and std::runtime_error if the construction itself fails.
Pattern build_pattern(const Catalogue& catalogue, const BuildRequest& request);

}  // namespace tripack
