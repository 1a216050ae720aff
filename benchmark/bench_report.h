// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The benchmark's outputs: CSV, the data and gnuplot scripts of the figures,
// and RESULTS.md.

#ifndef ENTROPY_SIMPLIFICATION_BENCH_REPORT_H
#define ENTROPY_SIMPLIFICATION_BENCH_REPORT_H

#include "bench_inputs.h"
#include "bench_machine.h"
#include "bench_metrics.h"
#include "bench_methods.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace bench {

struct Quality_row
{
  std::string input, method, family;
  double ratio = 0.;
  std::size_t target = 0, count = 0, reached = 0;
  std::vector<double> parameters;
  Quality quality;
  bool skipped = false;
};

struct Timing_row
{
  std::string input, method;
  double ratio = 0.;
  std::size_t size = 0;
  double pca_seconds = 0.;
  Timing timing;
  int runs = 0;
  bool skipped = false;
};

struct Input_summary
{
  std::string name, description;
  std::size_t size = 0, labelled = 0;
  double pca_seconds = 0., seconds = 0.;
  bool is_replica = false;
  Input_role role = Input_role::tuned;
  Quality original; // the metrics of the input itself (coverage 0)
};

struct Report
{
  std::vector<Input_summary> inputs;
  std::vector<Quality_row> quality;
  // the default mode at other feature weights (bench_feature_sweep.h), apart
  // so that no other table or chart lists them
  std::vector<Quality_row> feature_sweep;
  std::vector<Timing_row> timing;
  bool quick = false;
  int repeats = 3;
  double skip_seconds = 0., total_seconds = 0.;
  // the optional peer families (benchmark/CMakeLists.txt), each described
  std::vector<std::string> peers_built, peers_not_built;
};

inline std::string file_name(const std::string& method)
{
  std::string s;
  for (char c : method)
    s += std::isalnum((unsigned char)c) ? char(std::tolower((unsigned char)c)) : '_';
  return s;
}

inline std::string scientific(double v)
{
  std::ostringstream s;
  s << std::scientific << std::setprecision(2) << v;
  return s.str();
}

inline std::string percent(double v) { return fixed(100. * v, 1) + "%"; }

inline const Quality_row* find_row(const Report& r, const std::string& input, const std::string& method, double ratio)
{
  for (const Quality_row& q : r.quality)
    if (q.input == input && q.method == method && q.ratio == ratio && !q.skipped)
      return &q;
  return nullptr;
}

inline const Timing_row* find_timing(const Report& r, const std::string& input, const std::string& method,
                                     double ratio)
{
  for (const Timing_row& t : r.timing)
    if (t.input == input && t.method == method && t.ratio == ratio && !t.skipped)
      return &t;
  return nullptr;
}

inline const Input_summary* find_input(const Report& r, const std::string& name)
{
  for (const Input_summary& s : r.inputs)
    if (s.name == name)
      return &s;
  return nullptr;
}

inline std::vector<std::string> methods_of(const Report& r)
{
  std::vector<std::string> names;
  for (const Quality_row& q : r.quality)
    if (std::find(names.begin(), names.end(), q.method) == names.end())
      names.push_back(q.method);
  for (const Timing_row& t : r.timing)
    if (std::find(names.begin(), names.end(), t.method) == names.end())
      names.push_back(t.method);
  return names;
}

// The family a method was registered with ("package", "paper baseline",
// "CGAL", "PCL", "Open3D"), or "" if it has no quality row.
inline std::string family_of(const Report& r, const std::string& method)
{
  for (const Quality_row& q : r.quality)
    if (q.method == method)
      return q.family;
  return "";
}

// The simplifiers of other libraries a user would pick instead of the
// package: CGAL's, and PCL's and Open3D's where they were built.
inline bool is_library_family(const std::string& family)
{
  return family == "CGAL" || family == "PCL" || family == "Open3D";
}

inline bool is_library_peer(const Report& r, const std::string& method)
{
  return is_library_family(family_of(r, method));
}

inline std::vector<std::string> library_peers(const Report& r)
{
  std::vector<std::string> peers;
  for (const std::string& m : methods_of(r))
    if (is_library_peer(r, m))
      peers.push_back(m);
  return peers;
}

inline std::vector<double> ratios_of(const Report& r, const std::string& input)
{
  std::set<double> s;
  for (const Quality_row& q : r.quality)
    if (q.input == input)
      s.insert(q.ratio);
  return std::vector<double>(s.begin(), s.end());
}

