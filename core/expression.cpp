#include "core/expression.hpp"

#include <algorithm>
#include <cctype>

namespace tripack {

class ExpressionParser {
 public:
  explicit ExpressionParser(Expression& e) : e_(e), s_(e.text_) {}

  void parse() {
    sum();
    skip();
    if (pos_ != s_.size()) fail("unexpected '" + std::string(1, s_[pos_]) + "'");
  }

 private:
  using Kind = Expression::Kind;
  Expression& e_;
  const std::string& s_;
  std::size_t pos_ = 0;
  int depth_ = 0;  // nesting of unary(): every recursion passes through it
  // Deeper formulas are refused: 3000 '(' overflowed the stack of this recursive descent.
  static constexpr int kMaxDepth = 200;

  [[noreturn]] void fail(const std::string& what) const {
    throw ExpressionError("cannot parse '" + s_ + "' at position " + std::to_string(pos_) + ": " +
                          what);
  }
  void skip() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  bool eat(char c) {
    skip();
    if (pos_ < s_.size() && s_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  int push(Kind k, std::string name, std::vector<int> args) {
    e_.nodes_.push_back({k, std::move(name), std::move(args)});
    return static_cast<int>(e_.nodes_.size()) - 1;
  }
  // One level of left-associative operators: operand (op operand)*, the operands one level down.
  int left_associative(int (ExpressionParser::*operand)(), char op1, Kind k1, char op2, Kind k2) {
    int lhs = (this->*operand)();
    for (;;) {
      if (eat(op1))
        lhs = push(k1, "", {lhs, (this->*operand)()});
      else if (eat(op2))
        lhs = push(k2, "", {lhs, (this->*operand)()});
      else
        return lhs;
    }
  }
  int sum() { return left_associative(&ExpressionParser::product, '+', Kind::Add, '-', Kind::Sub); }
  int product() {
    return left_associative(&ExpressionParser::unary, '*', Kind::Mul, '/', Kind::Div);
  }
  int unary() {
    struct Nesting {
      int& depth;
      ~Nesting() { --depth; }
    } nesting{++depth_};
    if (depth_ > kMaxDepth) fail("nested deeper than " + std::to_string(kMaxDepth) + " levels");
    if (eat('-')) return push(Kind::Negate, "", {unary()});
    if (eat('+')) return unary();
    return power();
  }
  int power() {
    int base = primary();
    if (eat('^')) return push(Kind::Pow, "", {base, unary()});
    return base;
  }
  int primary() {
    skip();
    if (pos_ >= s_.size()) fail("unexpected end");
    const char c = s_[pos_];
    if (eat('(')) {
      int v = sum();
      if (!eat(')')) fail("missing ')'");
      return v;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      const std::size_t b = pos_;
      while (pos_ < s_.size() &&
             (std::isdigit(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '.'))
        ++pos_;
      if (pos_ < s_.size() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
        ++pos_;
        if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) ++pos_;
        while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
      }
      return push(Kind::Number, s_.substr(b, pos_ - b), {});
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const std::size_t b = pos_;
      while (pos_ < s_.size() &&
             (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_'))
        ++pos_;
      std::string name = s_.substr(b, pos_ - b);
      if (eat('(')) {
        std::vector<int> args;
        if (!eat(')')) {
          do {
            args.push_back(sum());
          } while (eat(','));
          if (!eat(')')) fail("missing ')' after arguments of " + name);
        }
        return push(Kind::Call, std::move(name), std::move(args));
      }
      return push(Kind::Variable, std::move(name), {});
    }
    fail("unexpected '" + std::string(1, c) + "'");
  }
};

Expression Expression::parse(std::string_view text) {
  Expression e;
  e.text_ = std::string(text);
  ExpressionParser(e).parse();
  return e;
}

std::vector<std::string> Expression::variables() const {
  std::vector<std::string> v;
  for (const auto& n : nodes_)
    if (n.kind == Kind::Variable && std::find(v.begin(), v.end(), n.name) == v.end())
      v.push_back(n.name);
  return v;
}

}  // namespace tripack
