// A condition on rule schemes (docs/verify.md, "Condition plug-ins"): every node of L and of R has
// exactly one d-arc (explicit, or implicit through its label) for every dimension d of the model.
#include "checker/smt/condition_api.hpp"

namespace {
using namespace gmr::condition;
bool full_degree(const SchemeView& s, Side side) {
  for (unsigned v = 0; v < s.side(side).nodes.size(); ++v)
    for (int d = 0; d <= s.n; ++d)
      if (s.arcs(side, v, d) != 1) return false;
  return true;
}
bool holds(const SchemeView& s) {
  return full_degree(s, Side::Left) && full_degree(s, Side::Right);
}
}  // namespace

GMR_SCHEME_CONDITION_PLUGIN("full-degree",
                            "every scheme node has one d-arc per dimension on both sides", holds)
