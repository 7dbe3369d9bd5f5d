// The certificate of an exact d(n) (docs/exact.md "Certificates"): a PARI/GP file that assigns
// the polynomial, its root's interval, the field, the coordinates, the bonds and the given points,
// so that checker/check_exact.gp, which shares no code with tripack, re-checks every claim.
#pragma once

#include <ostream>
#include <string>

#include "exact/algebraic.hpp"
#include "exact/configuration.hpp"
#include "exact/optimality.hpp"

namespace tripack::exact {

struct CertificateData {
  std::string label;
  const ConfigurationInput* input = nullptr;
  const MinimalPolynomial* polynomial = nullptr;
  const ExactConfiguration* configuration = nullptr;  // proven
  const StrictOptimality* optimality = nullptr;        // when proven: claimed too
  std::string given_tolerance = "1e-25";
};

// Format 1; claims "existence", and "strict-local-optimum" with the stress when proven.
void write_certificate(std::ostream& out, const CertificateData& data);

}  // namespace tripack::exact
