// A condition plug-in that crashes (SIGSEGV) on the first rule with an added node (bad-input test).
#include <csignal>

#include "checker/smt/condition_api.hpp"

namespace {
bool holds(const gmr::condition::RuleView& r) {
  for (const auto& v : r.right.nodes)
    if (v.status == gmr::condition::Status::Added) std::raise(SIGSEGV);
  return true;
}
}  // namespace

GMR_CONDITION_PLUGIN("crashing", "crashes on an added node", holds)
