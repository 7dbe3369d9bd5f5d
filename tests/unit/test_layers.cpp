// The layers' arrows (docs/architecture.md): core <- polish <- {constructors, analysis} <-
// patterns; core <- sim; core <- exact; core <- runner; those <- pipeline <- search (with runner)
// <- store <- jobs <- report <- commands; app sees only commands and core (it parses and
// dispatches); python (the module) sees what commands see, but not commands. Every #include
// "dir/..." of a source file must name its own layer or one below it; tests/ and bench/ may include
// anything.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Each layer and the layers it may include (itself included).
const std::map<std::string, std::set<std::string>>& allowed_includes() {
  static const std::map<std::string, std::set<std::string>> allowed = [] {
    std::map<std::string, std::set<std::string>> a;
    a["core"] = {"core"};
    a["polish"] = {"core", "polish"};
    a["constructors"] = {"core", "polish", "constructors"};
    a["analysis"] = {"core", "polish", "analysis"};
    a["sim"] = {"core", "formats", "sim"};  // a scene's initial points from a packing file
    a["exact"] = {"core", "exact"};
    a["runner"] = {"core", "runner"};
    a["formats"] = {"core", "polish", "formats"};
    a["patterns"] = {"core", "polish", "constructors", "analysis", "patterns"};
    a["pipeline"] = {"core",     "polish", "formats", "constructors", "analysis",
                     "patterns", "sim",    "exact",   "pipeline"};
    // A chain from here: each layer may include itself and everything below it.
    const char* chain[] = {"pipeline", "search", "store", "jobs", "report", "commands"};
    for (std::size_t i = 1; i < std::size(chain); ++i) {
      a[chain[i]] = a[chain[i - 1]];
      a[chain[i]].insert(chain[i]);
    }
    a["search"].insert("runner");
    for (const char* above : {"store", "jobs", "report", "commands"}) a[above].insert("runner");
    // The program only parses and dispatches: it sees the command table and core's values.
    a["app"] = {"core", "commands", "app"};
    // The Python module binds the library as the commands do, beside them, not through them.
    a["python"] = a["report"];
    a["python"].insert("python");
    return a;
  }();
  return allowed;
}

// "file:line includes dir/x.hpp" for every include that points up or sideways.
std::vector<std::string> layer_violations(const fs::path& root) {
  std::vector<std::string> found;
  const std::regex include_line(R"(^\s*#\s*include\s*"([a-z_]+)/[^"]+")");
  for (const auto& [layer, allowed] : allowed_includes()) {
    if (!fs::is_directory(root / layer)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root / layer)) {
      const auto ext = entry.path().extension();
      if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".hpp")) continue;
      std::ifstream in(entry.path());
      std::string line;
      for (int number = 1; std::getline(in, line); ++number) {
        std::smatch m;
        if (std::regex_search(line, m, include_line) && allowed_includes().count(m[1]) &&
            !allowed.count(m[1]))
          found.push_back(fs::relative(entry.path(), root).string() + ":" + std::to_string(number) +
                          " includes " + m[1].str() + "/");
      }
    }
  }
  return found;
}

TEST(Layers, EveryIncludePointsDown) {
  const auto violations = layer_violations(TRIPACK_SOURCE_DIR);
  for (const auto& v : violations) ADD_FAILURE() << v;
  // The check saw the tree: each layer directory exists.
  for (const char* layer :
       {"core", "polish", "constructors", "analysis", "patterns", "sim", "exact", "runner",
        "formats", "pipeline", "search", "store", "jobs", "report", "commands", "app", "python"})
    EXPECT_TRUE(fs::is_directory(fs::path(TRIPACK_SOURCE_DIR) / layer)) << layer;
}

TEST(Layers, APlantedUpwardIncludeIsCaught) {
  const fs::path root = fs::temp_directory_path() / "tripack_layers_test";
  fs::remove_all(root);
  for (const char* dir : {"core", "sim", "report", "app"}) fs::create_directories(root / dir);
  std::ofstream(root / "core" / "bad.hpp") << "#include \"analysis/relax.hpp\"\n";
  std::ofstream(root / "sim" / "bad.cpp") << "  #  include \"constructors/registry.hpp\"\n";
  std::ofstream(root / "report" / "ok.cpp")
      << "#include \"pipeline/build.hpp\"\n#include <cmath>\n";
  std::ofstream(root / "app" / "ok.cpp") << "#include \"commands/command.hpp\"\n";
  // report may render the jobs' results; the jobs must not reach up to report, nor the store to
  // jobs.
  for (const char* dir : {"jobs", "store"}) fs::create_directories(root / dir);
  std::ofstream(root / "report" / "ok2.cpp") << "#include \"jobs/stored.hpp\"\n";
  std::ofstream(root / "jobs" / "bad.cpp") << "#include \"report/render.hpp\"\n";
  std::ofstream(root / "store" / "bad.cpp") << "#include \"jobs/campaign.hpp\"\n";
  const auto violations = layer_violations(root);
  fs::remove_all(root);
  ASSERT_EQ(violations.size(), 4u);
  EXPECT_EQ(violations[0], "core/bad.hpp:1 includes analysis/");
  EXPECT_EQ(violations[1], "jobs/bad.cpp:1 includes report/");
  EXPECT_EQ(violations[2], "sim/bad.cpp:1 includes constructors/");
  EXPECT_EQ(violations[3], "store/bad.cpp:1 includes jobs/");
}

}  // namespace
