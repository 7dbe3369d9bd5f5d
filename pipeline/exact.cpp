#include "pipeline/exact.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/timing.hpp"
#include "polish/polish_mp.hpp"

namespace tripack::pipeline {

namespace {

// The file's coordinates as written ("x y" lines), when it has exactly n of them, and its label.
struct FileText {
  std::vector<std::array<std::string, 2>> points;
  std::string label;
};

FileText text_of(const std::string& file) {
  FileText out;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("# label:", 0) == 0) {
      std::istringstream words(line.substr(8));
      words >> out.label;
    }
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::string x, y, extra;
    if (!(words >> x >> y) || (words >> extra)) return {{}, out.label};
    out.points.push_back({x, y});
  }
  return out;
}

// Decimal places of the given coordinates (the fewest among them).
int decimals_of(const std::vector<std::array<std::string, 2>>& points) {
  int fewest = 1000000;
  for (const auto& p : points)
    for (const auto& c : p) {
      const auto dot = c.find('.');
      fewest =
          std::min(fewest, dot == std::string::npos ? 0 : static_cast<int>(c.size() - dot - 1));
    }
  return fewest;
}

// A fixed-notation decimal cut (not rounded) to 30 decimals: within 1e-30 of it.
std::string thirty_decimals(const std::string& text) {
  const auto dot = text.find('.');
  if (dot == std::string::npos) return text + "." + std::string(30, '0');
  std::string out = text.substr(0, dot + 31);
  out.append(dot + 31 - out.size(), '0');
  return out;
}

}  // namespace

std::string coordinates_text(const ExactResult& result, const std::string& label) {
  std::string out =
      "# tripack packing, unit-triangle convention: vertices (0,0) (1,0) (1/2,sqrt3/2)\n";
  out += fmt::format("# n: {}\n# label: {}\n# d: {}\n", result.n, label,
                     result.d.empty() ? std::string("") : thirty_decimals(result.d));
  for (const auto& p : result.input.given) out += p[0] + " " + p[1] + "\n";
  return out;
}

ExactResult exact_of_file(const std::string& file, const ExactSettings& settings) {
  AnalyzeRequest request;
  request.file = file;
  request.digits = 15;
  const FileAnalysis analysed = analyze_file(request);  // reads; throws InputError
  const FileText text = text_of(file);
  ExactResult result = exact_of_packing(
      analysed.analysis.pattern.packing,
      text.label.empty() ? std::filesystem::path(file).stem().string() : text.label, text.points,
      settings);
  result.file = file;
  return result;
}

ExactResult exact_of_packing(const Packing& packing, const std::string& label,
                             const std::vector<std::array<std::string, 2>>& given,
                             const ExactSettings& settings, const JobContext& job) {
  if (settings.digits < 40) throw std::invalid_argument("exact: --digits must be at least 40");
  if (settings.digits > 20000)
    throw std::invalid_argument(
        "exact: --digits must be at most 20000 (LLL at 2D digits beyond that takes hours)");
  ExactResult result;
  const auto stage = [&](const char* name) {
    throw_if_cancelled(job.cancel);
    Progress progress;
    progress.stage = name;
    progress.item = label;
    job.report(progress);
  };
  stage("analysis");
  const Analysis analysis = analyze_packing(packing, {});
  result.pattern = analysis.pattern;
  result.n = static_cast<int>(analysis.pattern.packing.size());
  FileText text{given, label};
  result.label = label;
  if (!analysis.certified()) {
    result.reason = "the packing is not certified: " + analysis.status();
    return result;
  }
  stage("polish");
  const auto start = Clock::now();
  MultiprecisionPolish polish =
      polish_multiprecision(analysis.pattern.packing, analysis.pattern.bonds,
                            analysis.pattern.rattlers, 2 * settings.digits);
  // Rattlers given to 27+ decimals stay where the file has them (below); others are centred in
  // their cages, a compass search whose cost grows with the digits (minutes at 2,000).
  const bool given_places = static_cast<int>(given.size()) == static_cast<int>(packing.size()) &&
                            decimals_of(given) >= 27;
  if (polish.converged && !analysis.pattern.rattlers.empty() && !given_places)
    centre_rattlers_multiprecision(polish, analysis.pattern.rattlers);
  result.seconds_polish = seconds_since(start);
  if (!polish.converged) {
    result.reason = fmt::format("the {}-digit polish did not converge", 2 * settings.digits);
    return result;
  }
  result.d = polish.d;
  // The given points: the file's own text when it is "x y" lines with enough digits for the
  // 10^-25 claim, else the polished points at 40 digits (the claim is then about those).
  std::string given_note;
  exact::ConfigurationInput& input = result.input;
  input.n = result.n;
  input.bonds = analysis.pattern.bonds;
  input.rattlers = analysis.pattern.rattlers;
  input.d = polish.d;
  input.points = polish.points;
  if (given_places) {
    input.given = text.points;
    result.given_tolerance = "1e-25";
    // A rattler is free in its cage: it stays where the file has it (checked strictly apart).
    for (int r : analysis.pattern.rattlers)
      input.points[static_cast<std::size_t>(r)] = text.points[static_cast<std::size_t>(r)];
  } else {
    for (const auto& p : polish.points)
      input.given.push_back({thirty_decimals(p[0]), thirty_decimals(p[1])});
    result.given_tolerance = "1e-25";
    given_note =
        "; the given points are the polish's, to 30 decimals (no coordinates with 27+ decimals "
        "given)";
  }
  // D, 2D, 4D, ... up to settings.digits; polish.d has 2 * settings.digits digits, and each
  // stage reads its first 2D of them.
  std::vector<int> ladder;
  const int first = settings.first_digits > 0 ? std::min(settings.first_digits, settings.digits)
                                              : settings.digits;
  for (int D = first; D < settings.digits; D *= 2) ladder.push_back(D);
  ladder.push_back(settings.digits);
  for (int D : ladder) {
    input.digits = D;
    if (!result.polynomial.found) {
      stage("polynomial");
      const auto t1 = Clock::now();
      result.polynomial = exact::minimal_polynomial(polish.d, D, settings.max_degree);
      result.seconds_polynomial += seconds_since(t1);
      if (!result.polynomial.found) {
        result.reason = result.polynomial.reason;
        continue;
      }
    }
    if (!settings.existence) {
      result.reason = "statement (I) not attempted";
      return result;
    }
    stage("existence");
    const auto t2 = Clock::now();
    result.configuration = exact::prove_existence(input, result.polynomial);
    result.seconds_existence += seconds_since(t2);
    if (!result.configuration->proven) {
      result.reason = result.configuration->reason;
      continue;
    }
    result.proof = "existence";
    stage("optimality");
    const auto t3 = Clock::now();
    result.optimality =
        exact::prove_strict_optimality(input, *result.configuration, analysis.stress.forces);
    result.seconds_optimality += seconds_since(t3);
    if (result.optimality->proven) {
      result.proof = "exact";
      result.reason = fmt::format("P from {} digits, the field and coordinates from {}{}",
                                  result.polynomial.digits, D, given_note);
    } else {
      result.reason = "statement (II): " + result.optimality->reason + given_note;
    }
    return result;
  }
  if (result.configuration && !result.configuration->proven) result.configuration.reset();
  return result;
}

}  // namespace tripack::pipeline
