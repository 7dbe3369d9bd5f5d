// Plots drawn by gnuplot (Debian gnuplot-nox): tripack writes the data (NAME.csv) and a readable
// script (NAME.gp) that reads it, then runs gnuplot on the script, so every axis, tic and legend
// comes from gnuplot and a user can restyle the script and rerun it (`gnuplot NAME.gp` in that
// directory). Each plot comes out as NAME.svg, NAME.png and NAME.pdf.
//
// Reruns give the same bytes: gnuplot runs with a fixed environment (no $HOME, so no ~/.gnuplot;
// TZ=UTC, C.UTF-8 locale), and the PDF's creation date, the only varying bytes (cairo 1.16 ignores
// SOURCE_DATE_EPOCH), is overwritten in place with 1970-01-01.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace tripack::report {

// delta(n) = L(n) - t(n) against n, like GL1995 Fig. 6.1.
struct DeltaPoint {
  long long n = 0;
  double delta = 0;
  std::string class_id;    // the class it belongs to ("" for n in no class: open squares)
  bool proven = false;     // proven optimum (Delta(k) and n <= 15): circled dot
  bool billiards = false;  // the billiards-best value (marked differently)
  bool atlas = false;      // the atlas's best (data/atlas.csv): a grey dot at every n
};
struct AccuracyPoint {
  std::string series;  // e.g. "n = 22 billiards", "n = 22 polish", ...
  double seconds = 0;
  double digits = 0;  // correct significant digits reached
};

// Each writes NAME.csv (the data), NAME.gp (the gnuplot script, reading NAME.csv, so a user can
// restyle and rerun it: `gnuplot NAME.gp`), then runs gnuplot to make NAME.svg, NAME.png,
// NAME.pdf in `dir`. Throws a one-line std::runtime_error naming the package (gnuplot-nox)
// when gnuplot is missing, and one naming the file when a write fails.
//
// Delta plot layers, drawn in this order: one line style per class joining its members
// (billiards == false) in n order; open squares for class_id == ""; a cross on every billiards
// point (never joined: it is a measurement, not a member of the class's formula); a ring around
// every proven point; last, on top, a small grey dot at every atlas point (atlas == true,
// class_id ""). Every layer has its entry in the key, below the graph in three columns
// (the canvas grows taller with the number of classes). A point in several classes is passed once
// per class. Log-scale n. Accuracy plot: one joined series per name, in seconds order, log-scale
// seconds; points with seconds <= 0 stay in the CSV but cannot be drawn on the log axis. Both keep
// the order in which classes / series first appear. Non-finite values, n < 1 and an empty point
// list are std::invalid_argument.
void plot_delta(const std::vector<DeltaPoint>& points, const std::filesystem::path& dir,
                const std::string& name = "delta");
void plot_accuracy(const std::vector<AccuracyPoint>& points, const std::filesystem::path& dir,
                   const std::string& name = "accuracy");
std::string find_gnuplot();  // path, or throws the one-line error; honours $TRIPACK_GNUPLOT

}  // namespace tripack::report
