// A tripack command: its options, bound to the fields of the request it runs, and its run. The
// command table (commands/table.cpp, family by family) lists every command once, with whether it
// is a long job (stops between items on Ctrl-C or SIGTERM, exit 130); app/ only parses and
// dispatches.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/options.hpp"
#include "core/progress.hpp"

namespace tripack::commands {

struct Context {
  std::string catalogue;                // --catalogue; empty: the default
  const CancelToken* cancel = nullptr;  // set for the long jobs
};

class Command {
 public:
  virtual ~Command() = default;
  virtual void declare(OptionList& options) = 0;
  // The exit code: 0, or kCancelledExit when a long job was cancelled. Errors are thrown (one
  // line, exit 1); results found before an error are written first.
  virtual int run(const Context& context) = 0;
};

inline constexpr int kCancelledExit = 130;
// How long a one-item job (CommandInfo::one_item_lost) has after the first request to reach a
// check before the signal thread ends it: a check is reached well within it between relaxes.
inline constexpr std::chrono::milliseconds kOneItemGrace{2000};

// What the help shows of a command, and whether it is a long job: each command class's kInfo.
struct CommandInfo {
  const char* name;  // "build"; "db export" is the subcommand export of the group db
  const char* summary;
  bool long_job;
  // A long job that is one item (nothing finished to keep until it ends): what its closing line
  // says was lost. The first request then ends it within kOneItemGrace even inside a library call.
  const char* one_item_lost = nullptr;
};

struct CommandEntry {
  std::string name;
  std::string summary;
  bool long_job = false;
  const char* one_item_lost = nullptr;
  std::function<std::unique_ptr<Command>()> make;
};

// A command class's entry in the table: its kInfo and its factory.
template <class C>
CommandEntry entry() {
  return {C::kInfo.name, C::kInfo.summary, C::kInfo.long_job, C::kInfo.one_item_lost,
          [] { return std::make_unique<C>(); }};
}

// Every command, in the order the help lists them.
const std::vector<CommandEntry>& command_table();
// The summary of a group of subcommands ("db").
std::string group_summary(const std::string& group);

}  // namespace tripack::commands
