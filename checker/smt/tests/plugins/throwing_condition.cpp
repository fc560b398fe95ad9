// A condition plug-in that throws on the first rule with a deleted node (bad-input test).
#include <stdexcept>

#include "checker/smt/condition_api.hpp"

namespace {
bool holds(const gmr::condition::RuleView& r) {
  for (const auto& v : r.left.nodes)
    if (v.status == gmr::condition::Status::Deleted)
      throw std::runtime_error("deleted nodes are not supported");
  return true;
}
}  // namespace

GMR_CONDITION_PLUGIN("throwing", "throws on a deleted node", holds)
