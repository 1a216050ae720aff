// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The benchmark: every method at equal point counts on every input, the
// paper's experiments, and speed as ratios to CGAL's pca_estimate_normals.
// PCL's and Open3D's simplifiers are included when the build found them
// (ES_BENCH_WITH_PCL, ES_BENCH_WITH_OPEN3D: benchmark/CMakeLists.txt).
//
//   run_benchmark --data DIR --out DIR [--quick]
//
// DIR is CGAL's demo data (libcgal-demo). Writes OUT/RESULTS.md, and
// quality.csv, timing.csv, the data and gnuplot scripts of the figures into
// OUT/results; benchmark/run.sh then draws the figures.

#include "bench_common.h"
#include "bench_inputs.h"
#include "bench_methods.h"
#include "bench_metrics.h"
#include "bench_peers.h"
#include "bench_results_markdown.h"

#include <CGAL/pca_estimate_normals.h>

#include <cstdlib>
#include <map>
#include <numeric>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace bench;

struct Input_plan
{
  std::function<Cloud()> make;
  std::vector<double> ratios; // percentages, for the quality metrics
  std::vector<double> timed_ratios;
  bool quality = true;
  std::string picture_ratio_name; // "replica" or "lion": draw its results at the picture ratio
  double picture_ratio = 0.;
  Input_role role = Input_role::tuned;
  bool feature_sweep = false; // also run the default mode at the swept feature weights
};

double pca_seconds(const Cloud& cloud, int repeats)
{
  std::vector<std::pair<Point, Vector> > v;
  for (const Point& p : cloud.points)
    v.emplace_back(p, CGAL::NULL_VECTOR);
  return median_seconds(repeats, [&] {
    CGAL::pca_estimate_normals<CGAL::Sequential_tag>(
      v, 10,
      CGAL::parameters::point_map(CGAL::First_of_pair_property_map<std::pair<Point, Vector> >())
        .normal_map(CGAL::Second_of_pair_property_map<std::pair<Point, Vector> >()));
  });
}

std::size_t count_for(std::size_t n, double percentage)
{
  return ES::internal::kept_count_from_percentage(n, percentage);
}

void write_points(const std::string& file, const Selection& s)
{
  std::ofstream out(file);
  out.precision(9);
  for (std::size_t i = 0; i < s.points.size(); ++i)
    out << s.points[i].x() << ' ' << s.points[i].y() << ' ' << s.points[i].z() << ' '
        << (s.labels.empty() ? 0 : s.labels[i]) << '\n';
}

// Every method: the package, the paper's baselines, CGAL's simplifiers, then
// the optional peers that were built (benchmark/CMakeLists.txt).
std::vector<Method> methods_for(Method_context& context)
{
  std::vector<Method> methods = all_methods(context);
  const std::vector<Method> peers = optional_peer_methods(context);
  methods.insert(methods.end(), peers.begin(), peers.end());
  return methods;
}

// The optional peer families, built or not, for RESULTS.md's header.
void describe_peers(Report& report)
{
#ifdef ES_BENCH_WITH_PCL
  report.peers_built.push_back(pcl_peers::description());
#else
  report.peers_not_built.push_back("PCL (VoxelGrid, UniformSampling, NormalSpaceSampling; Debian libpcl-dev)");
#endif
#ifdef ES_BENCH_WITH_OPEN3D
  report.peers_built.push_back(open3d_peers::description());
#else
  report.peers_not_built.push_back("Open3D (VoxelDownSample, FarthestPointDownSample; Debian libopen3d-dev)");
#endif
}

// The default mode at each swept feature weight, at the targets' ratios the
// plan measures (bench_feature_sweep.h).
void run_feature_sweep(const Cloud& cloud, const Input_plan& plan, bool is_replica, const ES::Options& indicator,
                       Report& report)
{
  std::cerr << "   feature weight sweep" << std::flush;
  for (double weight : swept_feature_weights)
  {
    ES::Options options;
    options.feature_weight = weight;
    const Method method = package_method(cloud, options, swept_method_name(weight));
    for (double ratio : target_ratios)
    {
      if (std::find(plan.ratios.begin(), plan.ratios.end(), ratio) == plan.ratios.end())
        continue;
      const std::size_t m = count_for(cloud.points.size(), ratio);
      const Selection s = method.select(m);
      Quality_row row{ cloud.name, method.name, method.family, ratio, m };
      row.count = s.points.size();
      row.reached = s.count_before_trim;
      row.quality = measure(cloud, s, is_replica, indicator);
      report.feature_sweep.push_back(row);
      std::cerr << "." << std::flush;
    }
  }
  std::cerr << std::endl;
}

