// The builders of the vacancy classes (classes.yaml; docs/classes.md "Vacancy segments"): a
// lattice with a straight vacancy segment, relaxed, and its Delta(2)-inflation; a lattice with a
// whole line of vacancies, one of them jogged off the line. Each is a rule in k: the enumeration
// is over every such vacancy set of the lattice up to symmetry, and no stored packing is read.
#include <stdexcept>

#include "constructors/registry.hpp"
#include "patterns/inflation.hpp"
#include "patterns/vacancy_lattice.hpp"

namespace tripack::patterns {

namespace {

// The enumeration's settings with the call's progress and cancel token.
SegmentEnumeration segment_enumeration(const BuilderCall& c) {
  SegmentEnumeration search;
  if (c.control) {
    search.progress = c.control->progress;
    search.cancel = c.control->cancel;
    search.exhaustive = c.control->exhaustive;
    search.threads = c.control->threads;
  }
  return search;
}

// Delta(rows) minus the best straight segment of `vacancies` sites.
Pattern build_vacancy_segment(const BuilderCall& c) {
  return best_vacancy_segment(c.arg("rows"), c.arg("vacancies"), segment_enumeration(c)).pattern;
}

// The Delta(2)-inflation of that packing: Delta(2 rows - 1) - (2 vacancies - 1) disks, side
// L + rows - 1 (docs/findings.md §3), relaxed only to find its bonds. A long segment in a small
// lattice (8 sites in Delta(10)) relaxes too far from its sites to round onto them; then the
// unrelaxed lattice with the same segment is inflated instead (it rounds by construction), and
// the relax after the inflation finds the slip.
Pattern build_inflated_segment(const BuilderCall& c) {
  const long rows = c.arg("rows");
  const long vacancies = c.arg("vacancies");
  const SegmentChoice base = best_vacancy_segment(rows, vacancies, segment_enumeration(c));
  // A long slip can also round some disks onto the neighbouring site, which changes the vacancy
  // set and the inflated n (k = 2, p = 20: 913 disks instead of 907); the lattice then too.
  const std::size_t expected =
      static_cast<std::size_t>(triangular(2 * rows - 1) - (2 * vacancies - 1));
  auto inflated = inflate_by_two(base.pattern.packing);
  if (!inflated || inflated->size() != expected)
    inflated = inflate_by_two(lattice_with_vacancies(rows, base.vacancies));
  if (!inflated || inflated->size() != expected)
    throw std::logic_error("a lattice with a vacancy segment does not inflate to its class's n");
  // As the enumeration relaxes (patterns/vacancy_lattice.hpp): exhaustively up to 300 disks.
  const bool exhaustive =
      (c.control && c.control->exhaustive) ||
      static_cast<long>(inflated->size()) <= segment_enumeration(c).all_segments_up_to;
  return relax_to_pattern(*inflated, exhaustive);
}

// Delta(rows) minus the best jogged line `line` lines from a wall.
Pattern build_jogged_line(const BuilderCall& c) {
  return best_jogged_line(c.arg("rows"), c.arg("line"), segment_enumeration(c)).pattern;
}

const BuilderRegistration kVacancySegment{"vacancy-segment", build_vacancy_segment};
const BuilderRegistration kInflatedSegment{"inflated-segment", build_inflated_segment};
const BuilderRegistration kJoggedLine{"jogged-line", build_jogged_line};

}  // namespace

}  // namespace tripack::patterns