inline void write_csv(const Report& r, const std::string& dir)
{
  std::ofstream q(dir + "/quality.csv");
  q << "input,method,family,percent,target,count,reached_before_trim,parameters,mean,p95,p99,max,point_to_plane,"
       "uniformity,mean_entropy,labelled,sphere_radius,plane_rmse,skipped\n";
  q.precision(10);
  for (const Quality_row& row : r.quality)
  {
    const Quality& m = row.quality;
    std::string parameters;
    for (double p : row.parameters)
      parameters += (parameters.empty() ? "" : ";") + std::to_string(p);
    q << row.input << ',' << '"' << row.method << '"' << ',' << row.family << ',' << row.ratio << ',' << row.target
      << ',' << row.count << ',' << row.reached << ',' << parameters << ',' << m.mean << ',' << m.p95 << ','
      << m.p99 << ',' << m.max << ',' << m.point_to_plane << ',' << m.uniformity << ',' << m.mean_entropy << ','
      << m.labelled << ',' << m.sphere_radius << ',' << m.plane_rmse << ',' << row.skipped << '\n';
  }
  std::ofstream t(dir + "/timing.csv");
  t << "input,method,percent,size,seconds,normal_seconds,pca_seconds,ratio_to_pca,runs,skipped\n";
  t.precision(6);
  for (const Timing_row& row : r.timing)
    t << row.input << ',' << '"' << row.method << '"' << ',' << row.ratio << ',' << row.size << ','
      << row.timing.seconds << ',' << row.timing.normal_seconds << ',' << row.pca_seconds << ','
      << row.timing.seconds / row.pca_seconds << ',' << row.runs << ',' << row.skipped << '\n';
}

// A colour and a marker of its own for each method; the package's methods
// drawn thicker.
inline std::string line_style(const std::vector<std::string>& methods, std::size_t m)
{
  static const char* const colours[] = { "#d62728", "#ff7f0e", "#1f77b4", "#17becf", "#2ca02c", "#bcbd22",
                                         "#000000", "#7f7f7f", "#9467bd", "#e377c2", "#8c564b", "#aec7e8",
                                         "#98df8a", "#ff9896", "#c5b0d5", "#c49c94", "#dbdb8d", "#9edae5" };
  const bool package = methods[m].rfind("entropy", 0) == 0;
  std::ostringstream s;
  s << "with linespoints lw " << (package ? 3 : 1.5) << " pt " << (m % 13) + 1 << " lc rgb '"
    << colours[m % (sizeof colours / sizeof *colours)] << "'";
  return s.str();
}

// A multiplot panel holding only the key: one invisible curve per method.
inline void write_key_panel(std::ostream& gp, const std::vector<std::string>& methods)
{
  gp << "set key center center box font 'sans,11'\nunset title\nunset border\nunset tics\nunset grid\n"
     << "unset xlabel\nset xrange [0:1]\nset yrange [0:1]\nunset logscale\nplot ";
  for (std::size_t m = 0; m < methods.size(); ++m)
    gp << (m ? ", " : "") << "NaN " << line_style(methods, m) << " title '" << methods[m] << "'";
  gp << "\nunset key\nset border\nset tics\nset grid\nset xlabel 'points kept (%)'\nset autoscale\n"
     << "set logscale x\n";
}

