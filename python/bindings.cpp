// The compiled core of the Python module (docs/python.md): the library's calls, not the command
// line's. Each call runs the same pipeline function as its command, with the same defaults, and
// returns packings as PackingCore (a packing record and its description) and results as their
// descriptions (report/results/), which python/tripack/__init__.py turns into Python objects.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/data_directory.hpp"
#include "core/io.hpp"
#include "formats/formats.hpp"
#include "formats/tables.hpp"
#include "jobs/billiards_runs.hpp"
#include "pipeline/analyze.hpp"
#include "pipeline/build.hpp"
#include "pipeline/exact.hpp"
#include "python/background.hpp"
#include "python/keyword_options.hpp"
#include "report/diagram.hpp"
#include "report/results/analysis.hpp"
#include "report/results/billiards.hpp"
#include "report/results/build.hpp"
#include "report/results/catalogue.hpp"
#include "report/results/database.hpp"
#include "report/results/exact.hpp"
#include "report/results/search.hpp"
#include "search/search.hpp"

namespace py = pybind11;

namespace tripack::python {

namespace {

// A packing as the module hands it out: the record every layer passes (core/record.hpp) and the
// description of the result it came from (its certificate, as the CLI's --json prints it).
struct PackingCore {
  PackingRecord record;
  report::Tree description;
  std::string name;  // the label, or the builder's member
};

// nlohmann's tree -> Python objects, through the json module (keys keep their order).
py::object to_python(const report::Tree& tree) {
  return py::module_::import("json").attr("loads")(tree.dump());
}

template <class Result>
py::object describe(const Result& result) {
  return to_python(report::View<Result>::describe(result, {}).fields);
}

py::array_t<double> points_array(const PackingRecord& r) {
  const auto& points = r.pattern.packing.points;
  py::array_t<double> a({static_cast<py::ssize_t>(points.size()), py::ssize_t{2}});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i) {
    m(i, 0) = static_cast<double>(points[i].x);
    m(i, 1) = static_cast<double>(points[i].y);
  }
  return a;
}

// Bonds as in the files (docs/formats.md): (a, b) with b = -1 - side for a wall bond.
py::array_t<std::int64_t> bonds_array(const PackingRecord& r) {
  const auto& bonds = r.pattern.bonds;
  py::array_t<std::int64_t> a({static_cast<py::ssize_t>(bonds.size()), py::ssize_t{2}});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < bonds.size(); ++i) {
    m(i, 0) = bonds[i].a;
    m(i, 1) = bonds[i].b;
  }
  return a;
}

template <class T>
py::array_t<T> vector_array(const std::vector<T>& values) {
  py::array_t<T> a(static_cast<py::ssize_t>(values.size()));
  auto m = a.template mutable_unchecked<1>();
  for (std::size_t i = 0; i < values.size(); ++i) m(i) = values[i];
  return a;
}

// Each coordinate with every digit known: the MPFR polish's, else a long double's round trip.
std::vector<std::array<std::string, 2>> points_decimal(const PackingRecord& r) {
  if (!r.precise_points.empty()) return r.precise_points;
  std::vector<std::array<std::string, 2>> out;
  for (const auto& p : r.pattern.packing.points)
    out.push_back({format_significant(p.x, kLongDoubleRoundTripDigits),
                   format_significant(p.y, kLongDoubleRoundTripDigits)});
  return out;
}

std::string svg_of(const PackingCore& p, bool forces) {
  report::DiagramOptions options;
  options.forces = forces && !p.record.forces.empty();
  return report::diagram_svg({p.record.pattern, p.name, p.record.d.str(15), p.record.forces},
                             options);
}

Catalogue catalogue() {
  return Catalogue::load(Catalogue::default_path());
}

// A call's keywords as its command's options (python/keyword_options.hpp).
using Keywords = std::map<std::string, std::string>;

PackingCore build_call(const Keywords& keywords, const py::object& progress) {
  BuildRequest member{"", pipeline::kUnsetK, 0, ""};
  long long n = 0;
  pipeline::BuildSettings settings;
  KeywordOptions options(keywords);
  pipeline::declare_member(options, member, false);
  options.option("--n", n, "number of disks");
  settings.declare(options);
  options.check_all_used();
  const Catalogue classes = catalogue();
  const auto result = run_in_background(
      [&](const JobContext& job) {
        return pipeline::build_requested(classes, member, n, settings, job);
      },
      progress);
  return {result.best.record, report::View<pipeline::BestBuild>::describe(result, {}).fields,
          pipeline::member_name(result.best.record.pattern.provenance)};
}

