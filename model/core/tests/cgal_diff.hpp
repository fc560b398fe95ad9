// Differential testing against CGAL::Generalized_map (test-only; CGAL is an oracle, never a
// dependency of the library). Shared by cgal_diff_cgal_test.cpp and cgal_diff_cgal_slow_test.cpp.
//
// The CGAL copy of a gmr map has one CGAL dart per live gmr dart, and the CGAL alpha_i(h[d]) is
// set to h[alpha_i(d)] one direction at a time (dart_link_alpha), so that broken maps (an alpha_i
// that is not an involution) are copied as they are. Dangling links cannot be represented in CGAL
// and are not copied (the caller does not produce them).
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "model/core/map.hpp"
#include "model/core/orbit.hpp"
#include "model/core/signature.hpp"
#include "model/core/validity.hpp"
#include "model/testing/cgal_generalized_map.hpp"
#include "model/testing/random_maps.hpp"

namespace cgal_diff {

using gmr::Dart;
using gmr::Map;

template <unsigned N>
using CMap = CGAL::Generalized_map<N>;

template <unsigned N>
void to_cgal(const Map& g, CMap<N>& m) {
  m.clear();
  std::vector<typename CMap<N>::Dart_handle> h(g.capacity());
  g.for_each_dart([&](Dart d) { h[d] = m.create_dart(); });
  for (unsigned i = 0; i <= N; ++i)
    g.for_each_dart(
        [&](Dart d) { m.dart_link_alpha(h[d], h[g.alpha(static_cast<int>(i), d)], i); });
}

// CGAL's is_valid() prints every violation on std::cerr; silence it.
template <class M>
bool cgal_is_valid(const M& m) {
  std::ostringstream sink;
  std::streambuf* old = std::cerr.rdbuf(sink.rdbuf());
  const bool ok = m.is_valid();
  std::cerr.rdbuf(old);
  return ok;
}

// Connected components of a CGAL map, as lists of darts (BFS through every alpha_i).
template <unsigned N>
std::vector<std::vector<typename CMap<N>::Dart_const_handle>> cgal_components(const CMap<N>& m) {
  using H = typename CMap<N>::Dart_const_handle;
  std::vector<std::vector<H>> comps;
  const auto mark = m.get_new_mark();
  for (auto it = m.darts().begin(); it != m.darts().end(); ++it) {
    if (m.is_marked(it, mark)) continue;
    comps.emplace_back();
    auto& c = comps.back();
    H start = it;
    m.mark(start, mark);
    c.push_back(start);
    for (size_t k = 0; k < c.size(); ++k)
      for (unsigned i = 0; i <= N; ++i) {
        H w = m.alpha(c[k], i);
        if (!m.is_marked(w, mark)) {
          m.mark(w, mark);
          c.push_back(w);
        }
      }
  }
  for (const auto& c : comps)
    for (H d : c) m.unmark(d, mark);
  m.free_mark(mark);
  return comps;
}

// CGAL's verdict on isomorphism. CGAL's is_isomorphic_to has the precondition "the map is
// connected" (it only matches the component of the first dart), so: connected maps use
// is_isomorphic_to; otherwise components are matched one to one with are_cc_isomorphic (greedy
// matching is exact because "isomorphic" is an equivalence relation on components).
template <unsigned N>
bool cgal_isomorphic(const CMap<N>& a, const CMap<N>& b) {
  if (a.number_of_darts() != b.number_of_darts()) return false;
  if (a.number_of_darts() == 0) return true;
  const auto ca = cgal_components<N>(a), cb = cgal_components<N>(b);
  if (ca.size() != cb.size()) return false;
  if (ca.size() == 1) return a.is_isomorphic_to(b, false, false, false);
  std::vector<bool> used(cb.size(), false);
  for (const auto& c : ca) {
    bool matched = false;
    for (size_t l = 0; l < cb.size() && !matched; ++l) {
      if (used[l] || cb[l].size() != c.size()) continue;
      for (auto d2 : cb[l])
        if (a.are_cc_isomorphic(c.front(), b, d2, false, false, false)) {
          used[l] = matched = true;
          break;
        }
    }
    if (!matched) return false;
  }
  return true;
}

// Cell counts as CGAL gives them: i-cells for i = 0..N, then connected components.
template <unsigned N>
std::vector<size_t> cgal_cells(const CMap<N>& m) {
  const auto c = m.count_all_cells();
  return std::vector<size_t>(c.begin(), c.end());
}

inline std::vector<size_t> gmr_cells(const Map& g) {
  auto c = gmr::count_all_cells(g);
  c.push_back(gmr::count_components(g));
  return c;
}

// Breaks the involution of alpha_i at one dart: d -> x one way only, x != alpha_i(d) (then
// alpha_i(alpha_i(d)) = alpha_i(x) != d since the map was valid). Returns false when no such
// (i, d, x) was found (fewer than 3 darts may leave none).
inline bool break_involution(Map& g, gmr::testing::Rng& rng) {
  if (g.size() < 2) return false;
  const auto ds = g.darts();
  for (int t = 0; t < 100; ++t) {
    const Dart d = ds[gmr::testing::uniform(rng, 0, ds.size() - 1)];
    const Dart x = ds[gmr::testing::uniform(rng, 0, ds.size() - 1)];
    const int i =
        static_cast<int>(gmr::testing::uniform(rng, 0, static_cast<uint64_t>(g.dimension())));
    if (x == d || x == g.alpha(i, d)) continue;
    g.set_alpha(i, d, x);
    return true;
  }
  return false;
}

// Breaks a cycle constraint C(i,j), i+2 <= j, keeping every alpha an involution: finds d with
// e = alpha_j(d) != d and d' = alpha_i(d) not in {d, e}, d' not j-free, and makes d' j-free
// (with its partner). Then alpha_j alpha_i alpha_j alpha_i (d) = e != d. Returns false when the map
// has no such dart.
inline bool break_cycle(Map& g, gmr::testing::Rng& rng) {
  struct C {
    int i, j;
    Dart d;
  };
  std::vector<C> cands;
  const int n = g.dimension();
  for (int i = 0; i <= n; ++i)
    for (int j = i + 2; j <= n; ++j)
      g.for_each_dart([&](Dart d) {
        const Dart e = g.alpha(j, d), dp = g.alpha(i, d);
        if (e != d && dp != d && dp != e && !g.is_free(j, dp)) cands.push_back({i, j, d});
      });
  if (cands.empty()) return false;
  const C c = cands[gmr::testing::uniform(rng, 0, cands.size() - 1)];
  g.unlink(c.j, g.alpha(c.i, c.d));
  return true;
}

// --- the differential run ------------------------------------------------------------------

struct Stats {
  size_t maps = 0, darts = 0, max_darts = 0, multi_component = 0;
  size_t iso_pairs = 0, mutated_pairs = 0;
  size_t resew_iso = 0, resew_non_iso = 0, resew_none = 0;
  size_t broken_involution = 0, broken_cycle = 0;
  std::string str() const {
    std::ostringstream o;
    o << maps << " maps (" << darts << " darts, max " << max_darts << ", " << multi_component
      << " with several components); " << iso_pairs << " relabeled pairs, " << mutated_pairs
      << " mutated pairs, resewn pairs " << resew_iso << " isomorphic / " << resew_non_iso
      << " not (" << resew_none << " no resew); invalid maps: " << broken_involution
      << " broken involutions, " << broken_cycle << " broken cycles";
    return o.str();
  }
};

// Compares gmr and CGAL on one valid map g and on variants of it (see the file comment of
// cgal_diff_cgal_test.cpp). `rng` drives the variants.
template <unsigned N>
void compare_one(const Map& g, gmr::testing::Rng& rng, Stats& st) {
  using gmr::testing::Mutation;
  ++st.maps;
  st.darts += g.size();
  st.max_darts = std::max(st.max_darts, g.size());
  CMap<N> cg, ch;
  to_cgal<N>(g, cg);
  // Validity and cell counts.
  ASSERT_TRUE(gmr::is_valid(g));
  EXPECT_TRUE(cgal_is_valid(cg));
  const auto cells = gmr_cells(g);
  EXPECT_EQ(cells, cgal_cells<N>(cg));
  if (cells.back() > 1) ++st.multi_component;

  // Isomorphic pair: a random relabeling.
  {
    Map h = gmr::testing::permute_darts(g, gmr::testing::random_permutation(rng, g.capacity()));
    to_cgal<N>(h, ch);
    const bool gi = gmr::is_isomorphic(g, h), ci = cgal_isomorphic<N>(cg, ch);
    EXPECT_TRUE(gi) << "gmr: relabeled copy not isomorphic";
    EXPECT_TRUE(ci) << "CGAL: relabeled copy not isomorphic";
    EXPECT_EQ(gmr::is_isomorphic(h, g), gi);
    EXPECT_EQ(gmr::signature(g) == gmr::signature(h), ci);
    ++st.iso_pairs;
  }
  // A random relabeling of the mutated map m: valid with the same cells in both libraries, the
  // signatures equal iff CGAL finds it isomorphic to g; returns gmr's and CGAL's verdicts.
  auto relabeled_verdicts = [&](const Map& m) {
    Map h = gmr::testing::permute_darts(m, gmr::testing::random_permutation(rng, m.capacity()));
    to_cgal<N>(h, ch);
    EXPECT_TRUE(gmr::is_valid(h));
    EXPECT_TRUE(cgal_is_valid(ch));
    EXPECT_EQ(gmr_cells(h), cgal_cells<N>(ch));
    const bool gi = gmr::is_isomorphic(g, h), ci = cgal_isomorphic<N>(cg, ch);
    EXPECT_EQ(gmr::signature(g) == gmr::signature(h), ci);
    return std::pair{gi, ci};
  };
  // Non-isomorphic pair: one orbit unsewn (or sewn), then relabeled.
  {
    Map m = g;
    const Mutation mu = gmr::testing::mutate_one_link(m, rng);
    if (mu.kind != Mutation::Kind::None) {
      SCOPED_TRACE(mu.str());
      const auto [gi, ci] = relabeled_verdicts(m);
      EXPECT_FALSE(gi) << "gmr: mutated copy isomorphic";
      EXPECT_FALSE(ci) << "CGAL: mutated copy isomorphic";
      ++st.mutated_pairs;
    }
  }
  // Hard pair: one orbit re-glued elsewhere; no expected verdict, gmr must agree with CGAL.
  {
    Map m = g;
    const Mutation mu = gmr::testing::resew_one_link(m, rng);
    if (mu.kind == Mutation::Kind::None) {
      ++st.resew_none;
    } else {
      SCOPED_TRACE(mu.str());
      const auto [gi, ci] = relabeled_verdicts(m);
      EXPECT_EQ(gi, ci) << "gmr and CGAL disagree on a resewn pair";
      ++(ci ? st.resew_iso : st.resew_non_iso);
    }
  }
  // Invalid maps: both must report them.
  auto rejected_by_both = [&](const Map& b) {
    to_cgal<N>(b, ch);
    const auto rep = gmr::check_validity(b);
    EXPECT_FALSE(rep.ok());
    EXPECT_FALSE(cgal_is_valid(ch));
    return rep;
  };
  {
    Map b = g;
    if (break_involution(b, rng)) {
      const auto rep = rejected_by_both(b);
      bool has_invol = false;
      for (const auto& v : rep.violations)
        has_invol |= v.constraint == gmr::Constraint::NonOrientation;
      EXPECT_TRUE(has_invol);
      ++st.broken_involution;
    }
  }
  {
    Map b = g;
    if (break_cycle(b, rng)) {
      const auto rep = rejected_by_both(b);
      for (const auto& v : rep.violations)
        EXPECT_EQ(v.constraint, gmr::Constraint::Cycle) << gmr::to_text(v);
      ++st.broken_cycle;
    }
  }
}

}  // namespace cgal_diff
