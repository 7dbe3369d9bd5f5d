#include "exact/field_kernel.hpp"

#include <flint/nmod_poly.h>
#include <flint/ulong_extras.h>
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <optional>

#include "exact/flint_tools.hpp"

namespace tripack::exact {

namespace {

using flint::Fmpq;
using flint::FmpqPoly;
using flint::Fmpz;
using flint::FmpzPoly;

// A polynomial over Z/pZ; owning.
struct NmodPoly {
  nmod_poly_t value;
  explicit NmodPoly(mp_limb_t p) { nmod_poly_init(value, p); }
  ~NmodPoly() { nmod_poly_clear(value); }
  NmodPoly(const NmodPoly&) = delete;
  NmodPoly& operator=(const NmodPoly&) = delete;
};

// The matrix over K twice: as given (rational, for the exact verification) and with each row
// scaled by the lcm of its denominators (integral, for the images modulo p; a row's scaling
// changes no kernel).
struct Problem {
  int rows = 0, columns = 0, degree = 0;
  FmpzPoly modulus;  // K(t), primitive
  std::vector<std::unique_ptr<FmpqPoly>> exact;
  std::vector<std::unique_ptr<FmpzPoly>> integral;
  std::size_t at(int r, int c) const {
    return static_cast<std::size_t>(r) * static_cast<std::size_t>(columns) +
           static_cast<std::size_t>(c);
  }
};

void read_problem(Problem& problem, const std::vector<std::vector<RationalPolynomial>>& rows,
                  const IntegerPolynomial& field) {
  problem.rows = static_cast<int>(rows.size());
  problem.columns = rows.empty() ? 0 : static_cast<int>(rows[0].size());
  flint::poly_from_strings(problem.modulus.value, field.coefficients);
  fmpz_poly_primitive_part(problem.modulus.value, problem.modulus.value);
  problem.degree = static_cast<int>(fmpz_poly_degree(problem.modulus.value));
  FmpqPoly modulus;
  fmpq_poly_set_fmpz_poly(modulus.value, problem.modulus.value);
  Fmpz lcm, scale;
  for (const auto& row : rows) {
    if (static_cast<int>(row.size()) != problem.columns)
      throw std::invalid_argument("kernel_over_field: rows of different lengths");
    fmpz_one(lcm.value);
    const std::size_t first = problem.exact.size();
    for (const auto& entry : row) {
      auto element = std::make_unique<FmpqPoly>();
      flint::fmpq_poly_from_strings(element->value, entry.coefficients);
      fmpq_poly_rem(element->value, element->value, modulus.value);
      fmpz_lcm(lcm.value, lcm.value, fmpq_poly_denref(element->value));
      problem.exact.push_back(std::move(element));
    }
    for (std::size_t i = first; i < problem.exact.size(); ++i) {
      auto element = std::make_unique<FmpzPoly>();
      const fmpq_poly_struct* q = problem.exact[i]->value;
      fmpz_divexact(scale.value, lcm.value, fmpq_poly_denref(q));
      fmpz_poly_fit_length(element->value, fmpq_poly_length(q));
      _fmpz_vec_scalar_mul_fmpz(element->value->coeffs, fmpq_poly_numref(q), fmpq_poly_length(q),
                                scale.value);
      _fmpz_poly_set_length(element->value, fmpq_poly_length(q));
      problem.integral.push_back(std::move(element));
    }
  }
}

// The reduced row echelon form modulo p (leftmost pivots, each a unit of F_p[t]/(K)): its pivot
// columns and, for each wanted kernel vector k (its values c_k at the free columns) and pivot row
// i, the coefficients of -sum_f c_k[f] R[i][f], the vector's entry at pivot column i.
struct Image {
  mp_limb_t prime = 0;
  bool usable = false;  // false: a nonzero non-unit where a pivot was needed, or a value's
                        // denominator divisible by p
  std::vector<int> pivots;
  std::vector<mp_limb_t> residues;  // [k][i][j], j < degree
};

// A rational's image modulo p; false when p divides its denominator.
bool rational_mod(mp_limb_t& out, const fmpq_t q, mp_limb_t p) {
  const mp_limb_t den = fmpz_fdiv_ui(fmpq_denref(q), p);
  if (den == 0) return false;
  out = n_mulmod2_preinv(fmpz_fdiv_ui(fmpq_numref(q), p), n_invmod(den, p), p, n_preinvert_limb(p));
  return true;
}

using FreeValues = std::vector<std::vector<std::unique_ptr<Fmpq>>>;  // [vector][free column]

class Ring {
 public:
  Ring(mp_limb_t p, const fmpz_poly_t modulus) : p_(p), modulus_(p), inverse_(p) {
    fmpz_poly_get_nmod_poly(modulus_.value, modulus);
    nmod_poly_reverse(inverse_.value, modulus_.value, nmod_poly_length(modulus_.value));
    nmod_poly_inv_series(inverse_.value, inverse_.value, nmod_poly_length(modulus_.value));
  }
  void mul(nmod_poly_t out, const nmod_poly_t a, const nmod_poly_t b) const {
    nmod_poly_mulmod_preinv(out, a, b, modulus_.value, inverse_.value);
  }
  // out = 1 / a when a is a unit of F_p[t]/(K).
  bool invert(nmod_poly_t out, const nmod_poly_t a) const {
    if (nmod_poly_degree(modulus_.value) < 2) {  // F_p itself; a is a constant
      const mp_limb_t c = nmod_poly_get_coeff_ui(a, 0);
      if (c == 0) return false;
      nmod_poly_zero(out);
      nmod_poly_set_coeff_ui(out, 0, n_invmod(c, p_));
      return true;
    }
    return nmod_poly_invmod(out, a, modulus_.value) != 0;
  }

