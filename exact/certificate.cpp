#include "exact/certificate.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace tripack::exact {

namespace {

// A decimal as an exact GP rational: "0.125" -> "125/10^3".
std::string gp_rational(const std::string& decimal) {
  std::string text = decimal;
  std::string sign;
  if (!text.empty() && (text[0] == '-' || text[0] == '+')) {
    if (text[0] == '-') sign = "-";
    text.erase(0, 1);
  }
  const auto dot = text.find('.');
  if (dot == std::string::npos) return sign + text;
  const std::string fraction = text.substr(dot + 1);
  std::string digits = text.substr(0, dot) + fraction;
  digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size() - 1));
  return fmt::format("{}{}/10^{}", sign, digits, fraction.size());
}

}  // namespace

void write_certificate(std::ostream& out, const CertificateData& data) {
  if (!data.input || !data.polynomial || !data.configuration || !data.configuration->proven)
    throw std::invalid_argument("write_certificate: a proven configuration is needed");
  const ConfigurationInput& in = *data.input;
  const ExactConfiguration& c = *data.configuration;
  const int format = data.coordinates_file.empty() ? 1 : 2;
  out << fmt::format("\\\\ tripack exact certificate (format {}): read by checker/check_exact.gp\n",
                     format);
  out << fmt::format("cert_format = {};\n", format);
  out << fmt::format("label = \"{}\"; n = {};\n", data.label, in.n);
  if (format == 2) {
    out << "\\\\ the packing's coordinate file (relative to this file): n, label and given come "
           "from it\n";
    out << fmt::format("coordinates_file = \"{}\";\n", data.coordinates_file);
  }
  out << "\\\\ the minimal polynomial of d over Q; d is its only root in [d_low, d_high]\n";
  out << fmt::format("P = {};\n", data.polynomial->polynomial.pari("x"));
  out << fmt::format("d_low = {}; d_high = {};\n", data.polynomial->root.low,
                     data.polynomial->root.high);
  out << "\\\\ the field K = Q[t]/(K), embedded at its only root t0 in [t_low, t_high]\n";
  out << fmt::format("K = {};\n", c.field.pari("t"));
  out << fmt::format("t_low = {}; t_high = {};\n", c.embedding.low, c.embedding.high);
  out << fmt::format("d_in_K = {};\n", c.d_in_field.pari("t"));
  out << fmt::format("sqrt3_in_K = {};\n", c.sqrt3_in_field.pari("t"));
  out << "\\\\ the exact points: polynomials in t (rattlers: rationals)\n";
  // Multi-line values in braces: GP ends a statement at a newline outside { }.
  out << "{points = [";
  for (std::size_t i = 0; i < c.points.size(); ++i)
    out << (i ? ",\n  " : "\n  ") << "[" << c.points[i][0].pari("t") << ", "
        << c.points[i][1].pari("t") << "]";
  out << "];}\n";
  out << "rattlers = [";
  for (std::size_t i = 0; i < in.rattlers.size(); ++i) out << (i ? ", " : "") << in.rattlers[i] + 1;
  out << "];\n";
  out << "\\\\ [i, j]: |p_i - p_j| = d; [i, -w]: p_i on wall w (1 bottom, 2 left, 3 right)\n";
  out << "bonds = [";
  for (std::size_t i = 0; i < in.bonds.size(); ++i) {
    const Bond& b = in.bonds[i];
    out << (i ? ", " : "") << "[" << b.a + 1 << ", " << (b.is_wall() ? b.b : b.b + 1) << "]";
  }
  out << "];\n";
  out << "\\\\ the packing as given; every exact point lies within given_tolerance of it\n";
  out << "{given = [";
  for (std::size_t i = 0; i < in.given.size(); ++i)
    out << (i ? ",\n  " : "\n  ") << "[" << gp_rational(in.given[i][0]) << ", "
        << gp_rational(in.given[i][1]) << "]";
  out << "];}\n";
  out << fmt::format("given_tolerance = {};\n",
                     data.given_tolerance == "1e-25" ? "10^-25" : data.given_tolerance);
  if (data.optimality && data.optimality->proven) {
    out << "\\\\ a strictly positive self-stress, per bond (G^T stress = 0 in K; G of full rank)\n";
    out << "{stress = [";
    for (std::size_t i = 0; i < data.optimality->stress.size(); ++i)
      out << (i ? ",\n  " : "\n  ") << data.optimality->stress[i].pari("t");
    out << "];}\n";
    out << "claims = [\"existence\", \"strict-local-optimum\"];\n";
  } else {
    out << "claims = [\"existence\"];\n";
  }
}

}  // namespace tripack::exact
