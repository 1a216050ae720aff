// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Runs either mode on the distinct points of a range and returns its removal
// order, the copies of coincident points first: down to a target, or on
// through the kept points, so that every point has a rank.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_SIMPLIFY_POINTS_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_SIMPLIFY_POINTS_H

#include <CGAL/Entropy_simplification/Options.h>
#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Coverage_elimination.h>
#include <CGAL/Entropy_simplification/internal/Default_mode_terms.h>
#include <CGAL/Entropy_simplification/internal/Distinct_points.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Lloyd_relocation.h>
#include <CGAL/Entropy_simplification/internal/Neighbor_offsets.h>
#include <CGAL/Entropy_simplification/internal/Paper_simplification.h>
#include <CGAL/Entropy_simplification/internal/Weighted_elimination.h>
#include <CGAL/Entropy_simplification/internal/reference_plane.h>

#include <algorithm>
#include <functional>
#include <optional>
#include <utility>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// Iterations of the relocation that ends the default mode.
constexpr int relocation_iterations = 2;

// How far a run goes: down to its target, or on through the kept points
// until the last ones, so that the kept points are ordered too.
enum class Run_extent
{
  to_target,
  through_the_kept
};

// What an engine did: its removals, as indices of the Indexed_points, in
// removal order, unless the callback stopped it during its initialisation.
struct Engine_run
{
  bool initialized = false;
  bool completed = false;
  Array<Index> removed;
};

// Initialises an engine and removes points down to `target`. The callback
// receives the fraction done, the initialisation counting for the first
// quarter, about a thousand times in all.
template <typename ConcurrencyTag, typename Engine>
Engine_run run_engine(Engine& engine, std::size_t n, std::size_t target, const std::function<bool(double)>& callback)
{
  auto report = [&callback](double fraction) { return !callback || callback(fraction); };
  Engine_run run;
  run.initialized = engine.template initialize<ConcurrencyTag>([&](double f) { return report(0.25 * f); });
  if (!run.initialized)
    return run;
  const std::size_t removals = n - target;
  const std::size_t period = (std::max)(std::size_t(1), removals / 1000);
  run.removed.reserve(removals);
  run.completed = engine.template remove_down_to<ConcurrencyTag>(target, [&](Index p) {
    run.removed.push_back(p);
    return run.removed.size() % period != 0 || report(0.25 + 0.75 * double(run.removed.size()) / double(removals));
  });
  return run;
}

// Which points an engine's run left present.
inline Array<char> present_after(const Engine_run& run, std::size_t n)
{
  Array<char> present(n, 1);
  for (Index i : run.removed)
    present[i] = 0;
  return present;
}

// The relocation that ends the default mode, with the `terms` switched on,
// on the `scale` of each point, from `nearest`, each point's nearest present
// point after the run, when the engine kept them (see
// relocate_within_input), its searches answered from `offsets` when they
// can be. A relocated point takes the place, in the removal order, of the
// point that replaces it. Returns each point's nearest present point once
// relocated, when the relocation found them (see Relocation), or nothing.
template <typename ConcurrencyTag>
Array<Index> relocate(const Indexed_points& points, Engine_run& run, const Default_mode_terms& terms,
                      const Array<double>& scale, Array<Index> nearest, const Neighbor_offsets& offsets)
{
  Array<char> present = present_after(run, points.size());
  Array<Index> rank(points.size(), 0);
  for (std::size_t r = 0; r < run.removed.size(); ++r)
    rank[run.removed[r]] = Index(r);
  Relocation relocation =
    relocate_within_input<ConcurrencyTag>(points, present, terms.relocation ? relocation_iterations : 0, terms, scale,
                                          std::move(nearest), offsets);
  for (const auto& swap : relocation.swaps)
    run.removed[rank[swap.second]] = swap.first;
  return std::move(relocation.site);
}

// Goes on removing among the present points of `engine` down to one point,
// which no removal follows, appending the removals to `run`. The callback
// can stop it: it receives the fraction done when the run removed nothing
// (no level), as run_engine() does, and 1 otherwise.
template <typename ConcurrencyTag, typename Engine>
bool remove_down_to_one(Engine& engine, const Indexed_points& points, Engine_run& run,
                        const std::function<bool(double)>& callback)
{
  const bool whole_run = run.removed.empty();
  const std::size_t removals = points.size() - run.removed.size() - 1;
  const std::size_t period = whole_run ? (std::max)(std::size_t(1), removals / 1000) : 1024;
  std::size_t count = 0;
  return engine.template remove_down_to<ConcurrencyTag>(1, [&](Index p) {
    run.removed.push_back(p);
    return ++count % period != 0 || !callback ||
           callback(whole_run ? 0.25 + 0.75 * double(count) / double(removals) : 1.);
  });
}

