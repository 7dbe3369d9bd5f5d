#include "exact/number_field.hpp"

#include <mutex>
#include <string>
#include <utility>

// After the standard headers: PARI's headers define short macros.
#include <pari/pari.h>

namespace tripack::exact::pari {

namespace {

// PARI's stack. Debian's libpari is built with thread-local stacks: the first thread that uses
// PARI initialises the library (without its signal handlers and without replacing GMP's
// allocator, which FLINT and MPFR share; its parallel engine on one thread), every other thread
// gets a stack of its own, released
// when the thread ends. The stacks grow on demand up to kMaxStack (virtual memory).
constexpr std::size_t kStack = std::size_t{64} << 20, kMaxStack = std::size_t{8} << 30;

struct ThreadStack {
  bool started = false;
  bool own = false;  // a thread stack (not the main one) to close
  pari_thread thread{};
  ~ThreadStack() {
    if (own) {
      pari_thread_close();
      pari_thread_free(&thread);
    }
  }
};

void ensure_stack() {
  static std::once_flag initialised;
  thread_local ThreadStack stack;
  if (stack.started) return;
  bool first = false;
  std::call_once(initialised, [&] {
    pari_init_opts(kStack, 0, INIT_DFTm | INIT_noINTGMPm);
    paristack_setsize(kStack, kMaxStack);
    setdefault("nbthreads", "1", d_SILENT);  // one core per row: the passes run beside other work
    DEBUGMEM = 0;                            // no "new stack size" warnings on stderr
    first = true;
  });
  if (!first) {
    pari_thread_valloc(&stack.thread, kStack, kMaxStack, nullptr);
    pari_thread_start(&stack.thread);
    stack.own = true;
  }
  stack.started = true;
}

std::string text_of(GEN x) {
  char* s = GENtostr(x);
  std::string out(s);
  pari_free(s);
  return out;
}

// K's polynomial T(y) made monic and integral: Tm(y) = lc^(n-1) T(y / lc), y = lc t.
struct MonicField {
  GEN tm, lc;
  long n, vy;
};

MonicField monic_field(const char* field) {
  MonicField f;
  GEN t = gp_read_str(field);
  f.vy = varn(t);
  f.n = degpol(t);
  f.lc = leading_coeff(t);
  GEN scaled = gsubst(t, f.vy, gdiv(pol_x(f.vy), f.lc));
  f.tm = gmul(gpowgs(f.lc, f.n - 1), scaled);
  return f;
}

// An element of Q[y]/(Tm) (a polynomial, a POLMOD or a rational) as its coefficients in
// t = y / lc: a vector of n rationals.
GEN in_t(const MonicField& f, GEN element) {
  GEN poly = liftpol(element), out = cgetg(f.n + 1, t_VEC), power = gen_1;
  for (long i = 0; i < f.n; ++i) {
    GEN c = typ(poly) == t_POL ? polcoef(poly, i, f.vy) : (i == 0 ? poly : gen_0);
    gel(out, i + 1) = gmul(c, power);
    power = gmul(power, f.lc);
  }
  return out;
}

// A polynomial in t (its coefficients, constant first) as an element of Q[y]/(Tm).
GEN in_y(const MonicField& f, GEN coefficients) {
  GEN out = gen_0, y = pol_x(f.vy), power = gen_1;
  for (long i = 1; i < lg(coefficients); ++i) {
    out = gadd(out, gmul(gel(coefficients, i), power));
    power = gdiv(gmul(power, y), f.lc);
  }
  return out;
}

RationalPolynomial polynomial_of(GEN coefficients) {
  RationalPolynomial out;
  for (long i = 1; i < lg(coefficients); ++i)
    out.coefficients.push_back(text_of(gel(coefficients, i)));
  while (out.coefficients.size() > 1 && out.coefficients.back() == "0") out.coefficients.pop_back();
  return out;
}

// A polynomial in t as a PARI vector of its coefficients, written before PARI runs.
std::string vector_text(const RationalPolynomial& p) {
  std::string out = "[";
  for (std::size_t i = 0; i < p.coefficients.size(); ++i) {
    if (i) out += ',';
    out += p.coefficients[i];
  }
  return out + "]";
}

// Runs `body` (PARI calls only, no C++ objects: a PARI error unwinds it by longjmp) on this
// thread's PARI stack and hands its GEN to `convert`; the stack is emptied afterwards. A PARI
// error becomes Error with PARI's message.
template <typename Body, typename Convert>
auto with_pari(Body body, Convert convert) -> decltype(convert(GEN{})) {
  ensure_stack();
  const pari_sp top = avma;
  GEN result = nullptr;
  char* message = nullptr;
  pari_CATCH(CATCH_ALL) {
    message = pari_err2str(pari_err_last());
  }
  pari_TRY {
    result = body();
  }
  pari_ENDCATCH;
  if (message) {
    const std::string text(message);
    pari_free(message);
    set_avma(top);
    throw Error("PARI: " + text);
  }
  auto out = convert(result);
  set_avma(top);
  return out;
}

}  // namespace

std::vector<RationalPolynomial> roots_in_field(const IntegerPolynomial& field,
                                               const IntegerPolynomial& q) {
  const std::string field_text = field.pari("y"), q_text = q.pari("x");
  return with_pari(
      [&] {
        const MonicField f = monic_field(field_text.c_str());
        GEN roots = nfroots(f.tm, gp_read_str(q_text.c_str()));
        GEN out = cgetg(lg(roots), t_VEC);
        for (long i = 1; i < lg(roots); ++i) gel(out, i) = in_t(f, gel(roots, i));
        return out;
      },
      [](GEN roots) {
        std::vector<RationalPolynomial> out;
        for (long i = 1; i < lg(roots); ++i) out.push_back(polynomial_of(gel(roots, i)));
        return out;
      });
}

std::vector<std::vector<RationalPolynomial>> factors_over_field(const IntegerPolynomial& field,
                                                                const IntegerPolynomial& q) {
  const std::string field_text = field.pari("y"), q_text = q.pari("x");
  return with_pari(
      [&] {
        const MonicField f = monic_field(field_text.c_str());
        GEN factors = gel(nffactor(f.tm, gp_read_str(q_text.c_str())), 1);
        GEN out = cgetg(lg(factors), t_VEC);
        for (long i = 1; i < lg(factors); ++i) {
          GEN g = gel(factors, i);
          GEN coefficients = cgetg(degpol(g) + 2, t_VEC);
          for (long j = 0; j <= degpol(g); ++j)
            gel(coefficients, j + 1) = in_t(f, polcoef(g, j, varn(g)));
          gel(out, i) = coefficients;
        }
        return out;
      },
      [](GEN factors) {
        std::vector<std::vector<RationalPolynomial>> out;
        for (long i = 1; i < lg(factors); ++i) {
          std::vector<RationalPolynomial> coefficients;
          for (long j = 1; j < lg(gel(factors, i)); ++j)
            coefficients.push_back(polynomial_of(gmael(factors, i, j)));
          out.push_back(std::move(coefficients));
        }
        return out;
      });
}

Extension extend_field(const IntegerPolynomial& field, const std::vector<RationalPolynomial>& g) {
  const std::string field_text = field.pari("y");
  std::string g_text = "[";
  for (std::size_t j = 0; j < g.size(); ++j) {
    if (j) g_text += ',';
    g_text += vector_text(g[j]);
  }
  g_text += "]";
  return with_pari(
      [&] {
        const MonicField f = monic_field(field_text.c_str());
        const long vx = 0;  // x: PARI's first variable, of higher priority than y
        GEN coefficients = gp_read_str(g_text.c_str()), relative = gen_0;
        for (long j = lg(coefficients) - 1; j >= 1; --j)
          relative = gadd(gmul(relative, pol_x(vx)), in_y(f, gel(coefficients, j)));
        GEN all = rnfequation0(f.tm, relative, 1);
        GEN z = gel(all, 1);
        z = gdiv(z, content(z));
        // y = a(theta); t = y / lc; w = theta - k y.
        GEN a = liftpol(gel(all, 2));
        const MonicField absolute{z, gen_1, degpol(z), vx};
        GEN zc = cgetg(degpol(z) + 2, t_VEC);
        for (long i = 0; i <= degpol(z); ++i) gel(zc, i + 1) = polcoef(z, i, vx);
        // theta = w + k y = w + (k lc) t
        return mkvec4(zc, in_t(absolute, gdiv(a, f.lc)),
                      in_t(absolute, gsub(pol_x(vx), gmul(gel(all, 3), a))),
                      gmul(gel(all, 3), f.lc));
      },
      [](GEN all) {
        Extension out;
        out.field.coefficients = polynomial_of(gel(all, 1)).coefficients;
        out.t = polynomial_of(gel(all, 2));
        out.w = polynomial_of(gel(all, 3));
        out.shift = text_of(gel(all, 4));
        return out;
      });
}

}  // namespace tripack::exact::pari
