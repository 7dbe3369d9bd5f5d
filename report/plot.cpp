#include "report/plot.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <tuple>

#include "report/fields.hpp"

namespace tripack::report {
namespace fs = std::filesystem;

namespace {

constexpr std::string_view kInstallHint = "install the Debian package gnuplot-nox";

// Colour-blind-safe (Okabe-Ito) colours, then dash patterns, so two classes never look alike.
constexpr std::array<std::string_view, 8> kColours = {"#0072b2", "#d55e00", "#009e73", "#cc79a7",
                                                      "#e69f00", "#56b4e9", "#000000", "#999933"};
constexpr int kDashTypes = 5;  // gnuplot's dt 1..5 differ on every terminal

// The delta plot's key, below the graph: in kKeyColumns columns of kKeyRowPixels-high rows (at
// the SVG's 12 points), the canvas as much taller than kCanvasHeight as the rows need.
constexpr std::size_t kKeyColumns = 3;
constexpr int kKeyRowPixels = 18;
constexpr int kCanvasHeight = 650;

std::string style_line(std::size_t i, std::string_view points) {
  return fmt::format("set style line {} lc rgb '{}' dt {} lw 1.5 {}\n", i + 1,
                     kColours[i % kColours.size()], 1 + (i / kColours.size()) % kDashTypes, points);
}

bool is_executable(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec) && ::access(p.c_str(), X_OK) == 0;
}

std::string search_path(const std::string& program) {
  const char* env = std::getenv("PATH");
  std::istringstream dirs(env && *env ? env : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    // Absolute: gnuplot runs in the plot's directory, where a relative PATH entry means nothing.
    const fs::path candidate = fs::absolute(fs::path(dir.empty() ? "." : dir) / program);
    if (is_executable(candidate)) return candidate.string();
  }
  return {};
}

// A gnuplot string literal: single quotes take everything literally except '' for a quote.
std::string gp_string(std::string_view s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'')
      out += "''";
    else if (c == '\n' || c == '\r')
      out += ' ';
    else
      out += c;
  }
  return out + "'";
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("cannot read {}", path.string()));
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void check_name(const std::string& name) {
  if (name.empty() || name == "." || name == ".." ||
      name.find_first_of(std::string_view("/\0", 2)) != std::string::npos) {
    throw std::invalid_argument(fmt::format("plot name '{}' is not a plain file name", name));
  }
}

fs::path prepare_dir(const fs::path& dir) {
  const fs::path d = dir.empty() ? fs::path(".") : dir;
  std::error_code ec;
  fs::create_directories(d, ec);
  if (ec) throw std::runtime_error(fmt::format("cannot create {}: {}", d.string(), ec.message()));
  return d;
}

// The last non-blank line gnuplot wrote: its error message ("file" line N: what), on one line.
std::string last_line(const std::string& text) {
  std::istringstream in(text);
  std::string last;
  for (std::string line; std::getline(in, line);) {
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  }
  const auto first = last.find_first_not_of(" \t");
  return first == std::string::npos ? std::string("no message") : last.substr(first);
}

