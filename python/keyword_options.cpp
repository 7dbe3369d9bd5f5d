#include "python/keyword_options.hpp"

#include <charconv>
#include <stdexcept>

#include "core/option_values.hpp"

namespace tripack::python {

namespace {

std::vector<std::string> split_names(const std::string& names) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t comma; (comma = names.find(',', start)) != std::string::npos; start = comma + 1)
    out.push_back(names.substr(start, comma - start));
  out.push_back(names.substr(start));
  return out;
}

// The name the command line's errors use: the long name ("--seconds"), else the positional's.
std::string cli_name_of(const std::string& names) {
  std::string chosen;
  for (auto name : split_names(names)) {
    if (!name.empty() && name[0] == '!') name = name.substr(1);
    if (name.rfind("--", 0) == 0 || chosen.empty()) chosen = name;
  }
  return chosen;
}

// A number as the command line reads it: the whole text, or the CLI's conversion error.
template <class T>
T parse_number(const std::string& cli_name, const std::string& text) {
  T value{};
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, value);
  if (r.ec != std::errc{} || r.ptr != end)
    throw std::invalid_argument(cli_name + ": Value " + text + " could not be converted");
  return value;
}

}  // namespace

// Checks a range on the value given, if any, with the command line's words (app/main.cpp).
class KeywordOptions::KeywordHandle : public Handle {
  std::string cli_name_;
  const std::string* text_;

 public:
  KeywordHandle(std::string cli_name, const std::string* text)
      : cli_name_(std::move(cli_name)), text_(text) {}
  Handle& range(double min, double max) override {
    if (!text_) return *this;
    const double value = parse_number<double>(cli_name_, *text_);
    if (!(value >= min && value <= max))
      throw std::invalid_argument(cli_name_ + ": Value " + *text_ + " not in range " +
                                  option_range(min, max));
    return *this;
  }
  Handle& required() override { return *this; }  // a Python call's own signature requires
  Handle& shown_default(const std::string&) override { return *this; }
};

std::string KeywordOptions::keyword_of(const std::string& names) {
  std::string keyword = cli_name_of(names);
  if (keyword.rfind("--", 0) == 0) keyword = keyword.substr(2);
  if (names.rfind("!--no-", 0) == 0) keyword = keyword.substr(3);  // "!--no-polish": polish
  for (auto& c : keyword) c = c == '-' ? '_' : static_cast<char>(std::tolower(c));
  return keyword;
}

void KeywordOptions::check_all_used() const {
  std::string unknown;
  for (const auto& [keyword, text] : given_)
    if (!used_.count(keyword)) unknown += (unknown.empty() ? "" : ", ") + keyword;
  if (!unknown.empty()) throw std::invalid_argument("unknown keyword(s): " + unknown);
}

const std::string* KeywordOptions::take(const std::string& names) {
  const std::string keyword = keyword_of(names);
  const auto it = given_.find(keyword);
  if (it == given_.end()) return nullptr;
  used_.insert(keyword);
  return &it->second;
}

OptionList::Handle& KeywordOptions::keep(std::string cli_name, const std::string* text) {
  handles_.push_back(std::make_unique<KeywordHandle>(std::move(cli_name), text));
  return *handles_.back();
}

template <class T>
OptionList::Handle& KeywordOptions::number(const std::string& names, T& field) {
  const std::string* text = take(names);
  if (text) field = parse_number<T>(cli_name_of(names), *text);
  return keep(cli_name_of(names), text);
}

OptionList::Handle& KeywordOptions::option(const std::string& names, std::string& field,
                                           const std::string&) {
  const std::string* text = take(names);
  if (text) field = *text;
  return keep(cli_name_of(names), nullptr);
}
OptionList::Handle& KeywordOptions::option(const std::string& n, int& f, const std::string&) {
  return number(n, f);
}
OptionList::Handle& KeywordOptions::option(const std::string& n, long& f, const std::string&) {
  return number(n, f);
}
OptionList::Handle& KeywordOptions::option(const std::string& n, long long& f, const std::string&) {
  return number(n, f);
}
OptionList::Handle& KeywordOptions::option(const std::string& n, double& f, const std::string&) {
  return number(n, f);
}
OptionList::Handle& KeywordOptions::option(const std::string& n, std::uint64_t& f,
                                           const std::string&) {
  return number(n, f);
}
OptionList::Handle& KeywordOptions::option(const std::string& names,
                                           std::vector<std::string>& field, const std::string&) {
  const std::string* text = take(names);
  if (text) field = split_names(*text);
  return keep(cli_name_of(names), nullptr);
}

OptionList::Handle& KeywordOptions::flag(const std::string& names, bool& field,
                                         const std::string&) {
  const std::string* text = take(names);
  if (text) {
    if (*text != "true" && *text != "false")
      throw std::invalid_argument(cli_name_of(names) + ": must be true or false, not '" + *text +
                                  "'");
    field = *text == "true";
  }
  return keep(cli_name_of(names), nullptr);
}

OptionList::Handle& KeywordOptions::flag_action(const std::string& names, std::function<void()> act,
                                                const std::string&) {
  const std::string* text = take(names);
  if (text && *text == "true") act();
  return keep(cli_name_of(names), nullptr);
}

OptionList::Handle& KeywordOptions::parsed(const std::string& names,
                                           std::function<void(const std::string&)> set,
                                           const std::string&, const std::string&) {
  const std::string* text = take(names);
  if (text) set(*text);
  return keep(cli_name_of(names), nullptr);
}

}  // namespace tripack::python
