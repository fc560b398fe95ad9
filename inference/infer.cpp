#include "inference/infer.hpp"

#include <algorithm>

#include "inference/scheme_isomorphism.hpp"

namespace gmr::inference {

const char* to_string(AttemptOutcome o) {
  switch (o) {
    case AttemptOutcome::FoldFailed:
      return "fold failed";
    case AttemptOutcome::NoHook:
      return "no hook";
    case AttemptOutcome::Inconsistent:
      return "rejected by the checker";
    case AttemptOutcome::Accepted:
      return "accepted";
    case AttemptOutcome::Duplicate:
      return "duplicate";
  }
  return "?";
}

std::vector<OrbitType> all_orbit_types(int n) {
  std::vector<DimMask> masks;
  for (DimMask m = 0; m < (DimMask(1) << (n + 1)); ++m) masks.push_back(m);
  auto dims = [](DimMask m) {
    std::vector<int> d;
    for (int i = 0; m >> i; ++i)
      if ((m >> i) & 1u) d.push_back(i);
    return d;
  };
  std::stable_sort(masks.begin(), masks.end(), [&](DimMask x, DimMask y) {
    const auto dx = dims(x), dy = dims(y);
    if (dx.size() != dy.size()) return dx.size() < dy.size();
    return dx < dy;
  });
  std::vector<OrbitType> out;
  for (DimMask m : masks) out.emplace_back(dims(m));
  return out;
}

std::vector<uint32_t> equivalent_starts(const FoldResult& f) {
  std::vector<uint32_t> out;
  for (const auto& n : f.nodes)
    if (n.side == Side::L && !n.label.has_hole() && n.label.mask() == f.orbit.mask())
      for (uint32_t x : n.darts)
        if (x != kUndefined) out.push_back(x);
  return out;
}

InferenceResult infer_rules(const JointGraph& j, const InferOptions& opt) {
  InferenceResult res;
  const std::vector<OrbitType> types =
      opt.orbit ? std::vector<OrbitType>{*opt.orbit} : all_orbit_types(j.dimension());
  std::vector<uint8_t> marked(j.size());
  FoldWorkspace ws(j.size());
  auto process = [&](const FoldResult& f, const OrbitType& o, uint32_t a) {
    InferAttempt at;
    at.orbit = o;
    at.start = a;
    at.start_text = j.describe(a);
    marked[a] = 1;
    for (uint32_t x : equivalent_starts(f)) marked[x] = 1;
    if (!f.ok()) {
      at.outcome = AttemptOutcome::FoldFailed;
      at.failure = f.failure;
      at.reason = f.failure.message;
      for (const auto& n : f.nodes) (n.side == Side::L ? at.left_nodes : at.right_nodes)++;
      res.attempts.push_back(std::move(at));
      return;
    }
    for (const auto& n : f.nodes) (n.side == Side::L ? at.left_nodes : at.right_nodes)++;
    InferredRule r = rule_from_fold(f, j, "inferred_" + std::to_string(res.rules.size()), opt.rule);
    if (!r.accepted()) {
      at.outcome =
          r.verdict == RuleVerdict::NoHook ? AttemptOutcome::NoHook : AttemptOutcome::Inconsistent;
      at.reason = r.reason;
      at.rejected = std::move(r);
      res.attempts.push_back(std::move(at));
      return;
    }
    int dup = -1;
    for (size_t k = 0; k < res.rules.size() && dup < 0; ++k)
      if (schemes_isomorphic(r.scheme, res.rules[k].scheme)) dup = static_cast<int>(k);
    if (dup >= 0) {
      at.outcome = AttemptOutcome::Duplicate;
      at.rule = dup;
      ++res.duplicates[static_cast<size_t>(dup)];
    } else {
      at.outcome = AttemptOutcome::Accepted;
      at.rule = static_cast<int>(res.rules.size());
      res.rules.push_back(std::move(r));
      res.duplicates.push_back(0);
    }
    res.attempts.push_back(std::move(at));
  };
  for (size_t t = 0; t < types.size(); ++t) {
    const OrbitType& o = types[t];
    std::fill(marked.begin(), marked.end(), 0);
    for (uint32_t a = 0; a < j.size(); ++a) {
      if (j.side(a) != Side::L || marked[a]) continue;
      std::vector<FoldResult> folds;
      if (opt.all_relabelings) {
        FoldAll all = fold_all(j, o, a, opt.fold, opt.relabeling_limit, &ws);
        folds = std::move(all.folds);
        res.truncated = res.truncated || all.truncated;
      }
      if (folds.empty()) folds.push_back(fold(j, o, a, opt.fold, &ws));
      for (const FoldResult& f : folds) process(f, o, a);
    }
    if (opt.progress) opt.progress(t + 1, types.size(), o);
  }
  return res;
}

}  // namespace gmr::inference