// Runs `gnuplot SCRIPT` in `dir` with argument vectors (no shell, so no quoting of user paths)
// and a fixed environment: no $HOME (a user's ~/.gnuplot would change the output), UTC and a
// fixed locale. Its stderr is captured to turn a failure into one line.
void run_gnuplot(const std::string& gnuplot, const fs::path& dir, const std::string& script) {
  int err_pipe[2];
  if (::pipe2(err_pipe, O_CLOEXEC) != 0) {
    throw std::runtime_error(fmt::format("cannot run gnuplot: pipe: {}", std::strerror(errno)));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, err_pipe[1], 2);

  // "./": a script name starting with '-' must not read as an option.
  std::vector<std::string> args = {gnuplot, "./" + script};
  std::vector<std::string> env = {"PATH=/usr/bin:/bin", "LC_ALL=C.UTF-8", "TZ=UTC",
                                  "SOURCE_DATE_EPOCH=0"};
  std::vector<char*> argv, envp;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  for (auto& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);

  pid_t pid = 0;
  const int spawned =
      ::posix_spawn(&pid, gnuplot.c_str(), &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  ::close(err_pipe[1]);
  if (spawned != 0) {
    ::close(err_pipe[0]);
    throw std::runtime_error(
        fmt::format("cannot run {} in {}: {}", gnuplot, dir.string(), std::strerror(spawned)));
  }
  std::string err;
  std::array<char, 4096> buffer;
  for (;;) {
    const ssize_t got = ::read(err_pipe[0], buffer.data(), buffer.size());
    if (got > 0) {
      if (err.size() < (1u << 20)) err.append(buffer.data(), static_cast<std::size_t>(got));
    } else if (got == 0 || errno != EINTR) {
      break;
    }
  }
  ::close(err_pipe[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    const std::string how = WIFEXITED(status) ? fmt::format("exit {}", WEXITSTATUS(status))
                                              : fmt::format("signal {}", WTERMSIG(status));
    throw std::runtime_error(
        fmt::format("gnuplot failed on {} ({}): {}", (dir / script).string(), how, last_line(err)));
  }
}

// cairo 1.16 stamps the PDF with the current time and ignores SOURCE_DATE_EPOCH: the creation
// date is the only byte that differs between runs. Overwrite its digits with 1970-01-01 00:00:00
// (zone 00'00) in place: same length, so the cross-reference offsets stay right.
void fix_pdf_dates(const fs::path& pdf) {
  std::string bytes = read_file(pdf);
  constexpr std::string_view kFixed = "19700101000000";
  bool changed = false;
  for (std::string_view key : {"/CreationDate (", "/ModDate ("}) {
    for (auto at = bytes.find(key); at != std::string::npos; at = bytes.find(key, at + 1)) {
      const auto begin = at + key.size(), end = bytes.find(')', begin);
      if (end == std::string::npos) break;
      std::size_t digit = 0;
      for (auto i = begin; i < end; ++i) {
        if (bytes[i] < '0' || bytes[i] > '9') continue;
        const char fixed = digit < kFixed.size() ? kFixed[digit] : '0';
        changed = changed || bytes[i] != fixed;
        bytes[i] = fixed;
        ++digit;
      }
    }
  }
  if (changed) write_whole_file(pdf, bytes);
}

// The three terminals, each followed by the plot (the first) or `replot`. The PNG and the SVG
// share a pixel size (1200 x `height`; the PDF 1 in per 100 pixels); fonts are the generic
// sans-serif, which fontconfig and browsers both map.
std::string terminals(const std::string& name, const std::string& plot,
                      int height = kCanvasHeight) {
  std::string s;
  s += fmt::format("set terminal svg size 1200,{} font 'sans-serif,12' background rgb 'white'\n",
                   height);
  s += "set output " + gp_string(name + ".svg") + "\n" + plot;
  s += fmt::format(
      "set terminal pngcairo size 1200,{} font 'sans-serif,11' background rgb 'white'\n", height);
  s += "set output " + gp_string(name + ".png") + "\nreplot\n";
  s += fmt::format("set terminal pdfcairo size 12in,{}in font 'sans-serif,11' pointscale 0.6\n",
                   height / 100.0);
  s += "set output " + gp_string(name + ".pdf") + "\nreplot\nunset output\n";
  return s;
}

// Writes the data and script, removes stale pictures (a failed run must not leave old ones
// looking current), runs gnuplot and makes the PDF byte-stable.
void render(const fs::path& dir, const std::string& name, const std::string& csv,
            const std::string& script) {
  const std::string gnuplot = find_gnuplot();  // before writing anything: fail fast
  const fs::path d = prepare_dir(dir);
  write_whole_file(d / (name + ".csv"), csv);
  write_whole_file(d / (name + ".gp"), script);
  for (const char* ext : {".svg", ".png", ".pdf"}) {
    std::error_code ec;
    fs::remove(d / (name + ext), ec);
  }
  run_gnuplot(gnuplot, d, name + ".gp");
  for (const char* ext : {".svg", ".png", ".pdf"}) {
    if (!fs::exists(d / (name + ext))) {
      throw std::runtime_error(
          fmt::format("gnuplot ran but did not write {}", (d / (name + ext)).string()));
    }
  }
  fix_pdf_dates(d / (name + ".pdf"));
}

// Tics at 1, 2, 5 x 10^k inside [lo, hi] (every integer mantissa when that gives too few): log
// axes' default tics (powers of ten only) make n hard to read.
std::string log_tics(double lo, double hi) {
  std::vector<std::string> tics;
  for (const std::vector<int>& mantissas :
       {std::vector<int>{1, 2, 5}, std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9}}) {
    tics.clear();
    for (double decade = std::pow(10.0, std::floor(std::log10(lo))); decade <= hi; decade *= 10) {
      for (int m : mantissas) {
        const double t = m * decade;
        if (t >= lo && t <= hi) tics.push_back(fmt::format("{}", t));
      }
    }
    if (tics.size() >= 3) break;
  }
  std::string s;
  for (const auto& t : tics) s += (s.empty() ? "" : ", ") + t;
  return "set xtics (" + s + ")\nset mxtics default\n";
}

// Order of first appearance (the caller's order), so the legend reads as the caller listed.
template <class Point, class Key>
std::vector<std::string> first_appearance(const std::vector<Point>& points, Key key) {
  std::vector<std::string> out;
  for (const auto& p : points) {
    const std::string& k = key(p);
    if (std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
  }
  return out;
}

std::string gp_array(const std::string& var, const std::vector<std::string>& items) {
  std::string s = fmt::format("array {}[{}] = [", var, items.size());
  for (std::size_t i = 0; i < items.size(); ++i) s += (i ? ", " : "") + gp_string(items[i]);
  return s + "]\n";
}

std::string join_plot(const std::vector<std::string>& clauses) {
  std::string s = "plot ";
  for (std::size_t i = 0; i < clauses.size(); ++i) s += (i ? ", \\\n     " : "") + clauses[i];
  return s + "\n";
}

// How to remake the pictures by hand, after a script's title line; the caller ends the sentence.
std::string rerun_note(const std::string& name) {
  return fmt::format(
      "# Written by tripack. Rerun it in this directory, `gnuplot {0}.gp`, to remake\n"
      "# {0}.svg, .png and .pdf from {0}.csv after restyling (a run by hand\n"
      "# stamps the PDF with the current date; tripack's own run stamps 1970-01-01",
      name);
}

// The data file NAME.csv, comma-separated, as the script's variable `data`.
std::string data_settings(const std::string& name) {
  return "set encoding utf8\nset datafile separator comma\ndata = " + gp_string(name + ".csv") +
         "\n";
}

// The delta plot's data: rows grouped by class (classless last), constructed before billiards,
// then by n, so that each class line joins one contiguous block (see the script's comment).
std::string delta_csv(const std::vector<DeltaPoint>& points,
                      const std::vector<std::string>& classes) {
  std::map<std::string, std::size_t> rank;
  for (std::size_t i = 0; i < classes.size(); ++i) rank[classes[i]] = i;
  rank[""] = classes.size();
  std::vector<DeltaPoint> rows = points;
  std::stable_sort(rows.begin(), rows.end(), [&](const DeltaPoint& a, const DeltaPoint& b) {
    return std::tuple(rank.at(a.class_id), a.billiards, a.atlas, a.n) <
           std::tuple(rank.at(b.class_id), b.billiards, b.atlas, b.n);
  });
  std::string csv = "n,delta,class,class_no,proven,billiards,atlas\n";
  for (const auto& r : rows) {
    const std::size_t class_no = r.class_id.empty() ? 0 : rank.at(r.class_id) + 1;
    csv += fmt::format("{},{},{},{},{},{},{}\n", r.n, r.delta, csv_field(r.class_id), class_no,
                       int(r.proven), int(r.billiards), int(r.atlas));
  }
  return csv;
}

// What the delta plot spans (the limit line always inside) and which marker kinds it draws.
struct DeltaExtent {
  double n_lo = 0, n_hi = 0, y_lo = 0, y_hi = 0;
  bool classless = false, billiards = false, proven = false, atlas = false;
};

DeltaExtent delta_extent(const std::vector<DeltaPoint>& points) {
  DeltaExtent e;
  e.n_lo = e.n_hi = double(points[0].n);
  e.y_hi = std::sqrt(3.0) - 1.5;
  for (const auto& p : points) {
    e.n_lo = std::min(e.n_lo, double(p.n));
    e.n_hi = std::max(e.n_hi, double(p.n));
    e.y_lo = std::min(e.y_lo, p.delta);
    e.y_hi = std::max(e.y_hi, p.delta);
    e.classless = e.classless || (p.class_id.empty() && !p.atlas);
    e.billiards = e.billiards || p.billiards;
    e.atlas = e.atlas || p.atlas;
    e.proven = e.proven || p.proven;
  }
  return e;
}

// The plot command's clauses, each with its key entry: the class lines, then the markers, the
// atlas's grey dots last (on top of the squares, crosses and rings), then the limit line.
std::vector<std::string> delta_clauses(bool has_classes, const DeltaExtent& e) {
  std::vector<std::string> clauses;
  if (has_classes) {
    clauses.push_back(
        "for [i=1:|classes|] data skip 1 using 1:($4 == i && $6 == 0 ? $2 : NaN) \\\n"
        "       with linespoints ls i title classes[i]");
  }
  // Each marker kind drawn: its clause, in drawing order.
  const std::pair<bool, const char*> markers[] = {
      {e.classless,
       "data skip 1 using 1:($4 == 0 && $7 == 0 ? $2 : NaN) with points ls 101 "
       "title 'in no class: best found'"},
      {e.billiards,
       "data skip 1 using 1:($6 == 1 ? $2 : NaN) with points ls 102 "
       "title 'best of the billiards runs'"},
      {e.proven,
       "data skip 1 using 1:($5 == 1 ? $2 : NaN) with points ls 103 title 'proven optimum'"},
      {e.atlas,
       "data skip 1 using 1:($7 == 1 ? $2 : NaN) with points ls 105 title 'atlas best known'"}};
  for (const auto& [drawn, clause] : markers)
    if (drawn) clauses.push_back(clause);
  clauses.push_back("limit with lines ls 104 title 'limit of delta(4Delta(k))'");
  return clauses;
}

// The delta plot's gnuplot script: as it reads, a few substitutions aside.
std::string delta_script(const std::string& name, const std::vector<std::string>& classes,
                         const DeltaExtent& e) {
  std::string gp =
      "# delta(n) = L(n) - t(n) against n, like Graham & Lubachevsky (1995), Fig. 6.1.\n" +
      rerun_note(name) + " so its\n# files are the same bytes every time).\n#\n";
  gp += fmt::format(
      R"gp(# {name}.csv columns: 1 n, 2 delta, 3 class ('' = in no class), 4 class_no (its
# index in `classes` below, 0 = in no class), 5 proven (1/0), 6 billiards (1/0), 7 atlas
# (1/0: the best of data/atlas.csv, a grey dot). The
# clauses filter on class_no, not on the name: gnuplot's strcol() cuts a quoted CSV field
# at its first blank. Rows are sorted by class, constructed before billiards, then n, so
# each class line joins one contiguous block of rows: the rows a clause filters out are
# NaN, and a NaN between two members would break the line.
#
# Oler's bound: L(n) >= t(n) = (-3 + sqrt(8n+1))/2, so delta(n) >= 0, and 0 at n = Delta(k).
# n is on a log scale: on a linear axis up to a few hundred, the n where most is known
# (2..40: the proven optima and the classless n) would be squeezed into the left edge.

)gp",
      fmt::arg("name", name));
  gp += data_settings(name);
  if (!classes.empty()) gp += gp_array("classes", classes);
  gp += "\n# One line style per class (colour, then dash pattern), dots at the members.\n";
  for (std::size_t i = 0; i < classes.size(); ++i) gp += style_line(i, "pt 7 ps 0.6");
  gp += R"gp(set style line 101 lc rgb 'black' pt 4 ps 1.2 lw 1   # n in no class: open square
set style line 102 lc rgb '#b2182b' pt 2 ps 1.4 lw 1.5 # billiards best: cross
set style line 103 lc rgb 'black' pt 6 ps 1.9 lw 1   # proven optimum: ring
set style line 105 lc rgb '#737373' pt 7 ps 0.45      # atlas best: grey dot

set title "Distance from Oler's bound\nt(n) = (-3 + sqrt(8n+1))/2,  L(n) = 1/d(n)"
set xlabel 'n'
set ylabel 'delta(n) = L(n) - t(n)'
set logscale x
)gp";
  const double span = e.y_hi - e.y_lo;
  gp += fmt::format("set xrange [{:.6g}:{:.6g}]\n", e.n_lo / 1.15, e.n_hi * 1.15);
  gp += fmt::format("set yrange [{:.6g}:{:.6g}]\n", e.y_lo - 0.04 * span, e.y_hi + 0.06 * span);
  gp += log_tics(e.n_lo / 1.15, e.n_hi * 1.15);
  gp += "set grid xtics ytics lc rgb '#e0e0e0'\n";
  // The key: one entry per class line and per marker kind drawn, and the limit line; below the
  // graph, in columns. On the right in one column, 30 classes ran off the bottom of the picture,
  // and with them the entries of the markers, listed last.
  const std::size_t entries = classes.size() + std::size_t(e.classless) + std::size_t(e.billiards) +
                              std::size_t(e.proven) + std::size_t(e.atlas) + 1;
  const std::size_t key_rows = (entries + kKeyColumns - 1) / kKeyColumns;
  const int height = kCanvasHeight + static_cast<int>(key_rows) * kKeyRowPixels + 20;
  gp += fmt::format(
      R"gp(# The key below the graph, in columns of at most {rows} entries (the canvas is
# as much taller as they need); the graph ends at 88% of the width, the label naming
# the limit line on the right axis sits right of it.
set rmargin at screen 0.8833
set key outside below center vertical maxrows {rows} Left reverse samplen 2 noenhanced width 2

)gp",
      fmt::arg("rows", key_rows));
  gp +=
      R"gp(# Both delta(4Delta(k)) and delta(2Delta(k+1)+2Delta(k)-1) tend to sqrt(3) - 3/2 (GL1995, sec. 6).