Selection prefix(const Cloud& cloud, const std::vector<Index>& order, std::size_t m)
{
  std::vector<Index> kept(order.begin(), order.begin() + std::ptrdiff_t(m));
  std::sort(kept.begin(), kept.end());
  return subset(cloud, kept);
}

void run_input(const Input_plan& plan, int repeats, double skip_seconds, const std::string& out_dir, Report& report)
{
  CGAL::Real_timer clock;
  clock.start();
  const Cloud cloud = plan.make();
  std::cerr << "== " << cloud.name << ": " << cloud.description << std::endl;

  Input_summary summary;
  summary.name = cloud.name;
  summary.description = cloud.description;
  summary.size = cloud.points.size();
  summary.labelled = std::size_t(std::count(cloud.labels.begin(), cloud.labels.end(), 1));
  summary.pca_seconds = pca_seconds(cloud, repeats);
  summary.is_replica = cloud.name.rfind("replica", 0) == 0;
  summary.role = plan.role;

  // The indicator of every result uses the input's reference plane.
  Kernel::Plane_3 plane;
  CGAL::linear_least_squares_fitting_3(cloud.points.begin(), cloud.points.end(), plane, CGAL::Dimension_tag<0>());
  ES::Options indicator;
  indicator.reference_normal = std::array<double, 3>{ plane.orthogonal_vector().x(), plane.orthogonal_vector().y(),
                                                      plane.orthogonal_vector().z() };
  if (plan.quality)
  {
    Selection everything = subset(cloud, [&] {
      std::vector<Index> all(cloud.points.size());
      std::iota(all.begin(), all.end(), Index(0));
      return all;
    }());
    summary.original = measure(cloud, everything, summary.is_replica, indicator);
  }

  Method_context context(cloud);
  for (Method& method : methods_for(context))
  {
    std::cerr << "   " << method.name << std::flush;
    std::vector<Index> order;
    if (method.progressive_order && plan.quality)
    {
      const double smallest = *std::min_element(plan.ratios.begin(), plan.ratios.end());
      order = method.progressive_order(count_for(cloud.points.size(), smallest));
    }
    std::map<double, std::vector<double> > parameter_of; // percentage -> parameters found
    std::map<double, double> select_seconds; // for a slow method, its quality run is its timing run
    for (double ratio : plan.quality ? plan.ratios : std::vector<double>())
    {
      const std::size_t m = count_for(cloud.points.size(), ratio);
      Quality_row row{ cloud.name, method.name, method.family, ratio, m };
      if (method.predicted_seconds && method.predicted_seconds(m) > skip_seconds)
      {
        row.skipped = true;
        report.quality.push_back(row);
        continue;
      }
      CGAL::Real_timer select_timer;
      select_timer.start();
      const Selection s = order.empty() ? method.select(m) : prefix(cloud, order, m);
      select_seconds[ratio] = select_timer.time();
      parameter_of[ratio] = s.parameters;
      row.count = s.points.size();
      row.reached = s.count_before_trim;
      row.parameters = s.parameters;
      row.quality = measure(cloud, s, summary.is_replica, indicator);
      report.quality.push_back(row);
      if (!plan.picture_ratio_name.empty() && ratio == plan.picture_ratio)
        write_points(out_dir + "/points/" + cloud.name + "__" + file_name(method.name) + ".txt", s);
      std::cerr << "." << std::flush;
    }

    for (double ratio : plan.timed_ratios)
    {
      const std::size_t m = count_for(cloud.points.size(), ratio);
      Timing_row row{ cloud.name, method.name, ratio, cloud.points.size(), summary.pca_seconds };
      if (method.predicted_seconds && method.predicted_seconds(m) > skip_seconds)
      {
        row.skipped = true;
        report.timing.push_back(row);
        continue;
      }
      if (method.predicted_seconds && method.predicted_seconds(m) > 10. && select_seconds.count(ratio))
      {
        // a long run (WLOP, farthest point sampling) is timed once, by its quality run
        row.timing = Timing{ select_seconds[ratio], 0. };
        row.runs = 1;
        report.timing.push_back(row);
        continue;
      }
      if (!parameter_of.count(ratio) && method.select && !order.size() && method.searches_parameters)
        parameter_of[ratio] = method.select(m).parameters;
      const std::vector<double> parameters = parameter_of[ratio];
      const int runs = method.predicted_seconds && method.predicted_seconds(m) > 10. ? 1 : repeats;
      std::vector<Timing> timings;
      for (int r = 0; r < runs; ++r)
        timings.push_back(method.timed_run(m, parameters));
      std::sort(timings.begin(), timings.end(), [](const Timing& a, const Timing& b) { return a.seconds < b.seconds; });
      row.timing = timings[timings.size() / 2];
      row.runs = runs;
      report.timing.push_back(row);
    }
    std::cerr << std::endl;
  }
  if (plan.feature_sweep && plan.quality)
    run_feature_sweep(cloud, plan, summary.is_replica, indicator, report);
  summary.seconds = clock.time();
  report.inputs.push_back(summary);
}

} // namespace

