// constructors/catalogue: classes.yaml, classify, parameter and variant validation.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <set>

#include "constructors/catalogue.hpp"

namespace tripack {
namespace {

const Catalogue& catalogue() {
  static const Catalogue c = Catalogue::load(TRIPACK_DEFAULT_CATALOGUE);
  return c;
}

TEST(Catalogue, HasEveryClassOfTheIssue) {
  for (const char* id : {"hexagonal", "hexagonal-minus-one", "four-delta", "twin", "matrix",
                         "even-ripple", "ripple-of-pairs", "pairs", "sparse-rows", "odd-ripple"})
    EXPECT_NO_THROW(catalogue().find(id)) << id;
  EXPECT_THROW(catalogue().find("nonsense"), CatalogueError);
}

TEST(Catalogue, MatrixListUpTo300IsThePapers) {
  // GL1995 Sec.6: "the list of all n of the form n = n_p(k) for n <= 300".
  const std::vector<long long> paper{4,   11,  12,  22,  24,  30,  37,  40,  56,  57,
                                     58,  60,  79,  84,  93,  95,  106, 108, 112, 137,
                                     138, 141, 144, 172, 174, 175, 180, 192, 196, 211,
                                     220, 254, 255, 256, 258, 260, 264, 280};
  ASSERT_EQ(paper.size(), 38u);
  const auto& m = catalogue().find("matrix");
  std::vector<long long> ours;
  for (long long n = 1; n <= 300; ++n) {
    const auto members = catalogue().classify(n);
    const auto hits =
        std::count_if(members.begin(), members.end(), [&](const Member& x) { return x.cls == &m; });
    EXPECT_LE(hits, 1) << "GL1995: k and p are unique for each n_p(k); n = " << n;
    if (hits) ours.push_back(n);
  }
  EXPECT_EQ(ours, paper);
}

TEST(Catalogue, ClassifyTwelve) {
  // GL1995 Sec.7: 12 is on the path of 4Delta(k), Delta(3k+1)+2 and Delta(2k+3)-3 (and n_1(2));
  // and 12 = Delta(5) - 3, a vacancy-segment member and a jogged-line member (the 3-site line 2
  // lines from a wall; docs/findings.md §11).
  std::set<std::string> got;
  for (const auto& m : catalogue().classify(12))
    got.insert(m.cls->id + " p=" + std::to_string(m.p) + " k=" + std::to_string(m.k));
  EXPECT_EQ(got, (std::set<std::string>{"four-delta p=0 k=2", "matrix p=1 k=2",
                                        "ripple-of-pairs p=0 k=1", "pairs p=0 k=1",
                                        "vacancy-segment p=3 k=2", "jogged-line p=2 k=3"}));
}

TEST(Catalogue, ClassifyAgreesWithNOfForEveryMember) {
  for (long long n = 2; n <= 400; ++n)
    for (const auto& m : catalogue().classify(n)) EXPECT_EQ(catalogue().n_of(*m.cls, m.k, m.p), n);
  // 18, 23, 32, 33: GL1995 Sec.6 places them in no class; each is Delta(K) - m with 2 <= m < K,
  // so each is now a member of the discovered classes vacancy-segment (k, p: Delta(k+p) - p)
  // and jogged-line (k', p': Delta(k'+p') - k', the line of m sites; docs/findings.md §11), and
  // of no other class.
  for (const auto& [n, k, p, kj, pj] :
       {std::array<long, 5>{18, 3, 3, 3, 3}, std::array<long, 5>{23, 2, 5, 5, 2},
        std::array<long, 5>{32, 4, 4, 4, 4}, std::array<long, 5>{33, 5, 3, 3, 5}}) {
    std::set<std::string> got;
    for (const auto& m : catalogue().classify(n))
      got.insert(m.cls->id + " k=" + std::to_string(m.k) + " p=" + std::to_string(m.p));
    EXPECT_EQ(got, (std::set<std::string>{
                       "vacancy-segment k=" + std::to_string(k) + " p=" + std::to_string(p),
                       "jogged-line k=" + std::to_string(kj) + " p=" + std::to_string(pj)}))
        << n;
  }
}

TEST(Catalogue, ParameterValidation) {
  const auto& c = catalogue();
  EXPECT_THROW(c.check_parameters(c.find("four-delta"), 0, 0), CatalogueError);
  EXPECT_THROW(c.check_parameters(c.find("hexagonal"), 1, 0), CatalogueError);
  EXPECT_THROW(c.check_parameters(c.find("sparse-rows"), 13, 0), CatalogueError);
  EXPECT_THROW(c.check_parameters(c.find("odd-ripple"), 1, 0), CatalogueError);
  // A variant's own k_min: at k = 2 (n = 16) only the other modification exists, and it is what
  // the class builds there by default.
  EXPECT_NO_THROW(c.check_parameters(c.find("odd-ripple"), 2, 0));
  EXPECT_THROW(c.resolve_variant(c.find("odd-ripple"), 2, "depressed"), CatalogueError);
  EXPECT_EQ(c.resolve_variant(c.find("odd-ripple"), 2, ""), "other");
  EXPECT_EQ(c.resolve_variant(c.find("odd-ripple"), 3, ""), "depressed");
  EXPECT_EQ(c.variants_at(c.find("odd-ripple"), 2), std::vector<std::string>{"other"});
  EXPECT_THROW(c.check_parameters(c.find("matrix"), 2, 0), CatalogueError);      // missing p
  EXPECT_THROW(c.check_parameters(c.find("four-delta"), 2, 3), CatalogueError);  // p not taken
  EXPECT_NO_THROW(c.check_parameters(c.find("matrix"), 2, 3));
  try {
    c.check_parameters(c.find("matrix"), 2, 0);
  } catch (const CatalogueError& e) {
    EXPECT_NE(std::string(e.what()).find("--p"), std::string::npos);
  }
}

TEST(Catalogue, Variants) {
  const auto& c = catalogue();
  const auto& twin = c.find("twin");
  EXPECT_EQ(c.resolve_variant(twin, 3, ""), "rattler");
  EXPECT_EQ(c.resolve_variant(twin, 3, "cavity-2"), "cavity-2");
  EXPECT_THROW(c.resolve_variant(twin, 3, "cavity-3"), CatalogueError);  // m <= k-1
  EXPECT_THROW(c.resolve_variant(twin, 3, "cavity-0"), CatalogueError);
  EXPECT_THROW(c.resolve_variant(twin, 3, "bogus"), CatalogueError);
  EXPECT_EQ(c.variants_at(twin, 3),
            (std::vector<std::string>{"rattler", "cavity-1", "cavity-2", "full"}));
  EXPECT_EQ(c.variants_at(twin, 1), (std::vector<std::string>{"rattler", "full"}));
  EXPECT_THROW(c.resolve_variant(c.find("four-delta"), 2, "full"), CatalogueError);
  // Bond formulas per variant (GL1995 Sec.5): t31a79, t31a81, t31a82.
  EXPECT_EQ(c.bonds_of(twin, 3, 0, "rattler"), 79);
  EXPECT_EQ(c.bonds_of(twin, 3, 0, "cavity-1"), 81);
  EXPECT_EQ(c.bonds_of(twin, 3, 0, "full"), 82);
}

TEST(Catalogue, MalformedYamlIsACatalogueError) {
  auto bad = [](const std::string& text) {
    try {
      Catalogue::parse(text);
    } catch (const CatalogueError& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "accepted: " << text;
  };
  bad("classes: [");                                                         // not YAML
  bad("version: 1\n");                                                       // no classes
  bad("classes:\n  - id: a\n");                                              // no display / n
  bad("classes:\n  - {id: a, display: A, n: 'k+', builder: {name: x}}\n");   // bad formula
  bad("classes:\n  - {id: a, display: A, n: 'q+1', builder: {name: x}}\n");  // unknown variable
  bad("classes:\n  - {id: a, display: A, n: 'k', builder: {name: x}}\n  - {id: a, display: A, n: "
      "'k', builder: {name: x}}\n");
  bad("classes:\n  - {id: a, display: A, n: 'k', k_min: two, builder: {name: x}}\n");
  EXPECT_THROW(Catalogue::load("/nonexistent/classes.yaml"), CatalogueError);
}

// fuzz/findings/fuzz_catalogue/timeout-n-not-growing.yaml: classify scans k (and p) until n passes
// N, so an n that does not grow (there a mutated hexagonal class with n = "Delta(p)") hung it.
// Such a class is now a one-line CatalogueError naming it; well-formed classes are unaffected.
TEST(Catalogue, ClassifyRefusesAnNThatDoesNotGrowInsteadOfScanningForever) {
  auto one_class = [](const std::string& fields) {
    return Catalogue::parse("classes:\n  - {id: a, display: A, builder: {name: x}, " + fields +
                            "}\n");
  };
  auto refused = [](const Catalogue& c, const std::string& needle) {
    try {
      (void)c.classify(22);
    } catch (const CatalogueError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
      EXPECT_NE(what.find(needle), std::string::npos) << what;
      return;
    }
    ADD_FAILURE() << "classify(22) accepted it (expected: " << needle << ")";
  };
  refused(one_class("n: 'Delta(p)', k_min: 2"), "a.n does not grow with k: 1 at k = 2, 1 at k = 3");
  refused(one_class("n: '20-k'"), "a.n does not grow with k: 19 at k = 1, 18 at k = 2");
  refused(one_class("n: '5+0*k*p'"), "a.n does not grow with k");
  refused(one_class("n: 'k+0*p', k_max: 2"), "a.n does not grow with p: 1 at p = 1, 1 at p = 2");
  refused(one_class("n: 'k-1000000000000'"), "a.n is -999999999999 at k = 1");
  // Growing n: classify works as before, with or without p.
  const auto k_only = one_class("n: '2*k+1'").classify(21);
  ASSERT_EQ(k_only.size(), 1u);
  EXPECT_EQ(k_only[0].k, 10);
  EXPECT_EQ(one_class("n: 'k*p'").classify(6).size(), 4u);  // (6,1) (3,2) (2,3) (1,6)
}

}  // namespace
}  // namespace tripack
