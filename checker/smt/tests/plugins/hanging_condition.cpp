// A condition plug-in that never returns on the first rule with a deleted node (bad-input test of
// the per-evaluation time limit).
#include <atomic>

#include "checker/smt/condition_api.hpp"

namespace {
std::atomic<bool> forever{true};
bool holds(const gmr::condition::RuleView& r) {
  for (const auto& v : r.left.nodes)
    if (v.status == gmr::condition::Status::Deleted)
      while (forever.load()) {
      }
  return true;
}
}  // namespace

GMR_CONDITION_PLUGIN("hanging", "never returns on a deleted node", holds)
