// The atlas on disk (issue 12): DIR/atlas.csv with the columns
//   n, rank, label, d, L, delta, bonds, rattlers, certified, source, file
// (d and L as strings with the polish's significant digits, delta with L's decimals) and one
// coordinates file per row, DIR/atlas/<label>.txt: `x y` lines in the unit triangle with the
// polish's digits under the `# d:` header that `-o` writes. The format's one place: the writer
// (`tripack atlas`), the reader, and the loader the explorer draws the atlas from.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "campaign/atlas.hpp"

namespace tripack::campaign {

// Writes DIR/atlas.csv and DIR/atlas/*.txt (files of rows no longer in the atlas are removed, so
// the directory is exactly the table), and DIR/atlas-gaps.csv (class, p, k, n, n_label,
// next_label, L_n, L_next, L_difference, delta_difference, paper_tight: the tight/loose table).
// Coordinates files first, the tables last.
void write_atlas(const AtlasResult& atlas, const std::filesystem::path& dir);

// atlas.csv's text: the header and a line per row (`tripack atlas --csv` prints the same).
std::string atlas_table(const AtlasResult& atlas);

// A row of atlas.csv as read back (strings as written).
struct AtlasEntry {
  long long n = 0;
  long long rank = 0;
  std::string label, d, L, delta;
  long long bonds = 0, rattlers = 0;
  bool certified = false;
  std::string source, file;
};

// Reads DIR/atlas.csv; throws a one-line std::runtime_error naming the file and line when it is
// missing or malformed.
std::vector<AtlasEntry> read_atlas(const std::filesystem::path& csv);

// DIR/atlas-gaps.csv read back (the tight/loose table); same errors as read_atlas.
std::vector<AtlasGap> read_atlas_gaps(const std::filesystem::path& csv);

// A row with its packing: the file read back and analysed (the files keep no bonds), so it can
// be drawn with its bonds, rattlers and forces.
struct AtlasPacking {
  AtlasEntry entry;
  Pattern pattern;
  std::vector<long double> forces;  // the stress certificate's, per bond
  bool certified = false;           // certified again from the file
};

// The rows of atlas.csv with rank <= max_rank, each file read and analysed. Throws a one-line
// error for a missing or malformed table or file.
std::vector<AtlasPacking> load_atlas(const std::filesystem::path& csv, long long max_rank);

}  // namespace tripack::campaign
