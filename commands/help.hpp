// What the command line prints around the commands: the help's footer (the packing-file formats,
// listed from the format table) and an error as one JSON object.
#pragma once

#include <string>

namespace tripack::commands {

std::string help_footer();
std::string error_json(const std::string& message);  // {"error": message} and a line break

}  // namespace tripack::commands
