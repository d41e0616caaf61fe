#include "maps/form_pair_search.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <tuple>
#include <utility>

#include "common/errors.h"
#include "forms/holomorphic_forms.h"
#include "maps/branch_snapping.h"
#include "maps/fold_untangling.h"
#include "maps/form_ratio_map.h"
#include "sphere/branch_points.h"

namespace meromorph {

namespace {

// The pairs to try: the generic list, or the one pair asked for.
std::vector<FormPair> pairs_to_try(int genus, std::array<int, 2> form_pair) {
  const auto [i, j] = form_pair;
  if (i < 0 && j < 0) return generic_form_pairs(genus);
  if (i < 0 || j < 0 || i >= genus || j >= genus || i == j)
    throw ArgumentError("the form pair must be two different indices between 0 and " +
                        std::to_string(genus - 1) + " (or -1, -1 for the generic pair)");
  FormPair pair{Eigen::VectorXcd::Zero(genus), Eigen::VectorXcd::Zero(genus)};
  pair.first[i] = pair.second[j] = 1.0;
  return {pair};
}

// A pair is generic when the measured degree is 2g - 2 and Riemann-Hurwitz holds. Where a mesh
// is too coarse to resolve a pair's map (its image crowds where both forms live on the same
// handle), the next pair of the fixed list is tried; the best one is kept.
struct Attempt {
  bool generic = false;
  int deficit = 0; // |chi - (2 d - ramification)|
  std::vector<PlaneValue> values;
  MobiusCentering centring;
  int snapped = 0;
  Branching measured;
  int crowded = 0;   // faces whose image spans more than a chord of 1 (a quarter of the sphere)
  int untangled = 0; // vertices or regions moved to unfold sliver faces (fold_untangling.h)
  // Before snapping, the image's area is not 2g - 2 sheets: the map lost or gained a sheet where
  // zeros and poles crowd, and snapping (which moves values around critical points only) has
  // never made such a map generic on the test and bench meshes.
  bool degree_off = false;
  bool screened = false;               // solved to screening_tolerance only (form_ratio_map.h)
  std::unique_ptr<RatioMap> resumable; // a screened map's solve, to go on from
};

using Solved = std::vector<std::pair<size_t, Attempt>>;

bool less_crowded(const std::pair<size_t, Attempt> &a, const std::pair<size_t, Attempt> &b) {
  return a.second.crowded < b.second.crowded;
}

// The search's state: the pairs, the forms' coefficients worked out for them, the best attempt.
class PairSearcher {
public:
  PairSearcher(const PreparedMesh &prepared, const HolomorphicForms &forms,
               std::array<int, 2> form_pair, bool mobius, const Progress &progress)
      : prepared_(prepared), forms_(forms), mobius_(mobius), progress_(progress),
        euler_(2 - 2 * forms.genus), pairs_(pairs_to_try(forms.genus, form_pair)) {}

  PairSearch run();

private:
  // The pair's numerator omega1 + omega2 and denominator omega1 - omega2 (form_pairs.h), per
  // edge (for snapping) and their dz coefficients per face (for the map and its forecast), the
  // latter combined from the normalized forms' dz coefficients (forms x faces), worked out when
  // a pair first needs them and kept for the next pairs (but see dz_ahead_ below).
  std::array<Eigen::VectorXcd, 2> forms_of(const FormPair &pair) const {
    return ratio_forms(pair, forms_.normalized);
  }
  RatioDz combined_dz(const FormPair &pair) {
    if (!normalized_dz_)
      normalized_dz_ =
          dz_coefficients(prepared_.mesh, prepared_.edges, prepared_.geometry, forms_.normalized);
    return ratio_dz(pair, *normalized_dz_);
  }
  RatioDz dz_of(size_t k) {
    return dz_ahead_[k][0].empty() ? combined_dz(pairs_[k]) : std::exchange(dz_ahead_[k], {});
  }
  void least_crowded_pair_first();
  void judge(Attempt &result);
  Attempt solve(size_t k, bool first_round_pair);
  void full_solve(size_t k, Attempt &result);
  void untangle_if_that_makes_it_generic(Attempt &result, std::vector<Eigen::Vector3d> &sphere);
  void finish(size_t k, Attempt &result);
  void offer(size_t k, Attempt &&result);
  bool generic_kept() const { return best_ && best_->generic; }
  void first_round(size_t pairs_in_it, Solved &solved, Solved &degree_off);
  void finish_in_turn(Solved &attempts);