// Orders the points a default-mode run kept, once relocated: the
// elimination goes on among them down to one point, its stages ending at
// the level boundaries below, each relocated (see Level_cells) from the
// cells of the kept points, `site` holding each point's nearest kept point,
// or nothing when they are to be searched (the relocation's swaps find
// them, unless a run switches them off). The callback can stop it (see
// remove_down_to_one).
template <typename ConcurrencyTag>
bool eliminate_the_kept(Weighted_elimination& engine, const Indexed_points& points, Engine_run& run,
                        Array<Index> site, const std::function<bool(double)>& callback)
{
  const Array<char> present = present_after(run, points.size());
  engine.relocate_level_boundaries(site.empty() ? nearest_present_points<ConcurrencyTag>(points, present)
                                                : std::move(site));
  engine.set_present(present);
  return remove_down_to_one<ConcurrencyTag>(engine, points, run, callback);
}

// Orders the points a greedy coverage run kept, once relocated: the
// elimination goes on among them down to one point, each input point
// following its nearest and next kept points from the relocated ones, its
// rounds ending at the level boundaries, each relocated (see Level_cells),
// until at most 1% of the points are present, which then stand for the
// input points (see Coverage_elimination). `site`, each point's nearest
// kept point when the relocation found them, spares the input points their
// searches when at most 1% are kept.
template <typename ConcurrencyTag>
bool eliminate_the_kept(Coverage_elimination& engine, const Indexed_points& points, Engine_run& run,
                        Array<Index> site, const std::function<bool(double)>& callback)
{
  engine.set_present(present_after(run, points.size()), std::move(site));
  engine.relocate_level_boundaries();
  return remove_down_to_one<ConcurrencyTag>(engine, points, run, callback);
}

// Writes the normal of each present point when `with_normals`, and returns
// the removals as positions in the points given to `sort_spatially`.
template <typename ConcurrencyTag, typename Engine, typename NormalWriter>
Array<Index> finish(const Engine& engine, const Indexed_points& points, const Engine_run& run,
                          bool with_normals, const NormalWriter& write_normal)
{
  if (with_normals)
  {
    const Array<char> present = present_after(run, points.size());
    Array<Index> kept;
    for (Index i = 0; i < Index(points.size()); ++i)
      if (present[i])
        kept.push_back(i);
    const Array<Working_vector> normals = engine.template normals_of<ConcurrencyTag>(kept);
    for (std::size_t r = 0; r < kept.size(); ++r)
      write_normal(points.input_position[kept[r]], normals[r]);
  }
  Array<Index> removed;
  removed.reserve(run.removed.size());
  for (Index i : run.removed)
    removed.push_back(points.input_position[i]);
  return removed;
}

// The default mode's run with `engine`: the elimination down to `target`,
// the relocation, then, through the kept points, the elimination on among
// them (see simplify_distinct_points).
template <typename ConcurrencyTag, typename Engine, typename NormalWriter>
std::optional<Array<Index> > run_default_mode(Engine& engine, const Indexed_points& indexed, std::size_t target,
                                              bool through, const std::function<bool(double)>& callback,
                                              bool with_normals, const NormalWriter& write_normal,
                                              const Default_mode_terms& terms)
{
  Engine_run run = run_engine<ConcurrencyTag>(engine, indexed.size(), target, callback);
  if (!run.initialized)
    return std::nullopt;
  Array<Index> site; // each point's nearest kept point, when the relocation found them
  if ((terms.relocation || terms.coverage_swaps) && run.completed && !run.removed.empty())
    site = relocate<ConcurrencyTag>(indexed, run, terms, engine.field().scale, engine.take_nearest_present(),
                                    engine.take_neighbor_offsets());
  if (through &&
      !(run.completed && eliminate_the_kept<ConcurrencyTag>(engine, indexed, run, std::move(site), callback)))
    return std::nullopt;
  Array<Index>().swap(site); // a direct call's are not needed: their memory goes back first
  engine.release_first_neighbors();
  return finish<ConcurrencyTag>(engine, indexed, run, with_normals, write_normal);
}

