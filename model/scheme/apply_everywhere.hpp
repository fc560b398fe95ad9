// Repeated application of a one-hook rule scheme at every dart of a map, as Jerboa applies a rule
// "everywhere" (thesis §6.3.4; the engine is model/scheme/scheme_engine.hpp).
//
// Contract: the darts alive in g before the first application are visited in increasing order. At a
// dart that is still alive and not yet used by an application (as a matched dart), the scheme is
// applied in place with that dart as its hook when it applies; the matched darts of every successful
// application then count as used. Darts created by an application are never hooks. E.g. quad
// subdivision (orbit <0,1,2>) applies once per connected component, vertex insertion on <0> once per
// edge. The result is deterministic: it depends only on the map's dart numbering.
//
// Throws gmr::Error(Usage) when the scheme does not have exactly one hook, and whatever
// SchemeEngine::apply throws (wrong map kind or dimension). Inapplicability at a dart is not an
// error: the dart is skipped and the map is unchanged by it.
//
// Cost: one SchemeEngine::apply per visited dart, i.e. O(|D| · c) where c is the cost of a failed
// or successful application (linear in the instantiated rule, see scheme_engine.hpp), plus O(|D|)
// for the used-dart table (|D| = capacity of g before the first application).
#pragma once
#include <vector>

#include "model/core/map.hpp"
#include "model/scheme/scheme_engine.hpp"

namespace gmr::scheme {

struct EverywhereApplication {
  // The successful applications in the order they were made; hooks[k] is the hook dart of
  // applications[k].
  std::vector<SchemeApplication> applications;
  std::vector<Dart> hooks;
  // When no application succeeded: the report of the last dart tried (reason and why); else empty.
  SchemeApplication last_failure;

  size_t count() const { return applications.size(); }
  size_t darts_added() const;
  size_t darts_deleted() const;
};

// Applies `engine` at every dart of g (see above). With keep_tables == false, the orbit, match and
// comatch tables of each application are dropped (they grow with the number of applications).
// `observer` (optional) sees every successful application (scheme_engine.hpp).
// When the scheme rewrites whole components (component_rewrite.hpp) and the observer is absent or
// is also a ComponentObserver, the same result is computed by apply_everywhere_by_components.
EverywhereApplication apply_everywhere(const SchemeEngine& engine, Map& g, bool keep_tables = true,
                                       ApplicationObserver* observer = nullptr);
// The contract above, always one SchemeEngine::apply per visited dart (the reference the
// whole-component path is tested against).
EverywhereApplication apply_everywhere_at_each_dart(const SchemeEngine& engine, Map& g, bool keep_tables = true,
                                                    ApplicationObserver* observer = nullptr);

}  // namespace gmr::scheme
