// The atlas on disk: DIR/atlas.csv with the columns
//   n, rank, label, d, L, delta, bonds, rattlers, certified, confirmations, source, file
// (formats/tables.hpp; d and L as strings with the polish's significant digits, delta with L's
// decimals) and one
// coordinates file per row, DIR/atlas/<label>.txt: `x y` lines in the unit triangle with the
// polish's digits under the `# d:` header that `-o` writes. The format's one place: the writer
// (`tripack atlas`), the reader, and the loader the explorer draws the atlas from.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "jobs/atlas.hpp"

namespace tripack::jobs {

// Writes DIR/atlas.csv and DIR/atlas/*.txt (files of rows no longer in the atlas are removed, so
// the directory is exactly the table), and DIR/atlas-gaps.csv (class, p, k, n, n_label,
// next_label, L_n, L_next, L_difference, delta_difference, paper_tight: the tight/loose table).
// Coordinates files first, the tables last.
void write_atlas(const AtlasResult& atlas, const std::filesystem::path& dir);

// atlas.csv's text: the header and a line per row (`tripack atlas --csv` prints the same).
std::string atlas_table(const AtlasResult& atlas);

// DIR/atlas.csv read back: a record per row with its label, rank, d and L (the table's digits),
// its coordinates (from its file), `file`, and the source and confirmations columns as a Table
// source; bonds are not in the files (load_atlas analyses them). Throws a one-line
// std::runtime_error naming the file and line when the table or a file is missing or malformed.
std::vector<PackingRecord> read_atlas(const std::filesystem::path& csv);

// DIR/atlas-gaps.csv read back (the tight/loose table); same errors as read_atlas.
std::vector<AtlasGap> read_atlas_gaps(const std::filesystem::path& csv);

// The rows with rank <= max_rank, each file analysed again (bonds, rattlers, forces, the
// certificate from the file alone), with the table's label, rank, d and L. Same errors.
std::vector<PackingRecord> load_atlas(const std::filesystem::path& csv, long long max_rank);

}  // namespace tripack::jobs
