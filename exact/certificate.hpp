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
  const StrictOptimality* optimality = nullptr;       // when proven: claimed too
  std::string given_tolerance = "1e-25";
  // The coordinate file `given` was read from (the atlas's, with the label and n in its header),
  // relative to the certificate's directory: format 2 names it, and the checker compares n, the
  // label and every given point with it. Empty: format 1 (the checker looks for
  // ../atlas/LABEL.txt).
  std::string coordinates_file;
};

// Format 2 (format 1 without a coordinate file); claims "existence", and
// "strict-local-optimum" with the stress when proven.
void write_certificate(std::ostream& out, const CertificateData& data);

}  // namespace tripack::exact