 private:
  mp_limb_t p_;
  NmodPoly modulus_, inverse_;
};

Image eliminate_modulo(const Problem& problem, mp_limb_t p, const FreeValues& values) {
  Image image;
  image.prime = p;
  const Ring ring(p, problem.modulus.value);
  std::vector<std::unique_ptr<NmodPoly>> cell;
  cell.reserve(problem.integral.size());
  for (const auto& entry : problem.integral) {
    cell.push_back(std::make_unique<NmodPoly>(p));
    fmpz_poly_get_nmod_poly(cell.back()->value, entry->value);
  }
  const int rows = problem.rows, columns = problem.columns;
  auto at = [&](int r, int c) { return cell[problem.at(r, c)]->value; };
  auto swap_rows = [&](int a, int b) {
    for (int c = 0; c < columns; ++c) std::swap(cell[problem.at(a, c)], cell[problem.at(b, c)]);
  };
  NmodPoly inverse(p), product(p), factor(p);
  int row = 0;
  for (int c = 0; c < columns && row < rows; ++c) {
    int pivot = -1;
    bool nonzero = false;
    for (int r = row; r < rows && pivot < 0; ++r) {
      if (nmod_poly_is_zero(at(r, c))) continue;
      nonzero = true;
      if (ring.invert(inverse.value, at(r, c))) pivot = r;
    }
    if (pivot < 0) {
      if (nonzero) return image;  // the column is independent over K, not here: a bad prime
      continue;
    }
    swap_rows(row, pivot);
    for (int j = c; j < columns; ++j)
      if (!nmod_poly_is_zero(at(row, j))) ring.mul(at(row, j), at(row, j), inverse.value);
    for (int r = 0; r < rows; ++r) {
      if (r == row || nmod_poly_is_zero(at(r, c))) continue;
      nmod_poly_set(factor.value, at(r, c));
      for (int j = c; j < columns; ++j) {
        if (nmod_poly_is_zero(at(row, j))) continue;
        ring.mul(product.value, factor.value, at(row, j));
        nmod_poly_sub(at(r, j), at(r, j), product.value);
      }
    }
    image.pivots.push_back(c);
    ++row;
  }
  const std::vector<int> free_at = free_columns(image.pivots, columns);
  const std::size_t free = free_at.size();
  std::vector<mp_limb_t> c(free);
  image.residues.reserve(values.size() * image.pivots.size() *
                         static_cast<std::size_t>(problem.degree));
  for (const auto& vector : values) {
    if (vector.size() != free) return image;  // the pivots differ from the shape's
    for (std::size_t f = 0; f < free; ++f)
      if (!rational_mod(c[f], vector[f]->value, p)) return image;
    for (std::size_t i = 0; i < image.pivots.size(); ++i) {
      nmod_poly_zero(product.value);
      for (std::size_t f = 0; f < free; ++f) {
        if (c[f] == 0) continue;
        nmod_poly_scalar_mul_nmod(factor.value, at(static_cast<int>(i), free_at[f]), c[f]);
        nmod_poly_sub(product.value, product.value, factor.value);
      }
      for (int j = 0; j < problem.degree; ++j)
        image.residues.push_back(nmod_poly_get_coeff_ui(product.value, j));
    }
  }
  image.usable = true;
  return image;
}

// The rational coefficients [k][i][j] from the images by CRT and rational reconstruction; none
// when some coefficient has no reconstruction yet (its height needs more primes).
std::optional<std::vector<std::unique_ptr<Fmpq>>> reconstruct(const std::vector<Image>& images) {
  const auto count = static_cast<slong>(images.size());
  std::vector<mp_limb_t> primes, residues(images.size());
  Fmpz modulus, value;
  fmpz_one(modulus.value);
  for (const Image& image : images) {
    primes.push_back(image.prime);
    fmpz_mul_ui(modulus.value, modulus.value, image.prime);
  }
  fmpz_comb_t comb;
  fmpz_comb_temp_t temp;
  fmpz_comb_init(comb, primes.data(), count);
  fmpz_comb_temp_init(temp, comb);
  std::vector<std::unique_ptr<Fmpq>> out;
  bool complete = true;
  for (std::size_t index = 0; index < images[0].residues.size(); ++index) {
    for (std::size_t k = 0; k < images.size(); ++k) residues[k] = images[k].residues[index];
    fmpz_multi_CRT_ui(value.value, residues.data(), comb, temp, 0);
    out.push_back(std::make_unique<Fmpq>());
    if (!fmpq_reconstruct_fmpz(out.back()->value, value.value, modulus.value)) {
      complete = false;
      break;
    }
  }
  fmpz_comb_temp_clear(temp);
  fmpz_comb_clear(comb);
  if (!complete) return std::nullopt;
  return out;
}

// The reconstruction agrees with a further image (a cheap test before the exact one).
bool agrees_with(const std::vector<std::unique_ptr<Fmpq>>& coefficients, const Image& image) {
  mp_limb_t r = 0;
  for (std::size_t index = 0; index < coefficients.size(); ++index)
    if (rational_mod(r, coefficients[index]->value, image.prime) && r != image.residues[index])
      return false;
  return true;
}

// The kernel vectors from their free values and the reconstructed coefficients, each checked
// A v = 0 over K exactly; empty when one fails.
std::vector<std::vector<std::unique_ptr<FmpqPoly>>> verified_vectors(
    const Problem& problem, const std::vector<int>& pivots, const FreeValues& values,
    const std::vector<std::unique_ptr<Fmpq>>& coefficients) {
  const std::vector<int> free = free_columns(pivots, problem.columns);
  FmpqPoly modulus, sum, product;
  fmpq_poly_set_fmpz_poly(modulus.value, problem.modulus.value);
  std::vector<std::vector<std::unique_ptr<FmpqPoly>>> out;
  std::size_t index = 0;
  for (const auto& vector : values) {
    std::vector<std::unique_ptr<FmpqPoly>> v;
    for (int c = 0; c < problem.columns; ++c) v.push_back(std::make_unique<FmpqPoly>());
    for (std::size_t f = 0; f < free.size(); ++f)
      fmpq_poly_set_fmpq(v[static_cast<std::size_t>(free[f])]->value, vector[f]->value);
    for (int pivot : pivots)
      for (int j = 0; j < problem.degree; ++j)
        fmpq_poly_set_coeff_fmpq(v[static_cast<std::size_t>(pivot)]->value, j,
                                 coefficients[index++]->value);
    for (int r = 0; r < problem.rows; ++r) {
      fmpq_poly_zero(sum.value);
      for (int c = 0; c < problem.columns; ++c) {
        const fmpq_poly_struct* a = problem.exact[problem.at(r, c)]->value;
        if (fmpq_poly_is_zero(a) || fmpq_poly_is_zero(v[static_cast<std::size_t>(c)]->value))
          continue;
        fmpq_poly_mul(product.value, a, v[static_cast<std::size_t>(c)]->value);
        fmpq_poly_add(sum.value, sum.value, product.value);
      }
      fmpq_poly_rem(sum.value, sum.value, modulus.value);
      if (!fmpq_poly_is_zero(sum.value)) return {};
    }
    out.push_back(std::move(v));
  }
  return out;
}

// Better image first: the larger rank, then the lexicographically smaller pivots (a prime can
// only lose independence, never gain it).
bool better(const std::vector<int>& a, const std::vector<int>& b) {
  if (a.size() != b.size()) return a.size() > b.size();
  return a < b;
}

constexpr int max_primes = 20000;  // ~380,000 digits of modulus: heights far beyond any row's
constexpr int max_unusable = 50;

// The next prime below 2^63 that does not divide K's leading coefficient.
mp_limb_t next_prime(mp_limb_t p, const Problem& problem) {
  do p = n_nextprime(p, 1);
  while (fmpz_fdiv_ui(problem.modulus.value->coeffs + problem.degree, p) == 0);
  return p;
}

constexpr mp_limb_t first_prime = UWORD(1) << 62;

}  // namespace

std::vector<int> free_columns(const std::vector<int>& pivots, int columns) {
  std::vector<int> f;
  for (int c = 0; c < columns; ++c)
    if (!std::binary_search(pivots.begin(), pivots.end(), c)) f.push_back(c);
  return f;
}

KernelShape kernel_shape(const std::vector<std::vector<RationalPolynomial>>& rows,
                         const IntegerPolynomial& field) {
  Problem problem;
  read_problem(problem, rows, field);
  KernelShape out;
  mp_limb_t p = first_prime;
  int usable = 0;
  while (usable < 3 && out.primes < max_unusable + 3) {
    p = next_prime(p, problem);
    ++out.primes;
    const Image image = eliminate_modulo(problem, p, {});
    if (!image.usable) continue;
    if (usable++ == 0 || better(image.pivots, out.pivot_columns)) {
      out.pivot_columns = image.pivots;
      out.rank = static_cast<int>(image.pivots.size());
    }
    if (out.rank == problem.rows) return out;
  }
  if (usable == 0) out.reason = fmt::format("{} primes met a nonzero non-unit pivot", out.primes);
  return out;
}

KernelVectors kernel_vectors(const std::vector<std::vector<RationalPolynomial>>& rows,
                             const IntegerPolynomial& field, const KernelShape& shape,
                             const std::vector<std::vector<std::string>>& free_values) {
  Problem problem;
  read_problem(problem, rows, field);
  FreeValues values;
  for (const auto& vector : free_values) {
    values.emplace_back();
    for (const auto& text : vector) {
      values.back().push_back(std::make_unique<Fmpq>());
      if (fmpq_set_str(values.back().back()->value, text.c_str(), 10) != 0)
        throw std::invalid_argument("kernel_vectors: not a rational: '" + text + "'");
      fmpq_canonicalise(values.back().back()->value);
    }
  }
  KernelVectors out;
  mp_limb_t p = first_prime;
  std::vector<Image> images;
  std::optional<std::vector<std::unique_ptr<Fmpq>>> candidate;
  std::size_t next_attempt = 1;
  int unusable = 0;
  while (out.primes < max_primes) {
    p = next_prime(p, problem);
    ++out.primes;
    Image image = eliminate_modulo(problem, p, values);
    if (!image.usable || image.pivots != shape.pivot_columns) {
      if (++unusable > max_unusable) {
        out.reason = fmt::format("{} primes without the shape's pivots", unusable);
        return out;
      }
      continue;
    }
    if (candidate && !agrees_with(*candidate, image)) candidate.reset();
    if (candidate) {
      auto vectors = verified_vectors(problem, shape.pivot_columns, values, *candidate);
      if (!vectors.empty() || values.empty()) {
        for (const auto& v : vectors) {
          std::vector<RationalPolynomial> vector;
          for (const auto& e : v) vector.push_back(flint::strings_from_fmpq_poly(e->value));
          out.vectors.push_back(std::move(vector));
        }
        return out;
      }
      candidate.reset();
    }
    images.push_back(std::move(image));
    if (images.size() >= next_attempt) {
      candidate = reconstruct(images);
      next_attempt = images.size() + std::max<std::size_t>(1, images.size() / 4);
    }
  }
  out.reason = fmt::format("no verified kernel vector from {} primes", out.primes);
  return out;
}

FieldKernel kernel_over_field(const std::vector<std::vector<RationalPolynomial>>& rows,
                              const IntegerPolynomial& field) {
  FieldKernel out;
  out.shape = kernel_shape(rows, field);
  if (!out.shape.reason.empty()) {
    out.reason = out.shape.reason;
    return out;
  }
  const int columns = rows.empty() ? 0 : static_cast<int>(rows[0].size());
  const std::size_t free = static_cast<std::size_t>(columns) - out.shape.pivot_columns.size();
  std::vector<std::vector<std::string>> identity(free);
  for (std::size_t f = 0; f < free; ++f)
    for (std::size_t g = 0; g < free; ++g) identity[f].emplace_back(f == g ? "1" : "0");
  KernelVectors vectors = kernel_vectors(rows, field, out.shape, identity);
  out.basis = std::move(vectors.vectors);
  out.primes = vectors.primes;
  out.reason = vectors.reason;
  return out;
}

}  // namespace tripack::exact
