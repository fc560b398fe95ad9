#include "model/core/validity.hpp"

namespace gmr {

namespace {

// The violations at a dart, built only when the report stores them (the limit not reached).
ConstraintViolation dangling_link(Dart d, int i, Dart e) {
  return {.constraint = Constraint::IncidentArcs,
          .at = d,
          .i = i,
          .path = {d, e},
          .message = "its " + std::to_string(i) + "-link targets " + std::to_string(e) +
                     ", which is not a dart"};
}

ConstraintViolation not_involution(Dart d, int i, Dart e, Dart f) {
  return {.constraint = Constraint::NonOrientation,
          .at = d,
          .i = i,
          .path = {d, e, f},
          .message = "alpha_" + std::to_string(i) + " is not an involution: " + std::to_string(d) +
                     " -> " + std::to_string(e) + " -> " + std::to_string(f)};
}

ConstraintViolation not_permutation(Dart e, int i, Dart from, Dart d) {
  return {.constraint = Constraint::IncidentArcs,
          .at = e,
          .i = i,
          .path = {from, d},
          .message = "dart is the target of several 1-arcs (beta_1 not a permutation), from " +
                     std::to_string(from) + " and " + std::to_string(d)};
}

ConstraintViolation open_cycle(int i, int j, std::vector<Dart> path) {
  std::string m = "the " + std::to_string(i) + std::to_string(j) + std::to_string(i) +
                  std::to_string(j) + "-path does not close:";
  for (Dart x : path) m += " " + std::to_string(x);
  const Dart d = path.front();
  return {.constraint = Constraint::Cycle,
          .at = d,
          .i = i,
          .j = j,
          .path = std::move(path),
          .message = std::move(m)};
}

// One pass over the darts of a map without deleted darts whose every dimension is an involution
// (a G-map, Def. 32): true when no dart breaks a condition as the passes of check_validity read
// them (a link in range, alpha_i(alpha_i(d)) == d, and alpha_j(alpha_i(d)) == alpha_i(alpha_j(d))
// for the cycle pairs). Each dart's links are loaded once for all the conditions instead of once
// per condition's pass, so a valid map, the usual case, is checked in one sweep; the sweep stops
// at the first broken dart, and the passes then report the violations in their order.
template <int Dims>
bool dense_gmap_is_valid(const Map& g, int lo) {
  const Dart cap = g.capacity();
  const Dart* l[Dims];
  for (int k = 0; k < Dims; ++k) l[k] = g.links(lo + k).data();
  for (Dart d = 0; d < cap; ++d) {
    Dart e[Dims];
    bool ok = true;
    for (int k = 0; k < Dims; ++k) {
      e[k] = l[k][d];
      ok &= e[k] < cap;
    }
    if (!ok) return false;  // before any read through an out-of-range link
    for (int k = 0; k < Dims; ++k) ok &= l[k][e[k]] == d;
    for (int a = 0; a < Dims; ++a)
      for (int b = a + 2; b < Dims; ++b) ok &= l[b][e[a]] == l[a][e[b]];
    if (!ok) return false;  // the passes will name it
  }
  return true;
}

// Whether the one-pass check above applies to g and finds it valid.
bool valid_in_one_pass(const Map& g) {
  if (g.has_holes()) return false;
  const int lo = g.lowest_dim(), n = g.dimension();
  for (int i = lo; i <= n; ++i)
    if (!g.is_involutive_dim(i)) return false;
  switch (n - lo + 1) {
    case 2:
      return dense_gmap_is_valid<2>(g, lo);
    case 3:
      return dense_gmap_is_valid<3>(g, lo);
    case 4:
      return dense_gmap_is_valid<4>(g, lo);
    default:
      return false;
  }
}

}  // namespace

ValidityReport check_validity(const Map& g, size_t limit) {
  ValidityReport r;
  if (valid_in_one_pass(g)) return r;
  // `make` builds the violation (its path and message) only when it is stored.
  auto add = [&](auto make) {
    if (r.violations.size() < limit)
      r.violations.push_back(make());
    else
      ++r.truncated;
  };
  const int lo = g.lowest_dim(), n = g.dimension();
  const Dart cap = g.capacity();
  // Without deleted darts, "e is a dart" is just e < capacity (no look-up in the dead set).
  const bool dense = !g.has_holes();
  auto is_dart = [&](Dart e) { return dense ? e < cap : g.alive(e); };
  // A dimension is usable for the cycle check only if all its links are in range.
  std::vector<bool> dim_ok(static_cast<size_t>(n) + 1, true);
  // An involutive dimension without any violation (every alpha_i(alpha_i(d)) == d).
  std::vector<bool> invol_ok(static_cast<size_t>(n) + 1, true);
  for (int i = lo; i <= n; ++i) {
    const Dart* const l = g.links(i).data();
    const bool invol = g.is_involutive_dim(i);
    invol_ok[i] = invol;
    // The full check of one dart, run only where the tight loops below see a problem (kept out
    // of them so that they stay small enough to be inlined and unrolled).
    auto report = [&](Dart d) {
      const Dart e = l[d];
      if (!is_dart(e)) {
        dim_ok[i] = false;
        invol_ok[i] = false;
        add([&] { return dangling_link(d, i, e); });
        return;
      }
      if (invol && l[e] != d) {
        invol_ok[i] = false;
        add([&] { return not_involution(d, i, e, l[e]); });
      }
    };
    if (dense && invol) {
      for (Dart d = 0; d < cap; ++d) {
        const Dart e = l[d];
        if (e >= cap || l[e] != d) [[unlikely]]
          report(d);
      }
    } else if (dense) {
      for (Dart d = 0; d < cap; ++d)
        if (l[d] >= cap) [[unlikely]]
          report(d);
    } else {
      g.for_each_dart(report);
    }
    if (!invol && dim_ok[i]) {
      // beta_1 must be a permutation: every dart has exactly one incoming 1-arc.
      std::vector<Dart> from(g.capacity(), kNoDart);
      g.for_each_dart([&](Dart d) {
        const Dart e = l[d];
        if (from[e] != kNoDart)
          add([&] { return not_permutation(e, i, from[e], d); });
        else
          from[e] = d;
      });
    }
  }
  for (const auto& pair : g.spec().cycle_pairs()) {
    {
      const int i = pair.first,
                j = pair.second;  // named, not bound: the lambda below captures them
      if (!dim_ok[i] || !dim_ok[j]) continue;
      const Dart* const li = g.links(i).data();
      const Dart* const lj = g.links(j).data();
      auto report = [&](Dart d) {
        const Dart a = li[d], b = lj[a], c = li[b], e = lj[c];
        if (e != d) add([&] { return open_cycle(i, j, {d, a, b, c, e}); });
      };
      if (invol_ok[i] && invol_ok[j]) {
        // With alpha_i and alpha_j involutions, alpha_j alpha_i alpha_j alpha_i (d) == d iff
        // alpha_j(alpha_i(d)) == alpha_i(alpha_j(d)) (apply alpha_j, then alpha_i, to both
        // sides): two independent 2-load chains instead of one 4-load chain. Same verdict per
        // dart, so the same violations in the same order.
        g.for_each_dart([&](Dart d) {
          if (lj[li[d]] != li[lj[d]]) report(d);
        });
      } else {
        g.for_each_dart(report);
      }
    }
  }
  return r;
}

bool is_valid(const Map& g) { return check_validity(g, 0).ok(); }

}  // namespace gmr
