// What the command line prints around the commands: the help's footer (the packing-file formats,
// listed from the format table) and an error in the output format the command was asked for.
#pragma once

#include <string>

namespace tripack::commands {

std::string help_footer();
// What stdout gets of an error: {"error": message} for json, a one-column table for csv,
// nothing for text (the error line is on stderr in every format).
std::string error_output(const std::string& message, const std::string& format);
// The format a command line asks for (--json, --csv, --output-format NAME or =NAME), read before
// parsing so that a parse error follows it too; "text" when none.
std::string requested_format(int argc, const char* const* argv);

}  // namespace tripack::commands
