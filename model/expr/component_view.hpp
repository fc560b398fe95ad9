// The component of a whole-component application (model/scheme/component_rewrite.hpp), before
// its rewrite, as a map of its own numbered by orbit dart b: dart b is O.darts[b], its i-link is
// O's link at the position of dimension i, and each embedding's slot at b is the slot of O.darts[b]
// (the values are copied). The expressions of the application read darts of the component only,
// so evaluated on the view at b they give, bit for bit, their values at O.darts[b] on the map:
// the view is isomorphic to the component and the evaluator depends on the links and slots alone
// (tested in model/expr/tests/component_view_test.cpp). What changes is where the reads land: O is
// numbered in BFS order, so the darts of an orbit and their neighbours have close numbers, while
// on the map they are spread over the blocks the previous rewrites appended (docs/embeddings.md,
// "Evaluation on the component's view").
#pragma once
#include <optional>
#include <vector>

#include "model/core/embedded_map.hpp"
#include "model/core/map.hpp"
#include "model/scheme/component_rewrite.hpp"

namespace gmr::expr {

struct ComponentView {
  // The view's links: O's own map (ComponentInstance::orbit_map) when the component is the whole
  // map, read in place; else a copy of its first size() darts' links.
  const Map& map() const { return orbit_map ? *orbit_map : copy; }
  std::vector<std::optional<EmbeddingField>> fields;  // fields[k]: the view of source[k], if any

  const Map* orbit_map = nullptr;
  Map copy{2};
};

// Fills `view` (its storage reused) with the view of component c of g, whose hook label is t
// (position p of O follows dimension t[p]); `source` are the fields the expressions read (null:
// a declared embedding the map lacks). The view reads c.orbit_map: it is valid until the rewrite.
void view_component(const Map& g, const scheme::ComponentInstance& c, const OrbitType& t,
                    const std::vector<const EmbeddingField*>& source, ComponentView& view);

}  // namespace gmr::expr
