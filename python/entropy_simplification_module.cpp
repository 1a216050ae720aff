// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Python module entropy_simplification: the package on NumPy arrays of
// points. Each function takes an (n, 3) array of float64 or float32, of any
// strides (copied where needed; not complex, nor masked with values masked),
// and the library's options as keywords; it releases the GIL while it
// computes, and Ctrl-C raises KeyboardInterrupt at the library's next
// progress call.

#include <CGAL/Entropy_simplification/compute_entropy_importance.h>
#include <CGAL/Entropy_simplification/entropy_simplification_ranks.h>
#include <CGAL/Entropy_simplification/measure_simplification_quality.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include "thread_limit.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace py = pybind11;
namespace ES = CGAL::Entropy_simplification;
using Point = CGAL::Simple_cartesian<double>::Point_3;
using Tag = CGAL::Parallel_if_available_tag;

namespace {

// The rows of an (n, 3) array as points: a contiguous copy in doubles,
// made by NumPy only where the array is not one already.
using Points_array = py::array_t<double, py::array::c_style | py::array::forcecast>;

struct Row_point_map
{
  using key_type = std::size_t;
  using value_type = Point;
  using reference = value_type;
  using category = boost::readable_property_map_tag;

  const double* xyz;

  friend value_type get(const Row_point_map& map, std::size_t row)
  {
    return value_type(map.xyz[3 * row], map.xyz[3 * row + 1], map.xyz[3 * row + 2]);
  }
};

// The points of `array`, checked: the rows of the returned range are row
// numbers, read through `map`.
struct Rows
{
  Points_array array;
  std::vector<std::size_t> rows;
  Row_point_map map;
};

// Clears the Python error that a conversion of the caller's value raised,
// which the caller reports as a ValueError, unless it is an interruption
// (KeyboardInterrupt, SystemExit) or a MemoryError: those are raised as
// they are.
void clear_conversion_error()
{
  if (PyErr_Occurred() && (!PyErr_ExceptionMatches(PyExc_Exception) || PyErr_ExceptionMatches(PyExc_MemoryError)))
    throw py::error_already_set();
  PyErr_Clear();
}

// What `conversion()` gives, or none when the Python error it raised is
// one of a conversion, as for clear_conversion_error.
template <typename Conversion>
auto attempted(const Conversion& conversion) -> std::optional<decltype(conversion())>
{
  try
  {
    return conversion();
  }
  catch (py::error_already_set& e)
  {
    e.restore();
    clear_conversion_error();
    return std::nullopt;
  }
}

// `object` as an array of `Array`'s type and layout, converted by NumPy
// where needed, or none.
template <typename Array>
std::optional<Array> converted(const py::handle& object)
{
  return attempted([&] { return Array(py::reinterpret_borrow<py::object>(object)); });
}

// `object` as NumPy reads it, values unconverted and masked arrays kept as
// such (numpy.asanyarray), or none.
std::optional<py::object> as_numpy_array(const py::handle& object)
{
  return attempted([&] { return py::object(py::module_::import("numpy").attr("asanyarray")(object)); });
}

// Throws when `array` (see as_numpy_array) is a masked array with masked
// values: NumPy would read the values under the mask.
void require_nothing_masked(const py::object& array, const std::string& name, const std::string& remedy)
{
  const py::object ma = py::module_::import("numpy").attr("ma");
  if (py::isinstance(array, ma.attr("MaskedArray")) && ma.attr("is_masked")(array).cast<bool>())
    throw std::invalid_argument(name + " is a masked array with masked values: pass " + remedy);
}

// Throws when `object` is a sequence (a list, a tuple, a deque...) of
// masked arrays with masked values, such as list(masked_points): NumPy would
// read it without the masks, the values under them included. An object with
// a buffer (an array, a memoryview, bytes) holds numbers, not rows, and an
// array's masks are its own (require_nothing_masked). The rows' masks are
// gathered, then tested at once: a test per row took 1.9 s on 1,000,000 rows.
void require_no_masked_rows(const py::handle& object, const std::string& name)
{
  if (!py::isinstance<py::sequence>(object) || PyObject_CheckBuffer(object.ptr()) || py::isinstance<py::str>(object))
    return;
  const py::object numpy = py::module_::import("numpy"), ma = numpy.attr("ma");
  const py::object masked_array = ma.attr("MaskedArray"), getmask = ma.attr("getmask"), nomask = ma.attr("nomask");
  py::list masks;
  for (const py::handle row : object)
    if (py::isinstance(row, masked_array))
      if (py::object mask = getmask(row); !mask.is(nomask))
        masks.append(mask);
  if (!masks.empty() && numpy.attr("any")(masks).cast<bool>())
    throw std::invalid_argument(name + " is a list of masked rows with masked values: pass the rows to keep, as "
                                "m[~m.mask.any(axis=1)] for m = numpy.ma.array(" + name + ")");
}

// The points as an array of real numbers, or ValueError where NumPy would
// convert them silently but lose what they hold (masked values, imaginary
// parts) or read them as numbers they do not hold (booleans, text, dates,
// Python objects).
py::object real_values(const py::handle& points, const char* name)
{
  const std::optional<py::object> array = as_numpy_array(points);
  if (!array)
    throw std::invalid_argument(std::string(name) + " must be an (n, 3) array of numbers");
  require_nothing_masked(*array, name, std::string("the rows to keep, as ") + name + "[~" + name + ".mask.any(axis=1)]");
  // rows only: a sequence of masked blocks gets the error of its shape
  if (py::reinterpret_borrow<py::array>(*array).ndim() == 2)
    require_no_masked_rows(points, name);
  const py::dtype dtype = py::reinterpret_borrow<py::array>(*array).dtype();
  if (dtype.kind() != 'f' && dtype.kind() != 'i' && dtype.kind() != 'u')
    throw std::invalid_argument(std::string(name) + " must hold real numbers, not values of dtype " +
                                std::string(py::str(static_cast<const py::handle&>(dtype))));
  return *array;
}

Rows rows_of(const py::handle& points, const char* name)
{
  const std::optional<Points_array> array = converted<Points_array>(real_values(points, name));
  if (!array || array->ndim() != 2 || array->shape(1) != 3)
    throw std::invalid_argument(std::string(name) + " must be an (n, 3) array of numbers");
  Rows result{ *array, std::vector<std::size_t>(std::size_t(array->shape(0))), Row_point_map{ array->data() } };
  for (std::size_t i = 0; i < result.rows.size(); ++i)
    result.rows[i] = i;
  return result;
}

// The keyword options, checked as the program checks its own.
struct Call_options
{
  ES::Options options;
  unsigned int k = 10;
  std::optional<double> ratio;
  std::optional<std::size_t> count;
  std::optional<std::size_t> threads;
};

template <typename Value>
Value choice(const char* option, const std::string& text, const std::vector<std::pair<std::string, Value> >& choices)
{
  std::string names;
  for (const auto& c : choices)
  {
    if (c.first == text)
      return c.second;
    names += (names.empty() ? "'" : " or '") + c.first + "'";
  }
  throw std::invalid_argument(std::string(option) + " must be " + names + ", got '" + text + "'");
}

std::string repr(const py::object& value) { return py::repr(value).cast<std::string>(); }

// Whether `value` is a bool, Python's or NumPy's: one would read as 0 or 1.
bool is_boolean(const py::object& value)
{
  return py::isinstance<py::bool_>(value) || py::isinstance(value, py::module_::import("numpy").attr("bool_"));
}

// A keyword's value as text (a str), or ValueError.
std::string text(const py::object& value, const char* name)
{
  if (!py::isinstance<py::str>(value))
    throw std::invalid_argument(std::string(name) + " must be a string, got " + repr(value));
  return value.cast<std::string>();
}

// A keyword's value as a Python int (from an int or a NumPy integer, not a
// bool), or ValueError.
py::int_ whole_index(const py::object& value, const char* name)
{
  const py::object index = is_boolean(value) || !PyIndex_Check(value.ptr())
                             ? py::object()
                             : py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
  if (!index || !PyLong_Check(index.ptr()))
  {
    clear_conversion_error();
    throw std::invalid_argument(std::string(name) + " must be a whole number, got " + repr(value));
  }
  return py::reinterpret_borrow<py::int_>(index);
}

// The same, as the integer type that `convert` gives (PyLong_AsLongLong,
// say), or ValueError.
template <typename Integer>
Integer whole_number(const py::object& value, const char* name, Integer (*convert)(PyObject*))
{
  const py::int_ index = whole_index(value, name);
  const Integer n = convert(index.ptr());
  if (n == Integer(-1) && PyErr_Occurred())
  {
    clear_conversion_error();
    throw std::invalid_argument(std::string(name) + " is out of range, got " + repr(value));
  }
  return n;
}

long long whole_number(const py::object& value, const char* name)
{
  return whole_number<long long>(value, name, PyLong_AsLongLong);
}

// A keyword's value as a number, or ValueError. A NumPy value is one real
// number (a scalar or an array of no dimension), and a float32 or float16
// stands for the decimal NumPy prints it as: float32's 0.1 is
// 0.100000001490116, and as a ratio would keep 201 points of 2,000.
double real_number(const py::object& value, const char* name)
{
  const py::module_ numpy = py::module_::import("numpy");
  if (py::isinstance<py::array>(value) || py::isinstance(value, numpy.attr("generic")))
  {
    const py::array array = numpy.attr("asarray")(value);
    const char kind = array.dtype().kind();
    if (array.ndim() != 0 || (kind != 'f' && kind != 'i' && kind != 'u'))
      throw std::invalid_argument(std::string(name) + " must be a number, got " + repr(value));
    if (kind == 'f' && array.dtype().itemsize() < py::ssize_t(sizeof(double)))
      return real_number(py::float_(numpy.attr("format_float_positional")(array[py::tuple()])), name);
    return array[py::tuple()].cast<double>();
  }
  const bool number = !is_boolean(value) && PyNumber_Check(value.ptr());
  const double x = number ? PyFloat_AsDouble(value.ptr()) : 0.;
  if (!number || (x == -1. && PyErr_Occurred()))
  {
    clear_conversion_error();
    throw std::invalid_argument(std::string(name) + " must be a number, got " + repr(value));
  }
  return x;
}

Call_options call_options(const py::object& ratio, const py::object& count, const py::object& k, const py::object& mode,
                          const py::object& feature_weight, const py::object& normals, const py::object& order,
                          const py::object& threads)
{
  Call_options c;
  if (!ratio.is_none() && !count.is_none())
    throw std::invalid_argument("give only one of ratio and count");
  if (!ratio.is_none())
  {
    c.ratio = real_number(ratio, "ratio");
    if (!(*c.ratio > 0. && *c.ratio <= 1.))
      throw std::invalid_argument("ratio must lie in (0, 1], got " + repr(ratio));
  }
  if (!count.is_none())
  {
    // up to 2^64 - 1, as the program's --count: a count above the number
    // of points keeps them all
    if (whole_index(count, "count") < py::int_(1))
      throw std::invalid_argument("count must be at least 1, got " + repr(count));
    c.count = std::size_t(whole_number<unsigned long long>(count, "count", PyLong_AsUnsignedLongLong));
  }
  const long long kk = whole_number(k, "k");
  if (kk < 0 || kk > 1000000)
    throw std::invalid_argument("k = " + std::to_string(kk) + " is out of range");
  c.k = unsigned(kk);
  c.options.mode = choice<ES::Mode>(
    "mode", text(mode, "mode"), { { "default", ES::Mode::weighted_elimination }, { "paper", ES::Mode::paper } });
  c.options.normal_estimation =
    choice<ES::Normal_estimation>("normals", text(normals, "normals"),
                                  { { "pca", ES::Normal_estimation::pca }, { "jet", ES::Normal_estimation::jet } });
  if (!feature_weight.is_none())
  {
    if (c.options.mode == ES::Mode::paper)
      throw std::invalid_argument("feature_weight applies to the default mode only");
    c.options.feature_weight = real_number(feature_weight, "feature_weight");
  }
  if (!order.is_none())
  {
    if (c.options.mode != ES::Mode::paper)
      throw std::invalid_argument("order applies to mode='paper' only");
    c.options.removal_order = choice<ES::Removal_order>(
      "order", text(order, "order"), { { "lowest", ES::Removal_order::lowest_entropy_first },
                                       { "highest", ES::Removal_order::highest_entropy_first } });
  }
  if (!threads.is_none())
  {
    const long long n = whole_number(threads, "threads");
    if (n < 1)
      throw std::invalid_argument("threads must be at least 1, got " + std::to_string(n));
    c.threads = std::size_t(n);
  }
  return c;
}

// Runs `compute(callback)` without the GIL, on at most `threads` worker
// threads. The callback, which the library calls on this thread, takes the
// GIL back to check for signals: a pending KeyboardInterrupt stops the
// computation, and is raised once it has stopped.
template <typename Compute>
auto without_gil(const std::optional<std::size_t>& threads, const Compute& compute)
{
  bool interrupted = false;
  const std::function<bool(double)> callback = [&interrupted](double) {
    py::gil_scoped_acquire gil;
    interrupted = interrupted || PyErr_CheckSignals() != 0;
    return !interrupted;
  };
  decltype(compute(callback)) result;
  {
    py::gil_scoped_release released;
    const entropy_simplify::Thread_limit limit(threads);
    result = compute(callback);
  }
  if (interrupted)
    throw py::error_already_set();
  return result;
}

// The rank of every row, the level of `c` (if any) exact.
std::vector<std::size_t> ranks_of(const Rows& points, const Call_options& c)
{
  return without_gil(c.threads, [&](const std::function<bool(double)>& callback) {
    std::vector<std::size_t> ranks;
    ranks.reserve(points.rows.size());
    const auto np = CGAL::parameters::point_map(points.map).callback(callback);
    const auto into = std::back_inserter(ranks);
    const bool done =
      c.ratio   ? CGAL::entropy_simplification_ranks<Tag>(points.rows, c.k, into,
                                                          np.select_percentage(*c.ratio * 100.), c.options)
      : c.count ? CGAL::entropy_simplification_ranks<Tag>(points.rows, c.k, into,
                                                          np.number_of_output_points(*c.count), c.options)
                : CGAL::entropy_simplification_ranks<Tag>(points.rows, c.k, into, np, c.options);
    if (!done)
      ranks.clear();
    return ranks;
  });
}

template <typename T>
py::array_t<T> to_array(const std::vector<T>& values)
{
  py::array_t<T> array(py::ssize_t(values.size()));
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}

py::array_t<std::int64_t> simplify(const py::handle& points, const py::object& ratio, const py::object& count,
                                   const py::object& k, const py::object& mode, const py::object& feature_weight,
                                   const py::object& normals, const py::object& order, const py::object& threads)
{
  const Call_options c = call_options(ratio, count, k, mode, feature_weight, normals, order, threads);
  if (!c.ratio && !c.count)
    throw std::invalid_argument("give one of ratio and count");
  const Rows rows = rows_of(points, "points");
  const std::size_t n = rows.rows.size();
  const std::size_t kept = c.ratio ? ES::internal::kept_count_from_percentage(n, *c.ratio * 100.)
                                   : (std::min)(n, *c.count);
  // refused where a direct call refuses it (in the paper's mode, fewer than
  // k + 1 points): the ranks alone would take any count
  if (n > 0)
    ES::internal::check_simplification_arguments(n, n, c.k, kept, c.options);
  const std::vector<std::size_t> ranks = ranks_of(rows, c);
  std::vector<std::int64_t> by_rank(n);
  for (std::size_t i = 0; i < n; ++i)
    by_rank[ranks[i]] = std::int64_t(i);
  by_rank.resize(kept);
  return to_array(by_rank);
}

py::array_t<std::int64_t> ranks(const py::handle& points, const py::object& ratio, const py::object& count,
                                const py::object& k, const py::object& mode, const py::object& feature_weight,
                                const py::object& normals, const py::object& order, const py::object& threads)
{
  const Call_options c = call_options(ratio, count, k, mode, feature_weight, normals, order, threads);
  const std::vector<std::size_t> r = ranks_of(rows_of(points, "points"), c);
  return to_array(std::vector<std::int64_t>(r.begin(), r.end()));
}

py::array_t<double> importance(const py::handle& points, const py::object& k, const py::object& mode,
                               const py::object& normals, const py::object& threads)
{
  const Call_options c = call_options(py::none(), py::none(), k, mode, py::none(), normals, py::none(), threads);
  Rows rows = rows_of(points, "points");
  return to_array(without_gil(c.threads, [&](const std::function<bool(double)>& callback) {
    std::vector<double> values(rows.rows.size());
    if (!CGAL::compute_entropy_importance<Tag>(rows.rows, c.k, CGAL::make_property_map(values),
                                               CGAL::parameters::point_map(rows.map).callback(callback), c.options))
      values.clear();
    return values;
  }));
}

// The indices of `integers`, an array of integers of the signedness of
// `Integer`, each below `n`.
template <typename Integer>
std::vector<std::size_t> indices_below(const py::array& integers, std::size_t n)
{
  using Indices = py::array_t<Integer, py::array::c_style | py::array::forcecast>;
  const std::optional<Indices> converted_indices = converted<Indices>(integers);
  if (!converted_indices)
    throw std::invalid_argument("kept_idx cannot be read as indices");
  const Indices& indices = *converted_indices;
  std::vector<std::size_t> kept(std::size_t(indices.size()));
  for (std::size_t j = 0; j < kept.size(); ++j)
  {
    const Integer i = indices.data()[j];
    if ((std::is_signed<Integer>::value && i < 0) || std::uint64_t(i) >= n)
      throw std::invalid_argument("kept_idx holds " + std::to_string(i) + ", not an index of the " +
                                  std::to_string(n) + " points");
    kept[j] = std::size_t(i);
  }
  return kept;
}

// Throws when an index repeats: a kept point counted twice would weigh
// twice in the planes fitted to the kept points.
void require_distinct(std::vector<std::size_t> indices)
{
  std::sort(indices.begin(), indices.end());
  const auto repeated = std::adjacent_find(indices.begin(), indices.end());
  if (repeated != indices.end())
    throw std::invalid_argument("kept_idx holds the index " + std::to_string(*repeated) + " more than once");
}

// The kept indices: a one-dimensional array of integers, each an index of
// the `n` points. Booleans, which would read as the indices 0 and 1, and
// floats, which would be truncated, are refused.
std::vector<std::size_t> kept_indices_of(const py::handle& object, std::size_t n)
{
  const std::optional<py::object> as_read = as_numpy_array(object);
  if (as_read)
    require_nothing_masked(*as_read, "kept_idx", "kept_idx.compressed()");
  const std::optional<py::array> converted_array = converted<py::array>(as_read ? *as_read : object);
  if (!converted_array || converted_array->ndim() != 1)
    throw std::invalid_argument("kept_idx must be a one-dimensional array of indices");
  const py::array& array = *converted_array;
  // an empty array, of any dtype, keeps nothing
  if (array.size() == 0)
    return {};
  const char kind = array.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw std::invalid_argument("kept_idx must hold integers, not values of dtype " +
                                std::string(py::str(array.dtype())) +
                                (kind == 'b' ? " (for a mask of kept points, pass numpy.flatnonzero(mask))" : ""));
  std::vector<std::size_t> kept =
    kind == 'u' ? indices_below<std::uint64_t>(array, n) : indices_below<std::int64_t>(array, n);
  require_distinct(kept);
  return kept;
}

py::dict report(const py::handle& points, const py::handle& kept_indices)
{
  const Rows rows = rows_of(points, "points");
  const std::vector<std::size_t> kept = kept_indices_of(kept_indices, rows.rows.size());
  const ES::Quality_report r = without_gil(std::nullopt, [&](const std::function<bool(double)>&) {
    return CGAL::measure_simplification_quality<Tag>(rows.rows, kept, CGAL::parameters::point_map(rows.map),
                                                     CGAL::parameters::point_map(rows.map));
  });
  py::dict d;
  d["mean_distance"] = r.mean_distance;
  d["max_distance"] = r.max_distance;
  d["point_to_plane"] = r.point_to_plane;
  d["diagonal"] = r.diagonal;
  d["input_size"] = r.input_size;
  d["kept_size"] = r.kept_size;
  return d;
}

} // namespace

