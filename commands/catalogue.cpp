// The catalogue's commands: classes, classify, table, check-formula.
#include "report/results/catalogue.hpp"

#include <memory>

#include "commands/common.hpp"
#include "core/option_values.hpp"
#include "pipeline/catalogue_checks.hpp"

namespace tripack::commands {

namespace {

class Classes : public Command {
 public:
  static constexpr CommandInfo kInfo{"classes", "List the catalogue of classes", false};

 private:
  Output out;

 public:
  void declare(OptionList& o) override { out.declare(o); }
  int run(const Context& c) override {
    print_result(load_catalogue(c), out);
    return 0;
  }
};

class Classify : public Command {
 public:
  static constexpr CommandInfo kInfo{"classify", "Every (class, k[, p]) whose n(k) equals N",
                                     false};

 private:
  long long n = 0;
  Output out;

 public:
  void declare(OptionList& o) override {
    o.option("N", n, "number of disks").required().range(1, 1e12);
    out.declare(o);
  }
  int run(const Context& c) override {
    print_result(pipeline::classify(load_catalogue(c), n), out);
    return 0;
  }
};

class Table : public Command {
 public:
  static constexpr CommandInfo kInfo{
      "table", "Build, polish and certify the first terms of every class", false};

 private:
  long k_count = 4;
  Output out;

 public:
  void declare(OptionList& o) override {
    o.option("--kmax", k_count, "how many k per class").range(1, 50);
    out.declare(o);
  }
  int run(const Context& c) override {
    const auto table = pipeline::catalogue_table(load_catalogue(c), k_count);
    print_result(table, out);
    if (!table.all_ok) throw std::runtime_error("the table has rows that are not verified");
    return 0;
  }
};

class CheckFormula : public Command {
 public:
  static constexpr CommandInfo kInfo{"check-formula",
                                     "Compare built d with the catalogue's closed form", false};

 private:
  std::string class_id;
  std::pair<long long, long long> k;
  long p = 0;
  Output out;

 public:
  void declare(OptionList& o) override {
    o.option("class", class_id, "class id").required();
    o.parsed(
         "--k", [this](const std::string& s) { k = parse_range(s, "--k"); }, "",
         "k or a range A..B")
        .required();
    o.option("--p", p, "matrix row p").range(1, 1e9);
    out.declare(o);
  }
  int run(const Context& c) override {
    const auto check = pipeline::check_formula(load_catalogue(c), class_id, k.first, k.second, p);
    print_result(check, out);
    if (!check.all_ok) throw std::runtime_error("check-formula found mismatches");
    return 0;
  }
};

}  // namespace

std::vector<CommandEntry> catalogue_commands() {
  return {entry<Classes>(), entry<Classify>(), entry<Table>(), entry<CheckFormula>()};
}

}  // namespace tripack::commands