PackingCore analyze_call(
    const py::array_t<double, py::array::c_style | py::array::forcecast>& points,
    const Keywords& keywords, const std::string& name, const py::object& progress) {
  if (points.ndim() != 2 || (points.shape(1) != 2 && points.shape(1) != 3))
    throw std::invalid_argument(
        "analyze: points must be an (n, 2) array of x y, or (n, 3) of x y r");
  PointsFile file;
  file.layout = points.shape(1) == 2 ? "array x y" : "array x y r";
  const auto a = points.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    if (!std::isfinite(a(i, 0)) || !std::isfinite(a(i, 1)))
      throw std::invalid_argument("analyze: point " + std::to_string(i) + " is not finite");
    file.points.push_back({static_cast<long double>(a(i, 0)), static_cast<long double>(a(i, 1))});
    if (a.shape(1) == 3) {
      if (file.radius && *file.radius != a(i, 2))
        throw std::invalid_argument("analyze: the radius column must hold one value");
      file.radius = a(i, 2);
    }
  }
  pipeline::AnalyzeRequest request;
  KeywordOptions options(keywords);
  request.declare(options);
  options.check_all_used();
  request.file = name;
  const auto result = run_in_background(
      [&](const JobContext& job) {
        pipeline::AnalyzeRequest r = request;
        r.progress = job.progress;
        return pipeline::analyze_points(std::move(file), r);
      },
      progress);
  if (!result.warnings.empty()) {
    const auto warn = py::module_::import("warnings").attr("warn");
    for (const auto& w : result.warnings) warn(w, py::none(), 2);  // at the caller's line
  }
  PackingRecord record = pipeline::record_of(result.analysis);
  record.label = name;
  return {record, report::View<pipeline::FileAnalysis>::describe(result, {}).fields, name};
}

// The distinct packings of a search or billiards run, each described as the database's tables
// describe a ranked packing.
std::vector<PackingCore> ranked_packings(const std::vector<PackingRecord>& records) {
  std::vector<PackingCore> out;
  for (const auto& r : records) out.push_back({r, report::results::ranked_tree(r, {}), r.label});
  return out;
}

py::tuple search_call(const Keywords& keywords, const py::object& progress) {
  search::SearchRequest request;
  KeywordOptions options(keywords);
  request.declare(options);
  options.check_all_used();
  std::optional<Catalogue> classes;  // as the command: read only when the chains start from it
  if (request.builder_starts && request.method == search::SearchMethod::BasinHopping) {
    classes.emplace(catalogue());
    request.builders = &*classes;
  }
  const auto result = run_in_background(
      [&](const JobContext& job) { return search::run_search(request, job); }, progress);
  return py::make_tuple(ranked_packings(result.packings), describe(result));
}

py::tuple billiards_call(const Keywords& keywords, const py::object& progress) {
  long long n = 0;
  jobs::BilliardsRunsRequest request;
  KeywordOptions options(keywords);
  options.option("N", n, "number of disks").range(1, 1e7);  // as `tripack billiards N`
  request.declare(options);
  options.flag("!--no-certify", request.certify, "");
  options.check_all_used();
  request.scene = default_scene(static_cast<int>(n));
  jobs::prepare_scene(catalogue(), request.scene, n);
  const auto result = run_in_background(
      [&](const JobContext& job) { return jobs::billiards_runs(request, job); }, progress);
  return py::make_tuple(ranked_packings(result.packings), describe(result));
}

// atlas.csv as read (formats/tables.hpp): its columns and a list of fields per row.
py::tuple atlas_table() {
  const auto& format = atlas_table_format();
  std::vector<std::vector<std::string>> rows;
  for (auto& r : read_table(data_directory() / format.file, format)) rows.push_back(r.fields);
  return py::make_tuple(format.columns, rows);
}

py::object exact_call(const PackingCore& packing, const Keywords& keywords,
                      const py::object& progress) {
  pipeline::ExactSettings settings;
  KeywordOptions options(keywords);
  settings.declare(options);
  options.check_all_used();
  const auto given = points_decimal(packing.record);
  const auto result = run_in_background(
      [&](const JobContext& job) {
        return pipeline::exact_of_packing(packing.record.pattern.packing, packing.name, given,
                                          settings, job);
      },
      progress);
  report::Tree row = report::results::exact_row(result);
  row["coefficients"] = result.polynomial.found
                            ? report::Tree(result.polynomial.polynomial.coefficients)
                            : report::Tree(nullptr);
  return to_python(row);
}

