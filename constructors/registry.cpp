#include "constructors/registry.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <utility>

namespace tripack {

namespace {

// Name -> builder, filled by the BuilderRegistration constants of the builder files before
// main() and sealed by the first lookup. A function-local static: registrations run from other
// translation units' static initialisers, in no guaranteed order.
class BuilderTable {
 public:
  static BuilderTable& instance() {
    static BuilderTable table;
    return table;
  }
  void add(std::string_view name, BuilderFunction build) {
    if (sealed_.load(std::memory_order_relaxed))
      throw std::logic_error("builder '" + std::string(name) +
                             "' registered after the first lookup: the table is read-only");
    if (build == nullptr || name.empty())
      throw std::logic_error("builder registration without a name or a function");
    const auto at =
        std::lower_bound(entries_.begin(), entries_.end(), name,
                         [](const Entry& e, std::string_view n) { return e.first < n; });
    if (at != entries_.end() && at->first == name)
      throw std::logic_error("builder '" + std::string(name) + "' registered twice");
    entries_.insert(at, {std::string(name), build});
  }
  // Sorted by name.
  const std::vector<std::pair<std::string, BuilderFunction>>& entries() {
    sealed_.store(true, std::memory_order_relaxed);
    return entries_;
  }

 private:
  using Entry = std::pair<std::string, BuilderFunction>;
  std::vector<Entry> entries_;
  std::atomic<bool> sealed_{false};
};

}  // namespace

BuilderRegistration::BuilderRegistration(std::string_view name, BuilderFunction build) {
  BuilderTable::instance().add(name, build);
}

BuilderFunction find_builder(std::string_view name) {
  const auto& entries = BuilderTable::instance().entries();
  const auto at = std::lower_bound(entries.begin(), entries.end(), name,
                                   [](const auto& e, std::string_view n) { return e.first < n; });
  return at != entries.end() && at->first == name ? at->second : nullptr;
}

std::vector<std::string> registered_builders() {
  std::vector<std::string> names;
  for (const auto& [name, build] : BuilderTable::instance().entries()) names.push_back(name);
  return names;
}

long BuilderCall::arg(const std::string& name) const {
  const auto it = cls.builder_args.find(name);
  if (it == cls.builder_args.end())
    throw CatalogueError(cls.id + ": builder '" + cls.builder + "' needs argument '" + name + "'");
  return static_cast<long>(it->second.eval<long long>(integer_env(k, p)));
}

Pattern build_pattern(const Catalogue& catalogue, const BuildRequest& req,
                      const BuildControl& control) {
  const ClassInfo& c = catalogue.find(req.class_id);
  catalogue.check_parameters(c, req.k, req.p);
  const std::string variant = catalogue.resolve_variant(c, req.k, req.variant);
  const BuilderFunction build = find_builder(c.builder);
  if (build == nullptr) {
    std::string known;
    for (const auto& name : registered_builders()) known += (known.empty() ? "" : ", ") + name;
    throw CatalogueError(c.id + ": unknown builder '" + c.builder +
                         "' in the catalogue (known: " + known + ")");
  }
  Pattern pat = build({c, req.k, req.p, variant, &control});
  pat.provenance = {c.id, req.k, req.p, variant};
  return pat;
}

}  // namespace tripack