// One data file per input, one block per method (gnuplot's `index`), and one
// script drawing every metric against the ratio.
inline void write_charts(const Report& r, const std::string& dir)
{
  const std::vector<std::string> methods = methods_of(r);
  std::vector<std::string> inputs;
  for (const Input_summary& s : r.inputs)
    if (!ratios_of(r, s.name).empty())
      inputs.push_back(s.name);

  for (const std::string& input : inputs)
  {
    std::ofstream data(dir + "/data_" + input + ".dat");
    data.precision(8);
    const Input_summary* summary = find_input(r, input);
    for (const std::string& method : methods)
    {
      data << "# " << method << "\n";
      for (double ratio : ratios_of(r, input))
        if (const Quality_row* q = find_row(r, input, method, ratio))
          data << ratio << ' ' << q->quality.mean << ' ' << q->quality.p99 << ' ' << q->quality.max << ' '
               << q->quality.point_to_plane << ' ' << q->quality.uniformity << ' ' << q->quality.mean_entropy << ' '
               << (summary->labelled ? (double(q->quality.labelled) / double(q->count)) /
                                         (double(summary->labelled) / double(summary->size))
                                     : 0.)
               << '\n';
      data << "\n\n";
    }
  }

  struct Metric
  {
    std::string file, title;
    int column;
    bool log_y;
  };
  const std::vector<Metric> metrics = {
    { "mean_distance", "mean distance from the input to the result / diagonal", 2, true },
    { "p99_distance", "99th percentile of that distance / diagonal", 3, true },
    { "hausdorff", "maximum of that distance (one-sided Hausdorff) / diagonal", 4, true },
    { "point_to_plane", "point-to-plane RMS error of the input / diagonal", 5, true },
    { "uniformity", "coefficient of variation of the spacing of the result", 6, false },
    { "mean_entropy", "mean entropy of the paper (Eq. 7), bits", 7, false },
  };
  // the key takes the panel after the inputs; each row of panels keeps its height
  const int columns = 3, rows = int(inputs.size() + columns) / columns;
  std::ofstream gp(dir + "/charts.gp");
  gp << "set terminal pngcairo noenhanced size 1800," << 60 + 210 * rows << " font 'sans,10'\n"
     << "set logscale x\nset xlabel 'points kept (%)'\nset grid\nunset key\n";
  for (const Metric& metric : metrics)
  {
    gp << "set output 'chart_" << metric.file << ".png'\n"
       << "set multiplot layout " << rows << "," << columns << " title '" << metric.title << "'\n"
       << (metric.log_y ? "set logscale y\n" : "unset logscale y\n");
    for (std::size_t i = 0; i < inputs.size(); ++i)
    {
      gp << "set title '" << inputs[i] << "'\nplot ";
      for (std::size_t m = 0; m < methods.size(); ++m)
        gp << (m ? ", " : "") << "'data_" << inputs[i] << ".dat' index " << m << " using 1:" << metric.column << ' '
           << line_style(methods, m) << " notitle";
      gp << "\n";
    }
    write_key_panel(gp, methods);
    gp << "unset multiplot\n";
  }
  // fandisk: share of points near sharp edges over the input's share
  if (std::find(inputs.begin(), inputs.end(), "fandisk") != inputs.end())
  {
    gp << "set output 'chart_fandisk_sharp_edges.png'\nset terminal pngcairo noenhanced size 1000,600 font 'sans,10'\n"
       << "unset logscale y\nset key outside right top\nset title 'fandisk: share of kept points near a sharp edge / "
          "the input share'\nplot ";
    for (std::size_t m = 0; m < methods.size(); ++m)
      gp << (m ? ", " : "") << "'data_fandisk.dat' index " << m << " using 1:8 " << line_style(methods, m)
         << " title '" << methods[m] << "'";
    gp << "\n";
  }
}

// The kept points of the replica and the lion for each method, like the
// paper's Fig. 3 and Fig. 6.
inline void write_pictures(const Report& r, const std::string& dir, const std::string& input, double ratio,
                           bool front_view)
{
  const std::vector<std::string> methods = methods_of(r);
  std::vector<std::string> shown;
  for (const std::string& m : methods)
    if (find_row(r, input, m, ratio))
      shown.push_back(m);
  if (shown.empty())
    return;
  std::ofstream gp(dir + "/pictures_" + input + ".gp");
  const int columns = 4, rows = int(shown.size() + columns - 1) / columns;
  gp << "set terminal pngcairo noenhanced size " << 450 * columns << "," << 430 * rows << " font 'sans,10'\n"
     << "set output 'pictures_" << input << ".png'\n"
     << "set multiplot layout " << rows << "," << columns << " title '" << input << ", " << ratio
     << "% of the points kept by each method'\n"
     << "unset key\nunset tics\nunset border\nunset colorbox\n";
  if (front_view)
    gp << "set size ratio -1\nset palette defined (0 '#777777', 1 '#d62728')\nset cbrange [0:1]\n";
  else
    gp << "set view equal xyz\nset view 80,30,1.4\nset palette rgb 33,13,10\n";
  for (const std::string& m : shown)
  {
    gp << "set title '" << m << "'\n";
    if (front_view)
      gp << "plot 'points/" << input << "__" << file_name(m) << ".txt' using 1:2:4 with dots lc palette\n";
    else
      gp << "splot 'points/" << input << "__" << file_name(m) << ".txt' using 1:3:2:3 with dots lc palette\n";
  }
  gp << "unset multiplot\n";
}

} // namespace bench

#endif // ENTROPY_SIMPLIFICATION_BENCH_REPORT_H