void write_file(const PackingCore& p, const std::string& path, int digits) {
  WriteOptions options;
  options.digits = options.d_digits = std::max(digits, kLongDoubleRoundTripDigits);
  write_packing_file(path, p.record, options);
}

}  // namespace

py::dict progress_dict(const Progress& p) {
  py::dict d;
  d["stage"] = p.stage;
  d["item"] = p.item;
  d["done"] = p.done;
  d["total"] = p.total;
  d["fraction"] = p.fraction >= 0 ? py::object(py::float_(p.fraction)) : py::object(py::none());
  d["elapsed"] = p.elapsed;
  d["d"] = p.d > 0 ? py::object(py::float_(static_cast<double>(p.d))) : py::object(py::none());
  d["events"] = p.events;
  return d;
}

}  // namespace tripack::python

PYBIND11_MODULE(_tripack, m) {
  using namespace tripack;
  using namespace tripack::python;
  m.doc() = "tripack's compiled core; use the tripack package (docs/python.md)";

  // Failures of tripack's own (not of the input): tripack.Error; python/tripack/__init__.py
  // names the subclasses. Bad input keeps Python's ValueError with the CLI's one-line message.
  static py::exception<std::runtime_error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<std::runtime_error> data_error(m, "DataError", error.ptr());
  error.attr("__doc__") = "A failure of tripack's own (not of the input).";
  data_error.attr("__doc__") = "tripack's installed data (the catalogue) cannot be read.";
  py::register_exception_translator([](std::exception_ptr failure) {
    try {
      if (failure) std::rethrow_exception(failure);
    } catch (const Cancelled&) {
      PyErr_SetNone(PyExc_KeyboardInterrupt);
    } catch (const Abandoned&) {
      PyErr_SetNone(PyExc_KeyboardInterrupt);
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const MemberError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const CatalogueError& e) {
      data_error(e.what());
    } catch (const std::runtime_error& e) {
      error(e.what());
    }
  });

  py::class_<PackingCore>(m, "PackingCore", "A packing record and its result's description")
      .def_property_readonly("points", [](const PackingCore& p) { return points_array(p.record); })
      .def_property_readonly("points_decimal",
                             [](const PackingCore& p) { return points_decimal(p.record); })
      .def_property_readonly(
          "d", [](const PackingCore& p) { return static_cast<double>(p.record.d.value()); })
      .def_property_readonly(
          "d_decimal", [](const PackingCore& p) { return p.record.d.str(p.record.d.digits()); })
      .def_property_readonly("bonds", [](const PackingCore& p) { return bonds_array(p.record); })
      .def_property_readonly(
          "rattlers",
          [](const PackingCore& p) { return vector_array<int>(p.record.pattern.rattlers); })
      .def_property_readonly("forces",
                             [](const PackingCore& p) {
                               std::vector<double> f(p.record.forces.begin(),
                                                     p.record.forces.end());
                               return vector_array<double>(f);
                             })
      .def_property_readonly("certified", [](const PackingCore& p) { return p.record.certified; })
      .def_property_readonly("verdict", [](const PackingCore& p) { return p.record.verdict; })
      .def_property_readonly("name", [](const PackingCore& p) { return p.name; })
      .def_property_readonly("description",
                             [](const PackingCore& p) { return to_python(p.description); })
      .def("svg", &svg_of, py::arg("forces") = false)
      .def("write", &write_file, py::arg("path"), py::arg("digits") = 30);

  m.def("classes", [] { return describe(catalogue()); });
  m.def("build", &build_call, py::arg("keywords"), py::arg("progress"));
  m.def("analyze", &analyze_call, py::arg("points"), py::arg("keywords"), py::arg("name"),
        py::arg("progress"));
  m.def("search", &search_call, py::arg("keywords"), py::arg("progress"));
  m.def("billiards", &billiards_call, py::arg("keywords"), py::arg("progress"));
  m.def("exact", &exact_call, py::arg("packing"), py::arg("keywords"), py::arg("progress"));
  m.def("atlas_table", &atlas_table);
  m.def("data_directory", [] { return data_directory().string(); });
}
