// The atlas on disk (issue 12): DIR/atlas.csv with the columns
//   n, rank, label, d, L, delta, bonds, rattlers, certified, source, file
// (d and L as strings with the polish's significant digits, delta with L's decimals) and one
// coordinates file per row, DIR/atlas/<label>.txt: `x y` lines in the unit triangle with the
// polish's digits under the `# d:` header that `-o` writes. This file is the format's one place:
// the writer, the reader (the explorer draws the atlas) and the `tripack atlas` renderers.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "campaign/atlas.hpp"

namespace tripack::report {

struct RenderOptions;  // report/render.hpp

// Writes DIR/atlas.csv and DIR/atlas/*.txt (files of rows no longer in the atlas are removed, so
// the directory is exactly the table). Coordinates files first, the table last.
void write_atlas(const campaign::AtlasResult& atlas, const std::filesystem::path& dir);

// A row of atlas.csv as read back (strings as written).
struct AtlasEntry {
  long long n = 0;
  long long rank = 0;
  std::string label, d, L, delta;
  long long bonds = 0, rattlers = 0;
  bool certified = false;
  std::string source, file;
};

// Reads DIR/atlas.csv; throws a one-line error naming the file and line when it is malformed.
std::vector<AtlasEntry> read_atlas(const std::filesystem::path& csv);

// `tripack atlas`: a line per n (its best row), the builders that fell short, the errors.
void render_text(std::ostream& out, const campaign::AtlasResult& a, const RenderOptions& o);
void render_json(std::ostream& out, const campaign::AtlasResult& a, const RenderOptions& o);
void render_csv(std::ostream& out, const campaign::AtlasResult& a, const RenderOptions& o);

}  // namespace tripack::report
