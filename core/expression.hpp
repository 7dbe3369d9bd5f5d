// Small arithmetic expressions for the catalogue's formulas ("Delta(2*k)+1", "2*k-2+sqrt(3)",
// with Delta, sqrt and max(a, b)).
// Parsed once, evaluated for any number type: long long for disk and bond counts (division must
// be exact), long double for lengths, and later multiprecision and exact types. A hand-written
// evaluator because the Debian parsers (muparser) only evaluate in double.
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace tripack {

struct ExpressionError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

template <class T>
struct ExpressionEnv {
  // Value of a variable, or nullopt if unknown.
  std::function<std::optional<T>(std::string_view)> variable;
  // Extra functions (beyond sqrt and Delta), or nullopt if unknown.
  std::function<std::optional<T>(std::string_view, std::span<const T>)> function;
};

class Expression {
 public:
  Expression() = default;
  static Expression parse(std::string_view text);  // throws ExpressionError
  const std::string& text() const { return text_; }
  bool empty() const { return nodes_.empty(); }
  // Names of the variables the expression uses.
  std::vector<std::string> variables() const;

  template <class T>
  T eval(const ExpressionEnv<T>& env) const {
    if (nodes_.empty()) throw ExpressionError("empty expression");
    return eval_node<T>(static_cast<int>(nodes_.size()) - 1, env);
  }

 private:
  enum class Kind { Number, Variable, Negate, Add, Sub, Mul, Div, Pow, Call };
  struct Node {
    Kind kind;
    std::string name;  // number literal, variable or function name
    std::vector<int> args;
  };
  friend class ExpressionParser;
  std::string text_;
  std::vector<Node> nodes_;  // post-order; the root is last

  template <class T>
  T eval_node(int id, const ExpressionEnv<T>& env) const;
};

template <class T>
T Expression::eval_node(int id, const ExpressionEnv<T>& env) const {
  const Node& nd = nodes_[static_cast<std::size_t>(id)];
  auto arg = [&](std::size_t i) { return eval_node<T>(nd.args[i], env); };
  // Integer formulas are checked: an overflow is an error, not undefined behaviour (fuzzing
  // found 33^22 and 9999999999*9999999999 in catalogue formulas).
  auto overflow = [&] { throw ExpressionError("'" + text_ + "': integer overflow"); };
  auto add = [&](auto a, auto b) {
    T r{};
    if (__builtin_add_overflow(a, b, &r)) overflow();
    return r;
  };
  auto sub = [&](auto a, auto b) {
    T r{};
    if (__builtin_sub_overflow(a, b, &r)) overflow();
    return r;
  };
  auto mul = [&](auto a, auto b) {
    T r{};
    if (__builtin_mul_overflow(a, b, &r)) overflow();
    return r;
  };
  switch (nd.kind) {
    case Kind::Number:
      if constexpr (std::is_integral_v<T>) {
        if (nd.name.find_first_of(".eE") != std::string::npos)
          throw ExpressionError("'" + text_ + "': non-integer literal in an integer formula");
        return static_cast<T>(std::stoll(nd.name));
      } else {
        return T(std::stold(nd.name));
      }
    case Kind::Variable: {
      if (env.variable)
        if (auto v = env.variable(nd.name)) return *v;
      throw ExpressionError("'" + text_ + "': unknown variable '" + nd.name + "'");
    }
    case Kind::Negate:
      if constexpr (std::is_integral_v<T>) {
        return sub(T(0), arg(0));
      } else {
        return -arg(0);
      }
    case Kind::Add:
      if constexpr (std::is_integral_v<T>) {
        return add(arg(0), arg(1));
      } else {
        return arg(0) + arg(1);
      }
    case Kind::Sub:
      if constexpr (std::is_integral_v<T>) {
        return sub(arg(0), arg(1));
      } else {
        return arg(0) - arg(1);
      }
    case Kind::Mul:
      if constexpr (std::is_integral_v<T>) {
        return mul(arg(0), arg(1));
      } else {
        return arg(0) * arg(1);
      }
    case Kind::Div: {
      const T a = arg(0), b = arg(1);
      if constexpr (std::is_integral_v<T>) {
        if (b == 0 || a % b != 0)
          throw ExpressionError("'" + text_ + "': inexact integer division");
      }
      return a / b;
    }
    case Kind::Pow: {
      const T a = arg(0), b = arg(1);
      if constexpr (std::is_integral_v<T>) {
        if (b < 0) throw ExpressionError("'" + text_ + "': negative integer power");
        // Square and multiply: log2(b) checked steps (a loop of b steps hung on 1^999999999999).
        T r = 1, base = a;
        for (T e = b; e > 0; e /= 2) {
          if (e % 2 == 1) r = mul(r, base);
          if (e > 1) base = mul(base, base);
        }
        return r;
      } else {
        using std::pow;
        return pow(a, b);
      }
    }
    case Kind::Call: {
      std::vector<T> values;
      for (std::size_t i = 0; i < nd.args.size(); ++i) values.push_back(arg(i));
      if (nd.name == "Delta" && values.size() == 1) {
        if constexpr (std::is_integral_v<T>) {
          return mul(values[0], add(values[0], T(1))) / 2;
        } else {
          return values[0] * (values[0] + 1) / 2;
        }
      }
      // max(a, b): a formula with a small-k exception (odd-ripple other: one more bond at k = 2).
      if (nd.name == "max" && values.size() == 2)
        return values[0] < values[1] ? values[1] : values[0];
      if (nd.name == "sqrt" && values.size() == 1) {
        if constexpr (std::is_integral_v<T>) {
          throw ExpressionError("'" + text_ + "': sqrt in an integer formula");
        } else {
          using std::sqrt;
          return sqrt(values[0]);
        }
      }
      if (env.function)
        if (auto v = env.function(nd.name, std::span<const T>(values))) return *v;
      throw ExpressionError("'" + text_ + "': unknown function '" + nd.name + "' with " +
                            std::to_string(values.size()) + " argument(s)");
    }
  }
  throw ExpressionError("bad expression node");
}

}  // namespace tripack
