#include "model/expr/propagation.hpp"

#include <cmath>
#include <numeric>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"

namespace gmr::expr {

namespace {

uint32_t find_root(std::vector<uint32_t>& p, uint32_t x) {
  while (p[x] != x) {
    p[x] = p[p[x]];
    x = p[x];
  }
  return x;
}

void unite(std::vector<uint32_t>& p, uint32_t a, uint32_t b) {
  a = find_root(p, a);
  b = find_root(p, b);
  if (a == b) return;
  if (a < b)
    p[b] = a;
  else
    p[a] = b;
}

}  // namespace

namespace detail {

bool same_value(const Vec3& a, const Vec3& b) {
  for (size_t k = 0; k < 3; ++k) {
    const double scale = std::max({1.0, std::fabs(a[k]), std::fabs(b[k])});
    if (std::fabs(a[k] - b[k]) > 1e-9 * scale) return false;
  }
  return true;
}

std::string text(const Vec3& v, int arity) {
  if (arity == 1) return std::to_string(v[0]);
  return "(" + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " + std::to_string(v[2]) +
         ")";
}

}  // namespace detail

using detail::same_value;
using detail::text;

namespace {

// Rule applications carry numeric embeddings only (embedded_map.hpp): a JSON embedding would
// leave the new orbits without values. Error(Schema) naming the first value that is not numeric.
void require_numeric_embeddings(const EmbeddedMap& m) {
  for (const EmbeddingField& f : m.fields) {
    if (f.is_numeric()) continue;
    int arity = 0;
    for (Dart rep : orbit_representatives(m.map, f.orbit())) {
      if (!f.has(rep)) continue;
      const nlohmann::json v = f.value_json(rep);
      const std::string where = "embedding '" + f.name() + "', dart " + std::to_string(rep);
      int a = 0;
      if (numeric_value_problem(v, a))
        throw Error(
            ErrorCode::Schema,
            "rule applications carry numeric embeddings only (a number or [x, y, z]); found " +
                v.dump(),
            where);
      if (arity != 0 && a != arity)
        throw Error(ErrorCode::Schema, "the embedding mixes numbers and triples", where);
      arity = a;
    }
  }
}

}  // namespace

EmbeddingPropagation::EmbeddingPropagation(const CompiledScheme& cs, EmbeddedMap& m)
    : cs_(cs), m_(m) {
  require_numeric_embeddings(m);
  for (const auto& sig : cs.embeddings) {
    const int arity_wanted = arity(sig.type);
    EmbeddingField* f = m.find(sig.name);
    if (!f) {  // the map is not embedded for it: its expressions are not evaluated
      field_of_decl_.push_back(-1);
      continue;
    }
    if (!(f->orbit() == sig.orbit))
      throw Error(ErrorCode::Schema,
                  "the rule declares '" + sig.name + "' on " + sig.orbit.str() +
                      ", the map has it on " + f->orbit().str(),
                  "embedding " + sig.name);
    if (f->values.num_values() > 0 && f->arity != arity_wanted)
      throw Error(ErrorCode::Schema,
                  "the rule declares '" + sig.name + "' as " + to_string(sig.type) +
                      " values, the map holds " + (f->arity == 1 ? "numbers" : "triples"),
                  "embedding " + sig.name);
    f->arity = arity_wanted;
    field_of_decl_.push_back(static_cast<int>(f - m.fields.data()));
  }
  for (const auto& f : m.fields) require_orbit_type(m.map, f.orbit());
}

void EmbeddingPropagation::report(std::string code, const EmbeddingField& f, Dart d,
                                  std::string message) {
  ++issue_count_;
  if (issues_.size() < 100) issues_.push_back({std::move(code), f.name(), d, std::move(message)});
}

void EmbeddingPropagation::before_rewrite(const Map& g, const scheme::SchemeApplication& app,
                                          const scheme::OrbitGraph& O) {
  const scheme::RuleScheme& s = *cs_.scheme;
  const size_t sz = O.size(), nr = s.right.size(), nl = s.left.size();
  pending_.assign(m_.fields.size(), {});
  std::vector<const EmbeddingField*> fields;
  for (int fi : field_of_decl_)
    fields.push_back(fi < 0 ? nullptr : &m_.fields[static_cast<size_t>(fi)]);
  Evaluator ev(g, cs_.embeddings, fields);
  // An application covering much of the map reads the same collects from many places.
  ev.memoise_collects(sz * 8 >= g.capacity());
  std::vector<Dart> node_darts(nl);
  for (size_t e = 0; e < cs_.embeddings.size(); ++e) {
    if (!cs_.has_expressions(e) || field_of_decl_[e] < 0) continue;
    const DimMask mask = cs_.embeddings[e].orbit.mask();
    // Classes of the instantiated R over the dimensions of <o_pi>.
    parent_.resize(nr * sz);
    std::iota(parent_.begin(), parent_.end(), 0u);
    for (uint32_t v = 0; v < nr; ++v) {
      const OrbitType& label = s.right.nodes[v].label;
      for (size_t p = 0; p < label.size(); ++p)
        if (label[p] != OrbitType::kHole && (mask >> label[p] & 1u))
          for (uint32_t b = 0; b < sz; ++b)
            unite(parent_, static_cast<uint32_t>(v * sz + b),
                  static_cast<uint32_t>(v * sz + O.neighbor(b, p)));
    }
    for (const auto& a : s.right.arcs)
      if (mask >> a.dim & 1u)
        for (uint32_t b = 0; b < sz; ++b)
          unite(parent_, static_cast<uint32_t>(a.a * sz + b), static_cast<uint32_t>(a.b * sz + b));
    std::vector<bool> done(nr * sz, false);
    auto& out = pending_[static_cast<size_t>(field_of_decl_[e])];
    size_t with_expression = 0;
    for (uint32_t v = 0; v < nr; ++v) with_expression += cs_.right[e][v] ? 1 : 0;
    out.reserve(out.size() + with_expression * sz);  // an upper bound; untouched pages cost nothing
    for (uint32_t v = 0; v < nr; ++v) {
      const auto& x = cs_.right[e][v];
      if (!x) continue;
      const std::string where = "rule " + s.name + ", R node " + s.right.nodes[v].name +
                                ", embedding " + cs_.embeddings[e].name;
      for (uint32_t b = 0; b < sz; ++b) {
        const uint32_t r = find_root(parent_, static_cast<uint32_t>(v * sz + b));
        if (done[r]) continue;
        done[r] = true;
        for (uint32_t l = 0; l < nl; ++l) node_darts[l] = app.match[l * sz + b];
        const Val val = ev.evaluate(*x, node_darts.data(), cs_.embeddings[e].type, where);
        ++evaluations_;
        out.push_back({v, b, Evaluator::to_storage(val)});
      }
    }
  }
}

void EmbeddingPropagation::after_rewrite(const Map& g, const scheme::SchemeApplication& app,
                                         const scheme::OrbitGraph& O) {
  const scheme::RuleScheme& s = *cs_.scheme;
  const size_t sz = O.size(), nr = s.right.size();
  for (size_t fi = 0; fi < m_.fields.size(); ++fi) {
    EmbeddingField& f = m_.fields[fi];
    Embedding<Vec3>& E = f.values;
    const DimMask mask = f.orbit().mask();
    // Added darts start without value (their indices may be reused ones).
    for (uint32_t v = 0; v < nr; ++v)
      if (!s.left_of(v))
        for (uint32_t b = 0; b < sz; ++b)
          E.set_slot(g, app.comatch[v * sz + b], Embedding<Vec3>::kNoValue);
    ScopedMarker vis(g);
    touched_.clear();
    touched_all_ = false;
    // The marked darts are listed for unmarking until they are more than a 64th of the map;
    // beyond, clearing the whole marker is cheaper (an application at every dart of a surface).
    const size_t list_limit = g.capacity() / 64 + 16;
    auto remember = [&](Dart y) {
      if (touched_all_) return;
      if (touched_.size() >= list_limit) {
        touched_all_ = true;
        return;
      }
      touched_.push_back(y);
    };
    // 2. computed values
    if (pending_.size() < m_.fields.size()) pending_.resize(m_.fields.size());
    E.reserve_values(E.num_values() + pending_[fi].size());
    for (const Pending& p : pending_[fi]) {
      const Dart x = app.comatch[p.v * sz + p.b];
      if (vis.test(x)) {
        const Vec3& old = E.get(x);
        if (!same_value(old, p.value))
          report("E-overlap", f, x,
                 "the orbit receives two values, " + text(old, f.arity) + " and " +
                     text(p.value, f.arity) + " (from R node " + s.right.nodes[p.v].name + ")");
        continue;
      }
      const uint32_t slot = E.add_value(p.value);
      E.set_slot(g, x, slot);  // sizes the slot table once; the orbit's darts are below capacity
      visit_orbit_marked(g, mask, x, vis.id(), stack_, [&](Dart y) {
        E.set_slot_unchecked(y, slot);
        remember(y);
      });
    }
    // 3. inherited values
    for (Dart x : app.comatch) {
      if (vis.test(x)) continue;
      orbit_darts_.clear();
      visit_orbit_marked(g, mask, x, vis.id(), stack_, [&](Dart y) { orbit_darts_.push_back(y); });
      for (Dart y : orbit_darts_) remember(y);
      uint32_t slot = Embedding<Vec3>::kNoValue;
      bool reported = false;
      for (Dart y : orbit_darts_) {
        const uint32_t sy = E.slot(y);
        if (sy == Embedding<Vec3>::kNoValue) continue;
        if (slot == Embedding<Vec3>::kNoValue) {
          slot = sy;
        } else if (sy != slot && !reported && !same_value(E.value(sy), E.value(slot))) {
          report("E-merge", f, y,
                 "the rewrite merges orbits of values " + text(E.value(slot), f.arity) + " and " +
                     text(E.value(sy), f.arity) +
                     " and no expression gives the merged orbit a value");
          reported = true;
        }
      }
      if (slot == Embedding<Vec3>::kNoValue) {
        // Reported when the map carries this embedding at all (a map without any value of it is
        // not embedded for it, and stays so).
        if (E.num_values() > 0)
          report(
              "E-no-value", f, x,
              "a new " + f.orbit().str() + "-orbit has no value: no expression, no preserved dart");
        continue;
      }
      // One slot for the whole orbit (the evaluator's collects rely on it, evaluator.hpp).
      for (Dart y : orbit_darts_)
        if (E.slot(y) != slot) E.set_slot(g, y, slot);
    }
    if (!touched_all_) {
      for (Dart y : touched_) vis.unmark(y);
      vis.set_clean();
    }  // else the marker is cleared whole when released
  }
}

}  // namespace gmr::expr