int main(int argc, char** argv)
{
  std::string data, out;
  bool quick = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--data" && i + 1 < argc)
      data = argv[++i];
    else if (a == "--out" && i + 1 < argc)
      out = argv[++i];
    else if (a == "--quick")
      quick = true;
    else
    {
      std::cerr << "usage: run_benchmark --data DIR --out DIR [--quick]\n";
      return 2;
    }
  }
  if (data.empty() || out.empty())
  {
    std::cerr << "usage: run_benchmark --data DIR --out DIR [--quick]\n";
    return 2;
  }
  std::filesystem::create_directories(out + "/results/points");

  // The full run and, with --quick, a smaller one: inputs divided in size,
  // fewer ratios, one timing run.
  const std::size_t scale = quick ? 8 : 1;
  const int repeats = quick ? 1 : 3;
  const double skip_seconds = quick ? 5. : 100.;
  const std::vector<double> everywhere = quick ? std::vector<double>{ 5., 20. } : std::vector<double>{ 2., 5., 10., 20., 50. };
  auto with = [&](std::vector<double> extra) {
    std::vector<double> r = everywhere;
    r.insert(r.end(), extra.begin(), extra.end());
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
    return r;
  };

  // The quality tables' inputs, each with its ratios, those timed, and the
  // paper's experiment it draws pictures for; the quick run keeps one replica.
  std::vector<Input_plan> plans;
  for (const Benchmark_input& input : benchmark_inputs(data, scale))
  {
    if (quick && input.name == "replica_2mm")
      continue;
    Input_plan plan{ input.make, everywhere, {}, true };
    if (input.name == "replica_2mm" || input.name == "replica_1.2mm")
      plan = { input.make, with({ 10. }), { 10. }, true, "replica", 10. };
    else if (input.name == "lion")
      plan = { input.make, with(quick ? std::vector<double>{} : std::vector<double>{ 20., 40., 60., 80. }),
               { 10., 20. }, true, "lion", 20. };
    else if (input.role == Input_role::tuned)
      plan.timed_ratios = { 10. };
    plan.role = input.role;
    // the feature weight sweep runs on every tuned input and on the
    // labelled machined parts held out anew or for the next term
    plan.feature_sweep = input.role == Input_role::tuned ||
                         (input.labelled && (input.role == Input_role::held_out_anew ||
                                             input.role == Input_role::held_out_next));
    plans.push_back(plan);
  }
  plans.push_back({ [&] { return mesh_sample("timing_1M", data + "/meshes/lion.off", 1000000 / scale, false); },
                    {}, { 10. }, false });

  Report report;
  report.quick = quick;
  report.repeats = repeats;
  report.skip_seconds = skip_seconds;
  describe_peers(report);
  CGAL::Real_timer total;
  total.start();
  for (const Input_plan& plan : plans)
    run_input(plan, repeats, skip_seconds, out + "/results", report);
  report.total_seconds = total.time();
  write_report(report, out + "/results", out + "/RESULTS.md", "results");
  std::cerr << "wrote " << out << "/RESULTS.md in " << total.time() << " s" << std::endl;
  return 0;
}