  const PreparedMesh &prepared_;
  const HolomorphicForms &forms_;
  const bool mobius_;
  const Progress &progress_;
  const int euler_;
  std::vector<FormPair> pairs_;
  std::optional<Eigen::MatrixXcd> normalized_dz_;
  std::vector<RatioDz> dz_ahead_; // pairs' dz coefficients worked out ahead
  // The first round's pairs are screened (solved to screening_tolerance, judged there, the solve
  // kept to go on from: `full_solve`) where the first pair's screening took more than
  // screening_steps conjugate gradient steps: then the steps are most of a solve and a screening
  // takes a quarter of them (raw marching cubes with needles: 8 to 14 against 37 to 41); on
  // meshes that take few (1 to 4, 5 to 12 to the full tolerance) the system's assembly is most
  // of a solve, and the first pair is solved on at once, judged as fully solved.
  static constexpr int screening_steps = 5;
  bool screening_ = false;
  std::optional<Attempt> best_;
  PairSearch out_;
};

// Genus 3 and up: where the first pair's guessed map crowds (guessed_crowding: before any solve
// or snapping), the pair whose guess crowds least (the first such) is tried first, the others
// after it in the list's order.
void PairSearcher::least_crowded_pair_first() {
  if (pairs_.size() <= 1 || forms_.genus <= 2) return;
  auto crowding = [&](const FormPair &pair) {
    return guessed_crowding(prepared_, combined_dz(pair));
  };
  int least = crowding(pairs_[0]);
  size_t least_at = 0;
  for (size_t k = 1; k < pairs_.size() && least > 0; ++k) {
    const int guessed = crowding(pairs_[k]);
    if (guessed < least) {
      least = guessed;
      least_at = k;
    }
  }
  std::rotate(pairs_.begin(), pairs_.begin() + long(least_at), pairs_.begin() + long(least_at) + 1);
}

// A pair's map centred and judged: its crowding before any snapping (snapping moves a few values
// around critical points: on the test and bench meshes the crowded faces were the same before
// and after, or two apart), and whether its image area is 2g - 2 spheres.
void PairSearcher::judge(Attempt &result) {
  if (mobius_) result.centring = center_on_sphere(result.values, prepared_.vertex_areas);
  const std::vector<Eigen::Vector3d> sphere = to_sphere(result.values);
  result.crowded = crowded_faces(prepared_.incidence, sphere);
  result.degree_off =
      std::lround(image_area_over_4pi(prepared_.mesh, sphere)) != long(2 * forms_.genus - 2);
  ++out_.attempts;
}

Attempt PairSearcher::solve(size_t k, bool first_round_pair) {
  progress_.report(0.6 + 0.1 * double(k) / double(pairs_.size()), "meromorphic function");
  auto map = std::make_unique<RatioMap>(prepared_, dz_of(k));
  if (k == 0 && first_round_pair) {
    map->advance(screening_tolerance);
    screening_ = map->steps() > screening_steps;
  }
  Attempt result;
  if (first_round_pair && screening_) {
    result.values = map->values(screening_tolerance);
    result.screened = true;
    result.resumable = std::move(map);
  } else {
    result.values = map->values(RatioSolve().tolerance);
  }
  judge(result);
  return result;
}

void PairSearcher::full_solve(size_t k, Attempt &result) {
  if (!result.screened) return;
  if (result.resumable) {
    result.values = result.resumable->values(RatioSolve().tolerance);
    result.resumable.reset();
  } else { // solved again from its screening map, as form_ratio_map returned it
    std::vector<PlaneValue> start = std::move(result.values);
    if (mobius_) {
      const Mobius undo = result.centring.transformation.inverse();
      for (PlaneValue &value : start)
        value = undo.apply(value);
    }
    result.values = form_ratio_map(prepared_, dz_of(k), {RatioSolve().tolerance, &start});
  }
  if (mobius_) result.centring = center_on_sphere(result.values, prepared_.vertex_areas);
  result.screened = false;
}

// A sliver's folded image (a vertex around which the image winds 0 or twice) fails
// Riemann-Hurwitz while the map is fine: where untangling its folds, as the written map's would
// (written_map.h), makes the map generic, the untangled map is the pair's (not the next pairs'
// solves and snapping).
void PairSearcher::untangle_if_that_makes_it_generic(Attempt &result,
                                                     std::vector<Eigen::Vector3d> &sphere) {
  std::vector<Eigen::Vector3d> untangled = sphere;
  const int moved = untangle_folds(prepared_, untangled, result.measured.branch_vertices);
  Branching again = moved ? analyse_branching(prepared_.mesh, untangled, euler_) : Branching{};
  if (!moved || !again.riemann_hurwitz_ok || again.degree != 2 * forms_.genus - 2) return;
  for (size_t v = 0; v < sphere.size(); ++v)
    if (untangled[v] != sphere[v]) result.values[v] = to_plane_value(untangled[v]);
  sphere = std::move(untangled);
  result.measured = std::move(again);
  result.generic = true;
  result.untangled = moved;
}

// Its critical points snapped, its branching measured, the ranking's figures. (A pair left for
// later does not keep its forms, two edge arrays: they are made again when it is snapped.)
void PairSearcher::finish(size_t k, Attempt &result) {
  full_solve(k, result);
  const std::array<Eigen::VectorXcd, 2> pair_forms = forms_of(pairs_[k]);
  ++out_.snapped_pairs;
  SpotsLeftAlone left_alone; // branch_snapping.h: not worked out again in later passes
  for (int pass = 0; pass < 4; ++pass) {
    const int repaired =
        snap_branch_points(prepared_, {&pair_forms[0], &pair_forms[1]}, result.values, &left_alone);
    result.snapped += repaired;
    if (!repaired) break;
  }
  std::vector<Eigen::Vector3d> sphere = to_sphere(result.values);
  result.measured = analyse_branching(prepared_.mesh, sphere, euler_);
  result.generic =
      result.measured.riemann_hurwitz_ok && result.measured.degree == 2 * forms_.genus - 2;
  if (!result.generic) untangle_if_that_makes_it_generic(result, sphere);
  const Branching &measured = result.measured;
  result.deficit = std::abs(euler_ - (2 * measured.degree - measured.ramification));
  result.crowded = crowded_faces(prepared_.incidence, sphere);
}

void PairSearcher::offer(size_t k, Attempt &&result) {
  auto rank = [](const Attempt &a) { return std::make_tuple(!a.generic, a.deficit, a.crowded); };
  if (!best_ || rank(result) < rank(*best_)) {
    best_ = std::move(result);
    out_.coefficients = pairs_[k];
  }
}

// The first round: each pair solved (screened where that pays), one that does not crowd finished
// at once, the others kept in `solved`, those whose degree is off in `degree_off`.
void PairSearcher::first_round(size_t pairs_in_it, Solved &solved, Solved &degree_off) {
  for (size_t k = 0; k < pairs_in_it && !generic_kept(); ++k) {
    // Past the first pair, the round's other pairs' dz coefficients are combined at once and the
    // normalized forms' let go while those pairs are solved (where they take less room: genus 5
    // and up), the stage's peak (57 MB at genus 10 and 178k vertices, beside a kept pair's
    // solve); they are worked out again only if a later pair needs them.
    if (k == 1 && 2 * (pairs_in_it - 1) < size_t(forms_.genus)) {
      for (size_t later = 1; later < pairs_in_it; ++later)
        dz_ahead_[later] = combined_dz(pairs_[later]);
      normalized_dz_.reset();
    }
    Attempt result = solve(k, true);
    if (result.degree_off) {
      result.resumable.reset(); // (finished last if at all: solved again from its values then)
      degree_off.emplace_back(k, std::move(result));
    } else if (result.crowded == 0) {
      finish(k, result);
      offer(k, std::move(result));
    } else {
      solved.emplace_back(k, std::move(result));
      // Only the one to be finished first (the least crowded, the first of equals) keeps its
      // solve to go on from: both charts' systems, as much memory as the solve itself.
      auto first_to_finish = std::min_element(solved.begin(), solved.end(), less_crowded);
      for (auto at = solved.begin(); at != solved.end(); ++at)
        if (at != first_to_finish) at->second.resumable.reset();
    }
  }
}

// The attempts finished from the least crowded on, until one is generic.
void PairSearcher::finish_in_turn(Solved &attempts) {
  std::stable_sort(attempts.begin(), attempts.end(), less_crowded);
  for (auto &[k, result] : attempts) {
    if (generic_kept()) break;
    finish(k, result);
    offer(k, std::move(result));
  }
}

// Where a zero and a pole of the ratio fall within a face or two, a face's image spans a good
// part of the sphere (and its texture with it); another generic pair puts them elsewhere. For
// genus 2 every generic pair gives the same map up to a Moebius transformation: no other pair
// helps there. Genus 3 and up: up to three pairs are solved (on surfaces whose handles crowd
// everywhere, every pair does), the first that does not crowd finished at once; then they are
// finished from the least crowded on, and the first generic one is kept (only it is snapped
// where it is the least crowded). Maps whose degree is off are finished last, only where no
// other pair is generic.
PairSearch PairSearcher::run() {
  least_crowded_pair_first();
  dz_ahead_.resize(pairs_.size());
  const size_t pairs_in_first_round = std::min<size_t>(pairs_.size(), forms_.genus == 2 ? 1 : 3);
  Solved solved, degree_off;
  first_round(pairs_in_first_round, solved, degree_off);
  finish_in_turn(solved);
  // None generic: the next pairs one at a time, until one is.
  for (size_t k = pairs_in_first_round; k < pairs_.size() && !generic_kept(); ++k) {
    Attempt result = solve(k, false);
    if (result.degree_off) {
      degree_off.emplace_back(k, std::move(result));
      continue;
    }
    finish(k, result);
    offer(k, std::move(result));
  }
  // Still none: the maps whose degree was off, from the least crowded on.
  finish_in_turn(degree_off);
  out_.values = std::move(best_->values);
  out_.centring = best_->centring;
  out_.snapped_branch_points = best_->snapped;
  out_.untangled_vertices = best_->untangled;
  out_.branching = std::move(best_->measured);
  return std::move(out_);
}

} // namespace

PairSearch search_form_pairs(const PreparedMesh &prepared, const HolomorphicForms &forms,
                             std::array<int, 2> form_pair, bool mobius, const Progress &progress) {
  return PairSearcher(prepared, forms, form_pair, mobius, progress).run();
}

} // namespace meromorph
