#include "inference/relabeling.hpp"

#include <algorithm>

namespace gmr::inference {

std::vector<int> order_candidates(std::vector<int> dims, int o_p, bool loop,
                                  const LoopPolicy& policy) {
  std::sort(dims.begin(), dims.end());
  std::vector<int> out;
  if (std::find(dims.begin(), dims.end(), o_p) != dims.end() && (!loop || policy.implicit(o_p)))
    out.push_back(o_p);
  for (int j : dims)
    if (j != o_p && (!loop || policy.implicit(j))) out.push_back(j);
  // `_` comes last at every position: a position without candidate is a deletion; a loop position
  // may be read as an explicit loop; and a candidate already taken by another position (the thesis
  // removes used dimensions from C before choosing, Alg. 6 buildOrbType) leaves a deletion.
  (void)loop;
  out.push_back(OrbitType::kHole);
  return out;
}

namespace {

struct Search {
  const RelabelingCandidates& c;
  const std::function<bool(size_t, int)>& passes;
  std::vector<std::vector<int>> ok;  // ok[p][k]: -1 unknown, 0 fails, 1 passes
  std::vector<int> label;
  DimMask used = 0;

  bool test(size_t p, size_t k) {
    const int j = c.candidates[p][k];
    if (j == OrbitType::kHole) return true;
    if (ok[p][k] < 0) ok[p][k] = passes(p, j) ? 1 : 0;
    return ok[p][k] == 1;
  }

  // Calls f(label) for each consistent assignment; stops when f returns false.
  // Rule 3: a deleted non-loop position needs all its candidates used elsewhere.
  bool admissible() const {
    for (size_t p = 0; p < label.size(); ++p) {
      if (label[p] != OrbitType::kHole || (p < c.loop.size() && c.loop[p])) continue;
      for (int j : c.candidates[p])
        if (j != OrbitType::kHole && !((used >> j) & 1u)) return false;
    }
    return true;
  }

  template <class F>
  bool run(size_t p, F& f) {
    if (p == c.candidates.size()) return admissible() ? f(label) : true;
    for (size_t k = 0; k < c.candidates[p].size(); ++k) {
      const int j = c.candidates[p][k];
      if (j != OrbitType::kHole && ((used >> j) & 1u)) continue;
      if (!test(p, k)) continue;
      label[p] = j;
      if (j != OrbitType::kHole) used |= DimMask(1) << j;
      const bool go_on = run(p + 1, f);
      if (j != OrbitType::kHole) used &= ~(DimMask(1) << j);
      if (!go_on) return false;
    }
    return true;
  }
};

}  // namespace

RelabelingChoice choose_relabeling(const RelabelingCandidates& c,
                                   const std::function<bool(size_t, int)>& passes) {
  Search s{c, passes, {}, std::vector<int>(c.candidates.size(), OrbitType::kHole)};
  for (const auto& cp : c.candidates) s.ok.emplace_back(cp.size(), -1);
  RelabelingChoice out;
  auto take = [&](const std::vector<int>& label) {
    out.label = label;
    return false;
  };
  s.run(0, take);
  if (out.label) return out;
  // Explain: the first non-loop position that has candidates, all failing the check.
  for (size_t p = 0; p < c.candidates.size(); ++p) {
    if (p < c.loop.size() && c.loop[p]) continue;
    bool any_candidate = false, any_pass = false;
    for (size_t k = 0; k < c.candidates[p].size(); ++k) {
      if (c.candidates[p][k] == OrbitType::kHole) continue;
      any_candidate = true;
      any_pass = any_pass || s.test(p, k);
    }
    if (any_candidate && !any_pass) {
      out.failed_position = static_cast<int>(p);
      out.failed_dim = c.candidates[p].front();
      return out;
    }
  }
  out.failed_position = 0;
  out.failed_dim =
      c.candidates.empty() || c.candidates[0].empty() ? OrbitType::kHole : c.candidates[0][0];
  return out;
}

std::vector<std::vector<int>> enumerate_relabelings(
    const RelabelingCandidates& c, const std::function<bool(size_t, int)>& passes) {
  Search s{c, passes, {}, std::vector<int>(c.candidates.size(), OrbitType::kHole)};
  for (const auto& cp : c.candidates) s.ok.emplace_back(cp.size(), -1);
  std::vector<std::vector<int>> all;
  auto keep = [&](const std::vector<int>& label) {
    all.push_back(label);
    return true;
  };
  s.run(0, keep);
  return all;
}

}  // namespace gmr::inference
