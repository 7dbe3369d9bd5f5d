// Options declared once, next to the fields they set (docs/extending.md "An option"): a request's
// declare(OptionList&) names each option with its help; the command line (app/main.cpp) binds it
// to the field and shows the field's initial value as the default. Core knows no CLI library.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace tripack {

class OptionList {
 public:
  // A declared option, for the checks the command line enforces before anything runs.
  class Handle {
   public:
    virtual ~Handle() = default;
    virtual Handle& range(double min, double max) = 0;  // inclusive
    virtual Handle& required() = 0;
    // What the help shows as the default instead of the field's initial value ("": none, for a
    // field whose initial value only means "not given").
    virtual Handle& shown_default(const std::string& text) = 0;
  };

  virtual ~OptionList() = default;

  // names: "--name", "-o,--output", or a word without dashes for a positional argument.
  virtual Handle& option(const std::string& names, std::string& field, const std::string& help) = 0;
  virtual Handle& option(const std::string& names, int& field, const std::string& help) = 0;
  virtual Handle& option(const std::string& names, long& field, const std::string& help) = 0;
  virtual Handle& option(const std::string& names, long long& field, const std::string& help) = 0;
  virtual Handle& option(const std::string& names, double& field, const std::string& help) = 0;
  virtual Handle& option(const std::string& names, std::uint64_t& field,
                         const std::string& help) = 0;
  virtual Handle& option(const std::string& names, std::vector<std::string>& field,
                         const std::string& help) = 0;
  // "--name" sets the field; "!--no-name" clears it (the field's initial value is the default).
  virtual Handle& flag(const std::string& names, bool& field, const std::string& help) = 0;
  // A flag that runs `act` when given (its std::exception is the one-line error).
  virtual Handle& flag_action(const std::string& names, std::function<void()> act,
                              const std::string& help) = 0;
  // A value parsed by `set` (its std::exception is the one-line error), shown as `shown_default`.
  virtual Handle& parsed(const std::string& names, std::function<void(const std::string&)> set,
                         const std::string& shown_default, const std::string& help) = 0;

  // One of named values, e.g. --method basin-hopping|restarts.
  template <class T>
  Handle& choice(const std::string& names, T& field, const std::map<std::string, T>& values,
                 const std::string& help) {
    std::string listed, shown;
    for (const auto& [name, value] : values) {
      listed += (listed.empty() ? "" : ", ") + name;
      if (value == field) shown = name;
    }
    return parsed(
        names,
        [&field, values, names, listed](const std::string& text) {
          const auto it = values.find(text);
          if (it == values.end())
            throw std::invalid_argument(names + " must be one of " + listed + ", not '" + text +
                                        "'");
          field = it->second;
        },
        shown, help + " (" + listed + ")");
  }
};

}  // namespace tripack