PYBIND11_MODULE(entropy_simplification, m)
{
  m.doc() = "Point cloud simplification by the local entropy of normals (CGAL package Entropy_simplification).";
  const char* options_doc =
    "ratio: the fraction of the points to keep, in (0, 1] (a float32 as the decimal it prints as);\n"
    "count: the number of points to keep, up to 2**64 - 1 (all of them when above their number).\n"
    "k: neighbours per point (default 10). mode: 'default' or 'paper'. feature_weight: default mode,\n"
    "features keep up to 1 + W times the density of flat regions (default 3). normals: 'pca' or 'jet'.\n"
    "order: paper mode, 'lowest' (default) or 'highest' entropy removed first. threads: at most N\n"
    "worker threads (default: all). Bad input raises ValueError; Ctrl-C raises KeyboardInterrupt.";
  m.def("simplify", &simplify, py::arg("points"), py::kw_only(), py::arg("ratio") = py::none(),
        py::arg("count") = py::none(), py::arg("k") = 10, py::arg("mode") = "default",
        py::arg("feature_weight") = py::none(), py::arg("normals") = "pca", py::arg("order") = py::none(),
        py::arg("threads") = py::none(),
        (std::string("simplify(points, *, ratio=None, count=None, ...) -> int64 array: the indices of the kept "
                     "points, in rank order (the most important first); exactly one of ratio and count.\n") +
         options_doc)
          .c_str());
  m.def("ranks", &ranks, py::arg("points"), py::kw_only(), py::arg("ratio") = py::none(),
        py::arg("count") = py::none(), py::arg("k") = 10, py::arg("mode") = "default",
        py::arg("feature_weight") = py::none(), py::arg("normals") = "pca", py::arg("order") = py::none(),
        py::arg("threads") = py::none(),
        (std::string("ranks(points, *, ratio=None, count=None, ...) -> int64 array: the rank of each point, 0 "
                     "kept longest; the points of rank below m are a simplification to m points. In the default "
                     "mode, the level of ratio or count is exactly simplify()'s result, and the longer prefixes are "
                     "not relocated; without one, the prefixes at 50, 20, 10, 5, 2, 1, 0.5, ...% are.\n") +
         options_doc)
          .c_str());
  m.def("importance", &importance, py::arg("points"), py::kw_only(), py::arg("k") = 10,
        py::arg("mode") = "default", py::arg("normals") = "pca", py::arg("threads") = py::none(),
        "importance(points, *, k=10, mode='default', normals='pca', threads=None) -> float64 array: the value "
        "each mode orders the points by, on the input: the feature strength in [0, 1] (default mode), the "
        "entropy of normal angles of Eq. 5 in nats (paper mode).");
  m.def("report", &report, py::arg("points"), py::arg("kept_idx"),
        "report(points, kept_idx) -> dict: the quality of the points kept_idx against all points: "
        "mean_distance, max_distance (to the nearest kept point) and point_to_plane, over the bounding-box "
        "diagonal; diagonal, input_size, kept_size.");
}
