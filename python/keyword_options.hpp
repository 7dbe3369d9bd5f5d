// A request's options (its declare(OptionList&), core/options.hpp) bound to a Python call's
// keywords: the same fields, defaults, ranges, parsers and one-line errors as the command line
// (app/main.cpp), so that `tripack.search(60, seconds=0)` fails with the CLI's own message.
// A keyword is the option's long name without dashes, '-' as '_' ("--builder-starts" from
// "!--no-builder-starts", "n" from the positional "N"); its value arrives as the text the
// command line would read (a flag's as "true" or "false").
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/options.hpp"

namespace tripack::python {

class KeywordOptions : public OptionList {
 public:
  explicit KeywordOptions(std::map<std::string, std::string> given) : given_(std::move(given)) {}

  // Throws std::invalid_argument naming the keywords no declared option took.
  void check_all_used() const;

  Handle& option(const std::string& names, std::string& field, const std::string& help) override;
  Handle& option(const std::string& names, int& field, const std::string& help) override;
  Handle& option(const std::string& names, long& field, const std::string& help) override;
  Handle& option(const std::string& names, long long& field, const std::string& help) override;
  Handle& option(const std::string& names, double& field, const std::string& help) override;
  Handle& option(const std::string& names, std::uint64_t& field, const std::string& help) override;
  Handle& option(const std::string& names, std::vector<std::string>& field,
                 const std::string& help) override;
  Handle& flag(const std::string& names, bool& field, const std::string& help) override;
  Handle& flag_action(const std::string& names, std::function<void()> act,
                      const std::string& help) override;
  Handle& parsed(const std::string& names, std::function<void(const std::string&)> set,
                 const std::string& shown_default, const std::string& help) override;

  // The keyword of an option's names ("-o,--output" -> "output", "!--no-polish" -> "polish").
  static std::string keyword_of(const std::string& names);

 private:
  class KeywordHandle;
  // The given text of the option's keyword (marked used), or nullptr.
  const std::string* take(const std::string& names);
  Handle& keep(std::string cli_name, const std::string* text);
  template <class T>
  Handle& number(const std::string& names, T& field);

  std::map<std::string, std::string> given_;
  std::set<std::string> used_;
  std::vector<std::unique_ptr<Handle>> handles_;
};

}  // namespace tripack::python
