// Reproduces the paper's Experiment I on a synthetic replica of its scan: a
// basketball in front of a board, 182,191 points, simplified to 10% by the
// default mode and by the paper's mode with each removal order. Prints the sphere/plane split of the kept points (the paper's
// Table 2), the time, also as a ratio to the time of one pass of CGAL's
// pca_estimate_normals (sequential, same k) on the same points in the same
// run, and the paper's accuracy indicator (Eq. 7).
//
//   experiment_I [--noise SIGMA] [-k K] [--write PREFIX]
//
// SIGMA is the range noise in metres (default: both 0.002 and 0.0012), K the
// number of neighbours (default 10). With
// --write, the replica and each result are written as PREFIX*.ply, with a
// `label` property (0 board, 1 ball).

#include <CGAL/Entropy_simplification/compute_mean_normal_angle_entropy.h>
#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>
#include <CGAL/Entropy_simplification/experiment_I_replica.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/write_ply_points.h>
#include <CGAL/Real_timer.h>
#include <CGAL/linear_least_squares_fitting_3.h>
#include <CGAL/pca_estimate_normals.h>

#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Labelled_point = std::pair<Point, int>;
using Point_map = CGAL::First_of_pair_property_map<Labelled_point>;
using Label_map = CGAL::Second_of_pair_property_map<Labelled_point>;
namespace ES = CGAL::Entropy_simplification;

void write(const std::string& file, const std::vector<Labelled_point>& points)
{
  std::ofstream out(file, std::ios::binary);
  CGAL::IO::set_binary_mode(out);
  CGAL::IO::write_PLY_with_properties(out, points, CGAL::make_ply_point_writer(Point_map()),
                                      std::make_pair(Label_map(), CGAL::IO::PLY_property<int>("label")));
}

int main(int argc, char** argv)
{
  std::vector<double> noises = { 0.002, 0.0012 };
  unsigned int k = 10;
  std::string prefix;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--noise" && i + 1 < argc)
      noises = { std::atof(argv[++i]) };
    else if (a == "-k" && i + 1 < argc)
      k = unsigned(std::atoi(argv[++i]));
    else if (a == "--write" && i + 1 < argc)
      prefix = argv[++i];
    else
    {
      std::cerr << "usage: experiment_I [--noise SIGMA] [-k K] [--write PREFIX]\n";
      return EXIT_FAILURE;
    }
  }

  std::cout << "Experiment I replica, simplified to 10% with k = " << k << "\n"
            << "paper (Table 2): 18,220 kept = 12,529 plane + 5,691 sphere (31.2% sphere)\n\n";
  for (double noise : noises)
  {
    ES::Experiment_I_setup setup;
    setup.range_noise = noise;
    std::vector<Labelled_point> replica;
    ES::experiment_I_replica<Point>(std::back_inserter(replica), setup);
    if (!prefix.empty())
      write(prefix + "replica_" + std::to_string(noise) + ".ply", replica);

    // The indicator of every result uses the input's reference plane.
    Kernel::Plane_3 plane;
    std::vector<Point> input_points;
    for (const auto& p : replica)
      input_points.push_back(p.first);
    CGAL::linear_least_squares_fitting_3(input_points.begin(), input_points.end(), plane, CGAL::Dimension_tag<0>());
    ES::Options indicator_options;
    const Kernel::Vector_3 n = plane.orthogonal_vector();
    indicator_options.reference_normal = std::array<double, 3>{ n.x(), n.y(), n.z() };

    // The peer the package's speed is reported against.
    std::vector<std::pair<Point, Kernel::Vector_3> > with_normals;
    for (const auto& p : replica)
      with_normals.emplace_back(p.first, CGAL::NULL_VECTOR);
    CGAL::Real_timer pca_timer;
    pca_timer.start();
    CGAL::pca_estimate_normals<CGAL::Sequential_tag>(
      with_normals, k,
      CGAL::parameters::point_map(CGAL::First_of_pair_property_map<std::pair<Point, Kernel::Vector_3> >())
        .normal_map(CGAL::Second_of_pair_property_map<std::pair<Point, Kernel::Vector_3> >()));
    pca_timer.stop();

    std::cout << "range noise " << noise * 1000. << " mm: " << replica.size() << " points, "
              << setup.board_points << " plane + " << setup.sphere_points << " sphere; "
              << "CGAL::pca_estimate_normals: " << std::setprecision(3) << pca_timer.time() << " s\n";
    ES::Options lowest, highest;
    lowest.mode = highest.mode = ES::Mode::paper;
    highest.removal_order = ES::Removal_order::highest_entropy_first;
    const std::vector<std::pair<std::string, ES::Options> > methods = {
      { "default", ES::Options() }, { "paper_lowest_first", lowest }, { "paper_highest_first", highest }
    };
    for (const auto& [name, options] : methods)
    {
      std::vector<Labelled_point> points = replica;
      CGAL::Real_timer timer;
      timer.start();
      const auto first_removed = CGAL::entropy_simplify_point_set<CGAL::Parallel_if_available_tag>(
        points, k, CGAL::parameters::select_percentage(10.).point_map(Point_map()), options);
      timer.stop();
      points.erase(first_removed, points.end());

      std::size_t sphere = 0;
      for (const auto& p : points)
        sphere += (p.second == ES::sphere_label);
      const double indicator = CGAL::compute_mean_normal_angle_entropy<CGAL::Parallel_if_available_tag>(
        points, k, CGAL::parameters::point_map(Point_map()), indicator_options);

      std::cout << "  " << std::setw(19) << std::left << name << std::right << ": kept " << points.size() << " = " << points.size() - sphere << " plane + "
                << sphere << " sphere (" << std::fixed << std::setprecision(1)
                << 100. * double(sphere) / double(points.size()) << "% sphere), " << std::setprecision(2)
                << timer.time() << " s (" << std::setprecision(1) << timer.time() / pca_timer.time()
                << "x pca), mean entropy " << std::setprecision(4) << indicator << " bits\n"
                << std::defaultfloat;
      if (!prefix.empty())
        write(prefix + name + "_" + std::to_string(noise) + ".ply", points);
    }
    std::cout << "\n";
  }
  return EXIT_SUCCESS;
}
