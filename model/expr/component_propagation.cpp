// EmbeddingPropagation on whole components (propagation.hpp, "Whole components"): classes derived
// from the scheme once, labelled by one sweep over the orbit before the rewrite, values written by
// one sweep over the R nodes after it.
#include <algorithm>
#include <numeric>

#include "model/core/huge_pages.hpp"
#include "model/core/orbit.hpp"
#include "model/expr/component_view.hpp"
#include "model/expr/propagation.hpp"

namespace gmr::expr {

namespace {
constexpr uint32_t kNone = UINT32_MAX;

// Whether e collects or enumerates the orbits of type `dims` somewhere (the orbits the evaluator
// lists: the classes' orbit lists are kept for them only).
bool enumerates(const Expr& e, DimMask dims) {
  if ((e.op == Expr::Op::Collect || e.op == Expr::Op::Comprehension) && e.word.empty() &&
      e.orbit_mask == dims)
    return true;
  for (const auto& a : e.args)
    if (enumerates(*a, dims)) return true;
  return false;
}
}  // namespace

// For each field: the R nodes joined by explicit arcs of dimensions in <o_pi> (one kind per
// connected set V), the dimensions o[p] of V's label positions p with o^v[p] in <o_pi>, and the
// first node of V with an expression for the field's declaration.
void EmbeddingPropagation::derive_class_kinds() {
  const scheme::RuleScheme& s = *cs_.scheme;
  const OrbitType& t = s.left.nodes[s.hook_nodes()[0]].label;
  const size_t nr = s.right.size();
  kinds_.clear();
  kinds_.resize(m_.fields.size());
  for (size_t fi = 0; fi < m_.fields.size(); ++fi) {
    const DimMask mask = m_.fields[fi].orbit().mask();
    std::vector<uint32_t> comp(nr);
    std::iota(comp.begin(), comp.end(), 0u);
    for (bool changed = true; changed;) {  // smallest node of each connected set (R is small)
      changed = false;
      for (const auto& a : s.right.arcs) {
        if (!(mask >> a.dim & 1u)) continue;
        const uint32_t m = std::min(comp[a.a], comp[a.b]);
        if (comp[a.a] != m || comp[a.b] != m) {
          comp[a.a] = comp[a.b] = m;
          changed = true;
        }
      }
    }
    int decl = -1;
    for (size_t e = 0; e < field_of_decl_.size(); ++e)
      if (field_of_decl_[e] == static_cast<int>(fi) && cs_.has_expressions(e))
        decl = static_cast<int>(e);
    for (uint32_t root = 0; root < nr; ++root) {
      if (comp[root] != root) continue;
      ClassKind k;
      for (uint32_t v = 0; v < nr; ++v) {
        if (comp[v] != root) continue;
        k.nodes.push_back(v);
        const OrbitType& label = s.right.nodes[v].label;
        for (size_t p = 0; p < label.size(); ++p)
          if (label[p] != OrbitType::kHole && (mask >> label[p] & 1u)) k.dims |= DimMask(1) << t[p];
        if (decl >= 0 && k.declaration < 0 && cs_.right[static_cast<size_t>(decl)][v]) {
          k.declaration = decl;
          k.expression_node = v;
          k.program = compile_program(*cs_.right[static_cast<size_t>(decl)][v]);
        }
      }
      for (size_t p = 0; p < t.size(); ++p)
        if (k.dims >> t[p] & 1u) k.positions.push_back(p);
      for (const auto& per_node : cs_.right)
        for (const auto& x : per_node) k.listed = k.listed || (x && enumerates(*x, k.dims));
      kinds_[fi].push_back(std::move(k));
    }
  }
  kinds_derived_ = true;
}

// The classes of a kind of one or two positions p0, p1 (p0 == p1: one), numbered in order of their
// first orbit dart: each walked from its first dart b along p0, p1, p0, ... (O's links at those
// positions, n0 and n1), and from b along p1, p0, ... when the first way ends at a free dart. list
// (when not null): the orbit darts of each class in that order, class after class, from start[id].
struct Walk {
  const uint32_t* n0;  // O's links at p0 and p1
  const uint32_t* n1;
  size_t size;
  uint32_t* class_of;
  std::vector<uint32_t>& first_b;
  uint32_t* list;
  std::vector<uint32_t>& start;
};

template <bool Lists>
uint32_t walk_classes(const Walk& w) {
  uint32_t* const class_of = w.class_of;
  const size_t sz = w.size;
  uint32_t classes = 0;
  size_t listed = 0;
  for (uint32_t b = 0; b < sz; ++b) {
    if (class_of[b] != kNone) continue;
    const uint32_t id = classes++;
    class_of[b] = id;
    w.first_b.push_back(b);
    if constexpr (Lists) {
      w.start.push_back(static_cast<uint32_t>(listed));
      w.list[listed++] = b;
    }
    // The links are involutions: the walk closes exactly when it is back at b (no read of
    // class_of to find out); the step bound only guards against links that are not involutions.
    size_t steps = 0;
    // One step from x along the links nb: 0 on to y, 1 a free end, 2 back at b (closed).
    auto step = [&](uint32_t& x, const uint32_t* nb) {
      const uint32_t y = nb[x];
      if (y == x) return 1;
      if (y == b || ++steps >= sz) return 2;
      class_of[y] = id;
      if constexpr (Lists) w.list[listed++] = y;
      x = y;
      return 0;
    };
    uint32_t x = b;
    int end = 0;
    if (w.n0 == w.n1) {  // a pair
      while (step(x, w.n0) == 0) {
      }
      continue;
    }
    while ((end = step(x, w.n0)) == 0 && (end = step(x, w.n1)) == 0) {
    }
    if (end == 2) continue;
    x = b;  // a free end: the other way from b
    while (step(x, w.n1) == 0 && step(x, w.n0) == 0) {
    }
  }
  if constexpr (Lists) w.start.push_back(static_cast<uint32_t>(listed));
  return classes;
}

// class_of[b] for every orbit dart: the orbits of the map before under k.dims, numbered in order
// of their first orbit dart, listed in first_b. Returns their number.
uint32_t EmbeddingPropagation::label_classes(const Map& g, const scheme::ComponentInstance& c,
                                             ClassKind& k) {
  const size_t sz = c.size();
  k.class_of.reserve(sz);
  std::vector<uint32_t>& class_of = *k.class_of;
  class_of.assign(sz, kNone);
  k.first_b.reserve(sz);  // pooled (the tables of one application reuse the previous one's)
  k.first_b->clear();
  (void)g;
  uint32_t classes = 0;
  if (k.positions.size() <= 2) {
    // Under one or two involutions an orbit is a pair, a path or an alternating cycle: walked
    // without a stack (walk_classes). Two positions: p0 is the one of the higher dimension, the
    // order of Evaluator::list_two_dims, and orbit dart lists of the classes of a listed kind are
    // kept in that order (orbit_list, orbit_start).
    size_t p0 = k.positions.empty() ? 0 : k.positions[0];
    size_t p1 = k.positions.size() < 2 ? p0 : k.positions[1];
    const OrbitType& t = cs_.scheme->left.nodes[cs_.scheme->hook_nodes()[0]].label;
    if (t[p1] > t[p0]) std::swap(p0, p1);
    if (k.positions.empty()) {  // every orbit dart is a class of its own
      for (uint32_t b = 0; b < sz; ++b) {
        class_of[b] = classes++;
        k.first_b->push_back(b);
      }
      k.orbit_start->clear();
      return classes;
    }
    const bool lists = p0 != p1 && k.listed;
    k.orbit_start.reserve(sz + 1);
    k.orbit_start->clear();
    if (lists) {
      k.orbit_list.reserve(sz);
      k.orbit_list->resize(sz);
    }
    // O's links at the kind's positions (the orbit's own tables: no dart index lookup).
    const Walk w{c.nb[p0],        c.nb[p1],   sz,
                 class_of.data(), *k.first_b, lists ? k.orbit_list->data() : nullptr,
                 *k.orbit_start};
    return lists ? walk_classes<true>(w) : walk_classes<false>(w);
  }
  for (uint32_t b = 0; b < sz; ++b) {
    if (class_of[b] != kNone) continue;
    const uint32_t id = classes++;
    class_of[b] = id;
    k.first_b->push_back(b);
    stack_.clear();
    stack_.push_back(b);
    while (!stack_.empty()) {
      const uint32_t x = stack_.back();
      stack_.pop_back();
      for (size_t p : k.positions) {
        const uint32_t y = c.nb[p][x];
        if (class_of[y] == kNone) {
          class_of[y] = id;
          stack_.push_back(y);
        }
      }
    }
  }
  return classes;
}

void EmbeddingPropagation::before_rewrite(const Map& g, const scheme::ComponentInstance& c) {
  if (!kinds_derived_) derive_class_kinds();
  const scheme::RuleScheme& s = *cs_.scheme;
  const size_t sz = c.size();
  std::vector<const EmbeddingField*> fields;
  for (int fi : field_of_decl_)
    fields.push_back(fi < 0 ? nullptr : &m_.fields[static_cast<size_t>(fi)]);
  // A component that is most of the map is evaluated on its view (component_view.hpp), in memo
  // mode; a small one on the map, without memo tables sized to the whole map.
  const bool on_view = sz * 8 >= g.capacity();
  std::vector<const EmbeddingField*> read = fields;
  if (on_view) {
    view_component(g, c, s.left.nodes[s.hook_nodes()[0]].label, fields, view_);
    for (size_t k = 0; k < read.size(); ++k) read[k] = fields[k] ? &*view_.fields[k] : nullptr;
  }
  // Every kind's classes first, so that each field's value array grows once, to its final size,
  // before the evaluator holds its values.
  std::vector<uint32_t> counts;
  for (size_t fi = 0; fi < kinds_.size(); ++fi) {
    size_t computed = 0;
    for (ClassKind& k : kinds_[fi]) {
      counts.push_back(label_classes(g, c, k));
      if (k.declaration >= 0) computed += counts.back();
    }
    Embedding<Vec3>& E = m_.fields[fi].values;
    E.reserve_values(E.num_values() + computed);
  }
  Evaluator ev(on_view ? view_.map() : g, cs_.embeddings, read);
  ev.memoise_collects(on_view);
  // The classes of a kind are the orbits of the map before under k.dims, numbered: the evaluator's
  // memo mode tells orbits apart by these numbers (the view's dart b is orbit dart b) instead of
  // numbering them by a sweep.
  if (on_view)
    for (auto& kinds : kinds_)
      for (ClassKind& k : kinds) {
        ev.share_orbit_numbers(k.dims, k.class_of->data(), nullptr);
        if (!k.orbit_start->empty())
          ev.share_orbit_lists(k.dims, k.orbit_list->data(), k.orbit_start->data(),
                               k.class_of->data());
      }
  // Each computed kind's values appended to its field's value array, class by class from slot
  // k.offset (step 1's buffer is the array itself); every field's appended values dropped again if
  // one class fails.
  std::vector<size_t> had;
  for (size_t fi = 0; fi < kinds_.size(); ++fi) had.push_back(m_.fields[fi].values.num_values());
  try {
    size_t ki = 0;
    for (size_t fi = 0; fi < kinds_.size(); ++fi) {
      Embedding<Vec3>& E = m_.fields[fi].values;
      for (ClassKind& k : kinds_[fi]) {
        const uint32_t count = counts[ki++];
        if (k.declaration < 0) continue;
        k.offset = static_cast<uint32_t>(E.num_values());
        E.append_values_by([&](std::vector<Vec3>& values) {
          evaluate_classes(ev, g, c, k, count, on_view, fields, values);
        });
      }
    }
  } catch (...) {
    for (size_t fi = 0; fi < kinds_.size(); ++fi) m_.fields[fi].values.truncate_values(had[fi]);
    throw;
  }
}

// Step 1 for one computed kind: the values of its count classes pushed onto out, each evaluated at
// its first orbit dart (the view's dart, or the map's).
void EmbeddingPropagation::evaluate_classes(Evaluator& ev, const Map& g,
                                            const scheme::ComponentInstance& c, const ClassKind& k,
                                            uint32_t count, bool on_view,
                                            const std::vector<const EmbeddingField*>& fields,
                                            std::vector<Vec3>& out) {
  const scheme::RuleScheme& s = *cs_.scheme;
  const auto e = static_cast<size_t>(k.declaration);
  const Expr& x = *cs_.right[e][k.expression_node];
  const std::string where = "rule " + s.name + ", R node " + s.right.nodes[k.expression_node].name +
                            ", embedding " + cs_.embeddings[e].name;
  const ValueType t = cs_.embeddings[e].type;
  auto evaluate = [&](Evaluator& on, const Dart* node_dart) {
    return k.program ? on.evaluate(*k.program, node_dart, t, where)
                     : on.evaluate(x, node_dart, t, where);
  };
  const size_t first = out.size();
  if (on_view && k.program && Evaluator::combines_node_values(*k.program)) {
    // One affine combination of node values (Loop's edge mask): every class in one loop; the
    // view's node dart at a class's first orbit dart b is b.
    const size_t done = ev.combine_classes(*k.program, k.first_b->data(), count, t, out);
    evaluations_ += done;
    if (done == count) return;  // else the class that fails is evaluated below, for its error
  } else if (on_view && k.program) {
    // Any other compiled program: the classes in lanes (evaluator_lanes.cpp), the same values.
    const size_t done = ev.run_classes(*k.program, k.first_b->data(), count, t, out);
    evaluations_ += done;
    if (done == count) return;  // else the classes from the batch that fails, one by one
  }
  for (size_t id = out.size() - first; id < count; ++id) {
    const uint32_t b = (*k.first_b)[id];
    const Dart node_dart = on_view ? b : c.darts[b];  // the hook, L's only node
    try {
      out.push_back(Evaluator::to_storage(evaluate(ev, &node_dart)));
    } catch (const Error&) {
      if (!on_view) throw;
      // The same error located on the map (its darts' numbers): the class evaluated there.
      Evaluator on_map(g, cs_.embeddings, fields);
      on_map.memoise_collects(true);
      evaluate(on_map, &c.darts[b]);
      throw;
    }
    ++evaluations_;
  }
}

// Step 3 on one kind without expression: the slot each class takes, into chosen (per class): the
// slot of its preserved darts. When they hold different slots, the one taken is the general
// path's: the first met by the traversal of the orbit of the result from the class's first dart in
// comatch order (its first node, its first orbit dart).
void EmbeddingPropagation::inherited_slots(const Map& g, const scheme::ComponentInstance& c,
                                           EmbeddingField& f, ClassKind& k,
                                           std::vector<uint32_t>& chosen) {
  constexpr uint32_t kNoValue = Embedding<Vec3>::kNoValue;
  Embedding<Vec3>& E = f.values;
  const size_t sz = c.size();
  const std::vector<uint32_t>& first_b = *k.first_b;
  const size_t classes = first_b.size();
  chosen.assign(classes, kNoValue);
  std::vector<bool> mixed(classes, false), reported(classes, false);
  auto preserved = [&](uint32_t v) {
    return c.engine->added_rank(v) == scheme::SchemeEngine::kAdded;
  };
  for (uint32_t v : k.nodes) {
    if (!preserved(v)) continue;
    for (uint32_t b = 0; b < sz; ++b) {
      const uint32_t sl = E.slot(c.darts[b]), id = (*k.class_of)[b];
      if (sl == kNoValue) continue;
      if (chosen[id] == kNoValue)
        chosen[id] = sl;
      else if (sl != chosen[id])
        mixed[id] = true;
    }
  }
  for (uint32_t id = 0; id < classes; ++id) {
    if (!mixed[id]) continue;
    ScopedMarker mk(g);
    orbit_darts_.clear();
    visit_orbit_marked(g, f.orbit().mask(), c.comatch(k.nodes[0], first_b[id]), mk.id(), stack_,
                       [&](Dart y) { orbit_darts_.push_back(y); });
    for (Dart y : orbit_darts_) mk.unmark(y);
    mk.set_clean();
    for (Dart y : orbit_darts_) {
      // Added darts have no value yet: only preserved darts (below the added ones) count.
      if (y >= c.base && y < c.base + c.engine->added_count() * sz) continue;
      if (E.slot(y) != kNoValue) {
        chosen[id] = E.slot(y);
        break;
      }
    }
  }
  for (uint32_t v : k.nodes) {
    if (!preserved(v)) continue;
    for (uint32_t b = 0; b < sz; ++b) {
      const uint32_t sl = E.slot(c.darts[b]), id = (*k.class_of)[b];
      if (!mixed[id] || reported[id] || sl == kNoValue ||
          detail::same_value(E.value(sl), E.value(chosen[id])))
        continue;
      report("E-merge", f, c.darts[b],
             "the rewrite merges orbits of values " + detail::text(E.value(chosen[id]), f.arity) +
                 " and " + detail::text(E.value(sl), f.arity) +
                 " and no expression gives the merged orbit a value");
      reported[id] = true;
    }
  }
  if (E.num_values() > 0)
    for (uint32_t id = 0; id < classes; ++id)
      if (chosen[id] == kNoValue)
        report(
            "E-no-value", f, c.comatch(k.nodes[0], first_b[id]),
            "a new " + f.orbit().str() + "-orbit has no value: no expression, no preserved dart");
}

// Steps 2 and 3: every dart of the result in the component takes the slot of its class, in its
// node's kind: k.offset + class for a computed kind (its values appended before the rewrite),
// chosen[class] for an inherited one. Preserved darts are written in place, computed kinds first
// (the traversal of a mixed inherited class reads them), then each inherited kind; the added darts'
// slots, rank by rank, are appended to the slot table when it ends where they start.
void EmbeddingPropagation::after_rewrite(const Map& g, const scheme::ComponentInstance& c) {
  constexpr uint32_t kNoValue = Embedding<Vec3>::kNoValue;
  const size_t sz = c.size();
  const size_t nr = cs_.scheme->right.size();
  auto preserved = [&](uint32_t v) {
    return c.engine->added_rank(v) == scheme::SchemeEngine::kAdded;
  };
  for (size_t fi = 0; fi < m_.fields.size(); ++fi) {
    EmbeddingField& f = m_.fields[fi];
    Embedding<Vec3>& E = f.values;
    std::vector<ClassKind>& kinds = kinds_[fi];
    E.reserve_slots(g.capacity());  // the slot table grown once, to the darts after the rewrite
    if (E.slots().size() < c.base)
      E.append_slots(c.base - E.slots().size(), [](size_t) { return kNoValue; });
    chosen_.resize(std::max(chosen_.size(), kinds.size()));
    std::vector<uint32_t> kind_of(nr, 0);
    auto slot_of = [&](size_t ki) {
      const uint32_t* const class_of = kinds[ki].class_of->data();
      const uint32_t* const table = kinds[ki].declaration < 0 ? chosen_[ki].data() : nullptr;
      const uint32_t off = kinds[ki].offset;
      return [=](uint32_t b) { return table ? table[class_of[b]] : off + class_of[b]; };
    };
    auto write_preserved = [&](size_t ki) {
      const auto slot = slot_of(ki);
      for (uint32_t v : kinds[ki].nodes)
        if (preserved(v))
          c.for_each_dart([&](Dart x, uint32_t b) { E.set_slot_unchecked(x, slot(b)); });
    };
    for (size_t ki = 0; ki < kinds.size(); ++ki) {
      for (uint32_t v : kinds[ki].nodes) kind_of[v] = static_cast<uint32_t>(ki);
      if (kinds[ki].declaration < 0) continue;
      write_preserved(ki);
    }
    for (size_t ki = 0; ki < kinds.size(); ++ki) {
      if (kinds[ki].declaration >= 0) continue;
      inherited_slots(g, c, f, kinds[ki], chosen_[ki]);
      write_preserved(ki);
    }
    std::vector<uint32_t> node_of_rank(c.engine->added_count());
    for (uint32_t v = 0; v < nr; ++v)
      if (!preserved(v)) node_of_rank[c.engine->added_rank(v)] = v;
    const bool appended = E.slots().size() == c.base;
    if (!appended) E.fit(g);
    for (uint32_t v : node_of_rank) {
      const auto slot = slot_of(kind_of[v]);
      const ClassKind& k = kinds[kind_of[v]];
      if (appended && k.declaration >= 0) {  // computed: offset + class
        E.append_slots_offset(k.class_of->data(), sz, k.offset);
      } else if (appended) {
        E.append_slots(sz, [&](size_t b) { return slot(static_cast<uint32_t>(b)); });
      } else {
        const Dart first = c.comatch(v, 0);
        for (uint32_t b = 0; b < sz; ++b) E.set_slot_unchecked(first + b, slot(b));
      }
    }
  }
}

}  // namespace gmr::expr