# Its value is a tic label on the right axis, its meaning in the key (a label on the line
# itself would sit on some class line sooner or later).
limit = sqrt(3) - 1.5
set link y2
set y2tics ('sqrt(3) - 3/2' limit) tc rgb 'gray30'
set style line 104 lc rgb 'gray40' dt 2 lw 1

# Drawn in this order, each with its key entry: the class lines, then the markers, the
# atlas's small grey dots last, on top of the squares, crosses and rings around them.
)gp";
  return gp + terminals(name, join_plot(delta_clauses(!classes.empty(), e)), height);
}

}  // namespace

std::string find_gnuplot() {
  if (const char* forced = std::getenv("TRIPACK_GNUPLOT"); forced && *forced) {
    const std::string path = std::string(forced).find('/') == std::string::npos
                                 ? search_path(forced)
                                 : (is_executable(forced) ? fs::absolute(forced).string() : "");
    if (!path.empty()) return path;
    throw std::runtime_error(
        fmt::format("gnuplot not found: TRIPACK_GNUPLOT={} is not an executable file; {}", forced,
                    kInstallHint));
  }
  if (std::string path = search_path("gnuplot"); !path.empty()) return path;
  throw std::runtime_error(fmt::format(
      "gnuplot not found on PATH: {} (or set TRIPACK_GNUPLOT to gnuplot's path)", kInstallHint));
}

