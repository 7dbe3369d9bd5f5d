// exact/tower.hpp: elements of Q(d, sqrt 3) written in the tower basis d^a, sqrt3 d^a, as the
// certificates of format 3 have them. Expected values are closed forms for d = sqrt 2, j = 1:
// t = sqrt 2 + sqrt 3 has K(t) = t^4 - 10 t^2 + 1, t^2 = 5 + 2 sqrt 6 and t^3 = 11 sqrt 2 + 9 sqrt
// 3, so sqrt 2 = (t^3 - 9 t) / 2 and sqrt 3 = (11 t - t^3) / 2.
#include <gtest/gtest.h>

#include <vector>

#include "exact/tower.hpp"

namespace tripack::exact {
namespace {

const IntegerPolynomial p{{"-2", "0", "1"}};  // x^2 - 2

ExactConfiguration root2_root3(const RationalPolynomial& sqrt3) {
  ExactConfiguration c;
  c.field = IntegerPolynomial{{"1", "0", "-10", "0", "1"}};
  c.d_in_field = RationalPolynomial{{"0", "-9/2", "0", "1/2"}};
  c.sqrt3_in_field = sqrt3;
  return c;
}

TEST(Tower, TheGeneratorIsFoundOnlyWhenTEqualsDPlusJSqrt3) {
  EXPECT_EQ(tower_generator(p, root2_root3(RationalPolynomial{{"0", "11/2", "0", "-1/2"}})), 1);
  // -sqrt 3: t = d - sqrt3_in_K, no j in 1..5
  EXPECT_FALSE(tower_generator(p, root2_root3(RationalPolynomial{{"0", "-11/2", "0", "1/2"}})));
  // K = Q(d) (degree deg P): format 2 is written
  ExactConfiguration q_of_d;
  q_of_d.field = p;
  q_of_d.d_in_field = RationalPolynomial{{"0", "1"}};
  q_of_d.sqrt3_in_field = RationalPolynomial{{"0", "1"}};
  EXPECT_FALSE(tower_generator(p, q_of_d));
}

TEST(Tower, PowersOfTAreTheirClosedForms) {
  const RationalPolynomial t{{"0", "1"}}, t2{{"0", "0", "1"}}, t3{{"0", "0", "0", "1"}},
      d{{"0", "-9/2", "0", "1/2"}};
  const auto forms = tower_forms(p, 1, {&t, &t2, &t3, &d});
  ASSERT_EQ(forms.size(), 4u);
  EXPECT_EQ(tower_pari(forms[0]), "(x) + s");       // t = d + s
  EXPECT_EQ(tower_pari(forms[1]), "5 + 2*s*(x)");   // t^2 = 5 + 2 d s
  EXPECT_EQ(tower_pari(forms[2]), "11*(x) + 9*s");  // t^3 = 11 d + 9 s
  EXPECT_EQ(tower_pari(forms[3]), "(x)");           // d itself
}

TEST(Tower, APrimitiveVectorHasIntegralCoprimeCoefficientsAndTheSameSigns) {
  std::vector<TowerForm> v{{RationalPolynomial{{"1/2"}}, RationalPolynomial{{"0", "3/4"}}},
                           {RationalPolynomial{{"-3/2"}}, RationalPolynomial{{"0"}}},
                           {RationalPolynomial{{"0"}}, RationalPolynomial{{"-5/4", "5/2"}}}};
  make_primitive(v);  // times 4
  EXPECT_EQ(tower_pari(v[0]), "2 + 3*s*(x)");
  EXPECT_EQ(tower_pari(v[1]), "-6");
  EXPECT_EQ(tower_pari(v[2]), "5*s*(2*x - 1)");
}

}  // namespace
}  // namespace tripack::exact
