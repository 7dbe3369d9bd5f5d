// The command table: every command once, in the order of the help, family by family (each
// family's file lists its commands, their summaries and which are long jobs). A new command is
// its Command and its entry in a family's file; a new family is its file plus its line here
// (docs/extending.md).
#include <initializer_list>

#include "commands/command.hpp"

namespace tripack::commands {

std::vector<CommandEntry> catalogue_commands();
std::vector<CommandEntry> packing_commands();
std::vector<CommandEntry> search_commands();
std::vector<CommandEntry> jobs_commands();
std::vector<CommandEntry> db_commands();

const std::vector<CommandEntry>& command_table() {
  static const std::vector<CommandEntry> table = [] {
    std::vector<CommandEntry> all;
    for (auto family :
         {catalogue_commands, packing_commands, search_commands, jobs_commands, db_commands})
      for (auto& entry : family()) all.push_back(std::move(entry));
    return all;
  }();
  return table;
}

std::string group_summary(const std::string& group) {
  if (group == "db") return "Read, check, export and import a campaign database";
  return group;
}

}  // namespace tripack::commands
