// The builders of the vacancy-segment classes (classes.yaml; docs/classes.md "Vacancy segments"):
// a lattice with a straight vacancy segment, relaxed, and its Delta(2)-inflation. Each is a rule
// in k: the enumeration is over every straight segment of the lattice up to symmetry, and no
// stored packing is read.
#include <stdexcept>

#include "constructors/registry.hpp"
#include "patterns/inflation.hpp"
#include "patterns/vacancy_lattice.hpp"

namespace tripack::patterns {

namespace {

// Delta(rows) minus the best straight segment of `vacancies` sites.
Pattern build_vacancy_segment(const BuilderCall& c) {
  return best_vacancy_segment(c.arg("rows"), c.arg("vacancies")).pattern;
}

// The Delta(2)-inflation of that packing: Delta(2 rows - 1) - (2 vacancies - 1) disks, side
// L + rows - 1 (docs/findings.md §3), relaxed only to find its bonds.
Pattern build_inflated_segment(const BuilderCall& c) {
  const Pattern base = best_vacancy_segment(c.arg("rows"), c.arg("vacancies")).pattern;
  const auto inflated = inflate_by_two(base.packing);
  if (!inflated)
    throw std::runtime_error("the base packing does not round onto its lattice: no inflation");
  return relax_to_pattern(*inflated);
}

const BuilderRegistration kVacancySegment{"vacancy-segment", build_vacancy_segment};
const BuilderRegistration kInflatedSegment{"inflated-segment", build_inflated_segment};

}  // namespace

}  // namespace tripack::patterns