void plot_delta(const std::vector<DeltaPoint>& points, const fs::path& dir,
                const std::string& name) {
  check_name(name);
  if (points.empty()) throw std::invalid_argument("plot_delta: no points to plot");
  for (const auto& p : points) {
    if (p.n < 1 || !std::isfinite(p.delta)) {
      throw std::invalid_argument(
          fmt::format("plot_delta: bad point n = {}, delta = {}", p.n, p.delta));
    }
  }
  std::vector<std::string> classes = first_appearance(
      points, [](const DeltaPoint& p) -> const std::string& { return p.class_id; });
  classes.erase(std::remove(classes.begin(), classes.end(), ""), classes.end());
  render(dir, name, delta_csv(points, classes), delta_script(name, classes, delta_extent(points)));
}

void plot_accuracy(const std::vector<AccuracyPoint>& points, const fs::path& dir,
                   const std::string& name) {
  check_name(name);
  if (points.empty()) throw std::invalid_argument("plot_accuracy: no points to plot");
  bool drawable = false;
  for (const auto& p : points) {
    if (!std::isfinite(p.seconds) || !std::isfinite(p.digits)) {
      throw std::invalid_argument(fmt::format("plot_accuracy: bad point in '{}': {} s, {} digits",
                                              p.series, p.seconds, p.digits));
    }
    drawable = drawable || p.seconds > 0;
  }
  if (!drawable) {
    throw std::invalid_argument("plot_accuracy: no point has seconds > 0 (the axis is log)");
  }
  const std::vector<std::string> series = first_appearance(
      points, [](const AccuracyPoint& p) -> const std::string& { return p.series; });
  std::map<std::string, std::size_t> rank;
  for (std::size_t i = 0; i < series.size(); ++i) rank[series[i]] = i;
  std::vector<AccuracyPoint> rows = points;
  std::stable_sort(rows.begin(), rows.end(), [&](const AccuracyPoint& a, const AccuracyPoint& b) {
    return std::tuple(rank.at(a.series), a.seconds) < std::tuple(rank.at(b.series), b.seconds);
  });
  std::string csv = "series,series_no,seconds,digits\n";
  for (const auto& r : rows) {
    csv += fmt::format("{},{},{},{}\n", csv_field(r.series), rank.at(r.series) + 1, r.seconds,
                       r.digits);
  }

  std::string gp =
      "# Accuracy against time: correct significant digits reached against wall time.\n" +
      rerun_note(name) + ").\n#\n";
  gp +=
      fmt::format(R"gp(# {name}.csv columns: 1 series, 2 series_no (its index in `series` below: the
# filter, as gnuplot's strcol() cuts a quoted CSV field at its first blank), 3 seconds,
# 4 digits. Rows are sorted by series, then seconds, so each series' line joins one
# contiguous block of rows (the rows a clause filters out are NaN). Seconds <= 0 cannot
# sit on the log axis: NaN too.

)gp",
                  fmt::arg("name", name));
  gp += data_settings(name);
  gp += gp_array("series", series);
  gp += "\n# One line style per series (colour, then dash pattern; point types cycle).\n";
  for (std::size_t i = 0; i < series.size(); ++i) {
    gp += style_line(i, fmt::format("pt {} ps 1.0", std::array{7, 5, 9, 13, 11}[i % 5]));
  }
  gp += R"gp(
set title 'Accuracy costs time'
set xlabel 'wall time (s)'
set ylabel 'correct significant digits'
set logscale x
set format x '10^{%L}'
set yrange [0:*]
set offsets 0, 0, graph 0.05, 0  # room above the top point
set grid xtics ytics lc rgb '#e0e0e0'
set key outside right top Left reverse noenhanced

)gp";
  gp += terminals(name, join_plot({"for [i=1:|series|] data skip 1 using ($3 > 0 ? $3 : NaN):"
                                   "($2 == i ? $4 : NaN) \\\n"
                                   "       with linespoints ls i title series[i]"}));
  render(dir, name, csv, gp);
}

}  // namespace tripack::report
