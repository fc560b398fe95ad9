#include "checker/smt/scheme_verifier.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <set>

#include "model/core/error.hpp"
#include "model/graph/dart_permutations.hpp"

namespace gmr::smt {

namespace {
using graph::DartPermutation;

// Canonical code of a connected orbit graph: the smallest BFS relabeling over all roots.
std::vector<uint32_t> canonical(const std::vector<const DartPermutation*>& s, unsigned k) {
  std::vector<uint32_t> best;
  for (uint32_t root = 0; root < k; ++root) {
    std::vector<uint32_t> index(k, UINT32_MAX), order{root};
    index[root] = 0;
    for (size_t q = 0; q < order.size(); ++q)
      for (const DartPermutation* p : s) {
        const uint32_t y = (*p)[order[q]];
        if (index[y] == UINT32_MAX) {
          index[y] = static_cast<uint32_t>(order.size());
          order.push_back(y);
        }
      }
    std::vector<uint32_t> code;
    for (uint32_t x : order)
      for (const DartPermutation* p : s) code.push_back(index[(*p)[x]]);
    if (best.empty() || code < best) best = std::move(code);
  }
  return best;
}
}  // namespace

std::vector<OrbitGraph> hook_orbits(const OrbitType& o, unsigned max_darts) {
  const size_t a = o.size();
  std::vector<OrbitGraph> out;
  for (unsigned k = 1; k <= max_darts; ++k) {
    const auto inv = graph::involutions(k);
    std::set<std::vector<uint32_t>> seen;
    std::vector<const DartPermutation*> chosen(a, nullptr);
    std::function<void(size_t)> rec = [&](size_t p) {
      if (p == a) {
        if (!graph::connected(chosen, k)) return;
        auto code = canonical(chosen, k);
        if (!seen.insert(code).second) return;
        OrbitGraph O;
        O.arity = a;
        for (uint32_t b = 0; b < k; ++b) O.darts.push_back(b);
        // The canonical code lists, for the darts in canonical order, the neighbour per position.
        O.nb = std::move(code);
        out.push_back(std::move(O));
        return;
      }
      for (const DartPermutation& s : inv) {
        bool ok = true;
        for (size_t q = 0; q < p && ok; ++q)
          if (std::abs(o[p] - o[q]) >= 2) ok = graph::commute(*chosen[q], s);
        if (!ok) continue;
        chosen[p] = &s;
        rec(p + 1);
      }
    };
    if (a == 0) {
      if (k == 1) out.push_back(OrbitGraph{0, {0}, {}});
      continue;
    }
    rec(0);
  }
  return out;
}

SchemeVerifyResult verify_scheme(const RuleScheme& s, unsigned bound, Engine e,
                                 unsigned orbit_bound, const EncodingOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  s.validate_structure();
  SchemeVerifyResult res;
  res.bound = bound;
  res.orbit_bound = orbit_bound ? std::min(orbit_bound, bound) : bound;
  const unsigned hooks = static_cast<unsigned>(std::max<size_t>(1, s.hooks.size()));
  std::vector<OrbitGraph> orbits;
  if (s.hooks.empty()) {
    orbits.push_back(scheme::single_dart_orbit(s.orbit.size()));
  } else {
    // Each hook's instances are distinct darts of G: larger orbits cannot occur within the bound.
    orbits = hook_orbits(s.orbit, std::min(res.orbit_bound, bound / hooks));
  }
  for (const OrbitGraph& O : orbits) {
    ++res.orbits;
    Rule inst = scheme::instantiate_rule(s, O);
    VerifyResult v = e == Engine::Smt ? verify_smt(inst, bound, opt) : verify_enum(inst, bound);
    res.applicable += v.applicable;
    if (!v.preserves) {
      res.preserves = false;
      res.orbit = O;
      res.instance = std::move(inst);
      res.result = std::move(v);
      break;
    }
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace gmr::smt
