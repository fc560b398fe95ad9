// ComponentView (component_view.hpp): O's link arrays read in place or copied into the view's, the
// slots gathered by orbit dart.
#include "model/expr/component_view.hpp"

namespace gmr::expr {

void view_component(const Map& g, const scheme::ComponentInstance& c, const OrbitType& t,
                    const std::vector<const EmbeddingField*>& source, ComponentView& view) {
  const size_t sz = c.size();
  view.orbit_map = c.orbit_map && c.orbit_map->capacity() == sz ? c.orbit_map : nullptr;
  view.copy = Map(g.dimension(), g.kind());
  if (!view.orbit_map)
    view.copy.add_linked_darts(sz, [&](int i, Dart, LinkAppender& out) {
      size_t p = 0;
      while (p < t.size() && t[p] != i) ++p;
      const uint32_t* const nb = c.nb[p];
      out.append(sz, [nb](size_t b) { return nb[b]; });
    });
  view.fields.resize(source.size());
  for (size_t k = 0; k < source.size(); ++k) {
    if (!source[k]) {
      view.fields[k].reset();
      continue;
    }
    const Embedding<Vec3>& from = source[k]->values;
    EmbeddingField& v = view.fields[k].emplace(
        EmbeddingField::numeric(from.name(), from.orbit_type(), source[k]->arity));
    v.values.append_slots(sz, [&](size_t b) { return from.slot(c.darts[b]); });
    v.values.append_values(from.values());
  }
}

}  // namespace gmr::expr
