// Repeated application of a one-hook rule scheme at every dart of a map, as Jerboa applies a rule
// "everywhere" (thesis §6.3.4; the engine is model/scheme/scheme_engine.hpp).
//
// Contract: the darts alive in g before the first application are visited in increasing order. At a
// dart that is still alive and not yet used by an application (as a matched dart), the scheme is
// applied in place with that dart as its hook when it applies; the matched darts of every
// successful application then count as used. Darts created by an application are never hooks. E.g.
// quad subdivision (orbit <0,1,2>) applies once per connected component, vertex insertion on <0>
// once per edge. The result is deterministic: it depends only on the map's dart numbering.
//
// Throws gmr::Error(Usage) when the scheme does not have exactly one hook, and whatever
// scheme::apply throws (wrong map kind or dimension). Inapplicability at a dart is not an
// error: the dart is skipped and the map is unchanged by it.
//
// Two paths compute this contract (EverywherePath): one scheme::apply per visited dart, and the
// whole-component rewrite (component_rewrite.hpp) for schemes that rewrite whole components, which
// gives the same result dart for dart; the choice is made once per call, never per dart.
//
// Cost: one scheme::apply per visited dart, i.e. O(|D| · c) where c is the cost of a failed
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

enum class EverywherePath {
  // By components when the scheme rewrites whole components of g (rewrites_whole_components) and
  // the observer is absent or is also a ComponentObserver; else at each dart.
  Automatic,
  AtEachDart,  // one scheme::apply per visited dart: the reference the other path is tested against
  ByComponents,  // the whole-component rewrite; Error(Usage) when it does not apply (see Automatic)
};

struct EverywhereOptions {
  // With false, the orbit, match and comatch tables of each application are dropped (they grow
  // with the number of applications).
  bool keep_tables = true;
  // Sees every successful application (scheme_engine.hpp), or every component when it is also a
  // ComponentObserver and the whole-component path is taken.
  ApplicationObserver* observer = nullptr;
  EverywherePath path = EverywherePath::Automatic;
};

// Applies `engine` at every dart of g, in place (see above).
EverywhereApplication apply_everywhere(const SchemeEngine& engine, Map& g,
                                       const EverywhereOptions& options = {});

}  // namespace gmr::scheme