// The method of `options.mode` on points without copies, given in input
// order, down to `target` or through the kept points: the positions of the
// removed points in removal order, or nothing when the callback stopped the
// initialisation, or any part of a run through the kept points. The paper's
// removals are exactly progressive, so its run through the kept points is
// one run down to its last k + 1 points. The default mode runs with the
// `terms` switched on.
template <typename ConcurrencyTag, typename NormalWriter>
std::optional<Array<Index> > simplify_distinct_points(Array<Working_point>&& points, unsigned int k,
                                                            std::size_t target, Run_extent extent,
                                                            const Options& options,
                                                            const std::function<bool(double)>& callback,
                                                            bool with_normals, const NormalWriter& write_normal,
                                                            const Default_mode_terms& terms)
{
  // the paper's plane is fitted in input order; then the points in input
  // order are done with, and their memory goes back before the run
  const Working_vector plane_normal =
    options.mode == Mode::paper ? reference_normal(options, points) : Working_vector(CGAL::NULL_VECTOR);
  const Indexed_points indexed = sort_spatially<ConcurrencyTag>(std::move(points));
  const bool through = extent == Run_extent::through_the_kept;
  if (options.mode == Mode::paper)
  {
    Paper_simplification engine(indexed, k, options, plane_normal);
    const Engine_run run =
      run_engine<ConcurrencyTag>(engine, indexed.size(), through ? std::size_t(k) + 1 : target, callback);
    if (!run.initialized || (through && !run.completed))
      return std::nullopt;
    return finish<ConcurrencyTag>(engine, indexed, run, with_normals, write_normal);
  }
  if (terms.coverage_elimination)
  {
    Coverage_elimination engine(indexed, k, options, terms);
    return run_default_mode<ConcurrencyTag>(engine, indexed, target, through, callback, with_normals, write_normal,
                                            terms);
  }
  Weighted_elimination engine(indexed, k, options, terms);
  return run_default_mode<ConcurrencyTag>(engine, indexed, target, through, callback, with_normals, write_normal,
                                          terms);
}

// The method of `options.mode` on a range down to `target` points, or on
// through the kept points (see simplify_distinct_points): the input
// positions of the removed points in removal order, or nothing when the
// callback stopped the run before it removed anything, or before its end
// through the kept points. The copies of coincident points go first, the
// last in input order first, so that they come back in input order once
// every distinct point is kept; a kept copy gets the normal of its
// representative. The distinct points' coordinates are released once
// sorted, their input positions during the run. `write_normal(position,
// normal)` receives the normal of each kept point when `with_normals`. The
// default mode runs with the `terms` switched on, all of them unless the
// benchmark's ablation asks otherwise.
template <typename ConcurrencyTag, typename NormalWriter>
std::optional<Array<Index> > simplify_points(Distinct_points&& distinct, unsigned int k, std::size_t target,
                                                   Run_extent extent, const Options& options,
                                                   const std::function<bool(double)>& callback,
                                                   bool with_normals, const NormalWriter& write_normal,
                                                   const Default_mode_terms& terms = Default_mode_terms())
{
  const std::size_t distinct_count = distinct.size();
  const bool through = extent == Run_extent::through_the_kept;
  const std::size_t kept_copies = !through && target > distinct_count ? target - distinct_count : 0;
  Array<Index> removed;
  for (std::size_t c = distinct.copies.size(); c-- > kept_copies;)
    removed.push_back(distinct.copies[c]);
  if (target >= distinct_count && !with_normals && !through)
    return removed;

  // The representatives' input positions are those of no copy: released
  // during the run, which has its peak of memory there, and listed again.
  Array<Index>().swap(distinct.input_position);
  Array<std::pair<Index, Working_vector> > normal_of_slot;
  const std::optional<Array<Index> > removed_distinct = simplify_distinct_points<ConcurrencyTag>(
    std::move(distinct.points), k, (std::min)(target, distinct_count), extent, options, callback, with_normals,
    [&](Index slot, const Working_vector& normal) { normal_of_slot.emplace_back(slot, normal); }, terms);
  if (!removed_distinct)
    return std::nullopt;
  const Array<Index> input_position = positions_of_no_copy(distinct.copies, distinct_count);
  for (Index slot : *removed_distinct)
    removed.push_back(input_position[slot]);
  for (const auto& [slot, normal] : normal_of_slot)
    write_normal(input_position[slot], normal);
  if (kept_copies > 0)
  {
    Array<Working_vector> normal_of_representative(distinct_count);
    for (const auto& [slot, normal] : normal_of_slot)
      normal_of_representative[slot] = normal;
    for (std::size_t c = 0; c < kept_copies; ++c)
      write_normal(distinct.copies[c], normal_of_representative[distinct.representative[c]]);
  }
  return removed;
}

// The removal order of the default mode on `points` (in input order) down
// to `target`, with the `terms` switched on only: the input positions of
// the removed points, first removed first. What the benchmark's ablation
// measures, and its tests check against the reference.
template <typename ConcurrencyTag>
Array<Index> removal_order_with_terms(Array<Working_point> points, unsigned int k, std::size_t target,
                                      const Options& options, const Default_mode_terms& terms)
{
  return simplify_points<ConcurrencyTag>(collapse_duplicates<ConcurrencyTag>(std::move(points)), k, target,
                                         Run_extent::to_target, options, std::function<bool(double)>(), false,
                                         [](Index, const Working_vector&) {}, terms)
    .value_or(Array<Index>());
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_SIMPLIFY_POINTS_H
