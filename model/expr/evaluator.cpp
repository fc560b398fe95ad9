#include "model/expr/evaluator.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "model/core/error.hpp"
#include "model/core/huge_pages.hpp"
#include "model/core/orbit.hpp"

namespace gmr::expr {

namespace {

using ops::add;
using ops::scale;
using ops::sub;
using K = StaticType::Kind;

// Whether two entries of v are equal: pairwise for the few pieces of a face or a vertex, sorted
// (in `buffer`) beyond.
bool has_duplicate(const std::vector<uint32_t>& v, std::vector<uint32_t>& buffer) {
  if (v.size() <= 16) {
    for (size_t i = 1; i < v.size(); ++i)
      for (size_t j = 0; j < i; ++j)
        if (v[i] == v[j]) return true;
    return false;
  }
  buffer.assign(v.begin(), v.end());
  std::sort(buffer.begin(), buffer.end());
  return std::adjacent_find(buffer.begin(), buffer.end()) != buffer.end();
}

}  // namespace

Evaluator::Evaluator(const Map& g, std::vector<EmbeddingSignature> sigs,
                     std::vector<const EmbeddingField*> fields)
    : g_(g), sigs_(std::move(sigs)), fields_(std::move(fields)) {
  for (const EmbeddingSignature& s : sigs_) types_.push_back(s.type);
  scratch_.resize(3 * kMaxNesting);  // never resized later: members() holds references into it
}

void Evaluator::memoise_collects(bool on) {
  memo_on_ = on;
  memos_.clear();
  ids_.clear();
  lists_.clear();
  for (auto& w : last_walk_) w.valid = false;
  held_fields_.clear();
  if (on) hold_tables();
  memos_.reserve(16);  // memo_for's pointers stay valid for a few kinds of collects
}

void Evaluator::hold_tables() {
  for (int i = 0; i <= g_.dimension() && i < kMaxDim; ++i) held_links_[i] = g_.links(i).data();
  held_fields_.resize(fields_.size());
  for (size_t k = 0; k < fields_.size(); ++k) {
    if (!fields_[k]) continue;
    const Embedding<Vec3>& v = fields_[k]->values;
    held_fields_[k] = {v.slots().data(), v.slots().size(), v.values().data(), types_[k]};
  }
}

void Evaluator::share_orbit_numbers(DimMask mask, const uint32_t* numbers, const uint32_t* index) {
  for (auto& o : ids_)
    if (o.mask == mask) return;
  ids_.push_back({mask, {}, numbers, index});
}

void Evaluator::share_orbit_lists(DimMask mask, const uint32_t* list, const uint32_t* start,
                                  const uint32_t* numbers) {
  for (auto& o : lists_)
    if (o.mask == mask) return;
  lists_.push_back({mask, list, start, numbers});
}

// The <mo>-orbit of d from a shared list (share_orbit_lists) when d is the first dart of its
// listed orbit and the orbit is small: list_two_dims' result without the walk.
bool Evaluator::listed_orbit(DimMask mo, Dart d, std::vector<Dart>& in_orbit) const {
  for (const OrbitLists& o : lists_) {
    if (o.mask != mo) continue;
    const uint32_t id = o.numbers[d];
    const uint32_t* const first = o.list + o.start[id];
    const size_t n = o.start[id + 1] - o.start[id];
    if (first[0] != d || n > kSmallOrbit) return false;
    in_orbit.assign(first, first + n);
    return true;
  }
  return false;
}

const Evaluator::OrbitIds& Evaluator::orbit_ids(DimMask mask) {
  for (auto& o : ids_)
    if (o.mask == mask) return o;
  ids_.push_back({mask, {}});
  ids_.back().ids.reserve(g_.capacity());
  std::vector<uint32_t>& v = *ids_.back().ids;
  v.assign(g_.capacity(), kNone);
  uint32_t count = 0;
  visit_all_orbits(
      g_, mask, [&](Dart) { ++count; }, [&](Dart x) { v[x] = count - 1; });
  return ids_.back();
}

Evaluator::CollectMemo* Evaluator::memo_for(const Expr& call, const Expr& collect) {
  const DimMask mo = collect.orbit_mask;
  for (auto& m : memos_)
    if (m.function == call.function && m.orbit == mo && m.embedding == collect.embedding) return &m;
  memos_.push_back({call.function, mo, collect.embedding, {}, {}});
  CollectMemo& m = memos_.back();
  m.at.reserve(g_.capacity());
  m.at->assign(g_.capacity(), kNone);
  m.values.reserve(g_.capacity() /
                   2);  // at most one per two darts but for loops; pages touched on use
  return &memos_.back();
}

void Evaluator::fail(const Expr& e, const std::string& msg, Dart d) const {
  std::string loc = (where_ && !where_->empty() ? *where_ + ", " : std::string()) + "column " +
                    std::to_string(e.column);
  if (d != kNoDart) loc += ", dart " + std::to_string(d);
  throw Error(ErrorCode::Schema, msg, loc);
}

Val Evaluator::evaluate(const Expr& e, const Dart* node_darts, ValueType target,
                        const std::string& where) {
  nodes_ = node_darts;
  where_ = &where;
  vars_.clear();
  lets_.clear();
  for (auto& b : bodies_) b = {};
  return checked(eval(e), e, target);
}

Val Evaluator::evaluate(const Program& p, const Dart* node_darts, ValueType target,
                        const std::string& where) {
  nodes_ = node_darts;
  where_ = &where;
  vars_.clear();
  lets_.clear();
  if (stack_.size() < p.max_stack) stack_.resize(p.max_stack);
  top_ = 0;
  loads_ = p.loads.data();
  program_ = p.id;
  code_ = p.code.data();
  return checked(run(p.code.data(), p.code.data() + p.code.size()), *p.root, target);
}

// The mass of a point (1) or a vector (0), checked within 1e-9 and made exact.
inline Val Evaluator::checked(Val v, const Expr& e, ValueType target) const {
  if ((target == ValueType::Point && std::fabs(v.w - 1.0) > 1e-9) ||
      (target == ValueType::Vector && std::fabs(v.w) > 1e-9))
    fail_mass(e, v.w, target);
  if (target == ValueType::Point) v.w = 1.0;
  if (target == ValueType::Vector) v.w = 0.0;
  return v;
}

void Evaluator::fail_mass(const Expr& e, double mass, ValueType target) const {
  if (target == ValueType::Point)
    fail(e,
         "the point's weights sum to " + std::to_string(mass) +
             ", not 1 (an affine combination of points needs weights summing to 1)",
         nodes_ ? nodes_[0] : kNoDart);
  fail(e, "the vector's weights sum to " + std::to_string(mass) + ", not 0",
       nodes_ ? nodes_[0] : kNoDart);
}

Dart Evaluator::dart_of(const NodeRef& r, const Expr& e) {
  Dart d = r.is_variable ? vars_[r.index] : nodes_[r.index];
  if (d == kNoDart) fail(e, "node " + r.base + " has no dart");
  for (int dim : r.path) d = g_.alpha(dim, d);
  return d;
}

// dart_of in memo mode: the path followed on the held link arrays (hold_tables), inlined.
inline Dart Evaluator::held_dart_of(const NodeRef& r, const Expr& e) {
  Dart d = r.is_variable ? vars_[r.index] : nodes_[r.index];
  if (d == kNoDart) return dart_of(r, e);  // its error
  for (const int dim : r.path) d = held_links_[dim][d];
  return d;
}

// A node value resolved at compile time (program.hpp): field_value(dart_of(...)) without reading
// the tree; their errors on a missing dart or value.
inline Val Evaluator::load(const LoadRef& r) {
  Dart d = r.variable ? vars_[r.index] : nodes_[r.index];
  if (d == kNoDart) dart_of(r.expr->ref, *r.expr);
  if (memo_on_) {  // the tables held (hold_tables); the same reads without the map's and fields'
                   // indirections
    for (uint8_t k = 0; k < r.length; ++k) d = held_links_[r.path[k]][d];
    const HeldField& f = held_fields_[r.embedding];
    if (d < f.size) {
      const uint32_t slot = f.slots[d];
      if (slot != Embedding<Vec3>::kNoValue) {
        return from_storage(f.values[slot], f.type);
      }
    }
    return field_value(r.embedding, d, *r.expr);  // its error
  }
  return load_from_map(r, d);
}

// load outside memo mode: the path and the value read through the map and the field.
Val Evaluator::load_from_map(const LoadRef& r, Dart d) {
  for (uint8_t k = 0; k < r.length; ++k) d = g_.alpha(r.path[k], d);
  return value_at(r.embedding, d, *r.expr);
}

// field_value's fast path (inlined): its error when d has no value.
inline Val Evaluator::value_at(int embedding, Dart d, const Expr& e) {
  const EmbeddingField* f = fields_[static_cast<size_t>(embedding)];
  const uint32_t slot = f ? f->values.slot(d) : Embedding<Vec3>::kNoValue;
  if (slot == Embedding<Vec3>::kNoValue) field_value(embedding, d, e);
  return from_storage(f->values.value(slot), types_[static_cast<size_t>(embedding)]);
}

Val Evaluator::field_value(int embedding, Dart d, const Expr& e) {
  const EmbeddingField* f = fields_[static_cast<size_t>(embedding)];
  const EmbeddingSignature& s = sigs_[static_cast<size_t>(embedding)];
  const uint32_t slot = f ? f->values.slot(d) : Embedding<Vec3>::kNoValue;
  if (slot == Embedding<Vec3>::kNoValue) fail(e, "no '" + s.name + "' value on this dart", d);
  return from_storage(f->values.value(slot), s.type);
}

void Evaluator::members(const Expr& e, MemberSum& out) {
  const Dart d = memo_on_ ? held_dart_of(e.ref, e) : dart_of(e.ref, e);
  const DimMask mo = e.orbit_mask;
  const DimMask mc = e.class_mask;
  if (!e.word.empty()) {  // walk: d, d w, d w w, ... until d again
    Dart x = d;
    double k = 0;
    do {
      lets_.push_back({k, 0, 0, 0});
      vars_.push_back(x);
      out.push_back(body_value(e));
      vars_.pop_back();
      lets_.pop_back();
      for (int dim : e.word) x = g_.alpha(dim, x);
      k += 1;
      if (k > static_cast<double>(g_.capacity()))
        fail(e, "the walk does not come back to its dart", d);
    } while (x != d);
    return;
  }
  if (e.op == Expr::Op::Collect && (mo & ~mc) == 0) {  // <o>(d) lies in one pi-orbit
    out.push_back(field_value(e.embedding, d, e));
    return;
  }
  // Scratch lists per nesting depth (comprehension bodies may collect again).
  const size_t depth = vars_.size();
  if (depth >= kMaxNesting)
    fail(e, "comprehensions nested more than " + std::to_string(kMaxNesting) + " deep");
  std::vector<Dart>& in_orbit = scratch_[3 * depth];
  std::vector<Dart>& in_classes = scratch_[3 * depth + 1];
  std::vector<Dart>& stack = scratch_[3 * depth + 2];
  in_classes.clear();
  LastWalk& last = last_walk_[depth];
  if (memo_on_ && last.valid && last.mask == mo && last.dart == d &&
      in_orbit.size() <= kSmallOrbit) {
    // The same <o>-orbit from the same dart as the previous walk at this depth (Catmull-Clark's
    // vertex point walks one vertex three times): its darts, in order, are still in in_orbit.
    memo_members(e, mc, in_orbit, out);
    return;
  }
  in_orbit.clear();
  last.valid = false;
  if (memo_on_ && mo != 0 && (mo & (mo - 1)) == 0) {
    // An <i>-orbit: d and alpha_i(d), the order of the walk below, without a marker.
    const Dart y = g_.alpha(__builtin_ctz(mo), d);
    in_orbit.push_back(d);
    if (y != d && y < g_.capacity()) in_orbit.push_back(y);
    last = {mo, d, true};
    memo_members(e, mc, in_orbit, out);
    return;
  }
  if (memo_on_ && g_.kind() == MapKind::GMap && __builtin_popcount(mo) == 2 &&
      (listed_orbit(mo, d, in_orbit) || list_two_dims(mo, d, in_orbit))) {
    last = {mo, d, true};
    memo_members(e, mc, in_orbit, out);
    return;
  }
  in_orbit.clear();
  ScopedMarker mo_mark(g_);
  visit_orbit_marked(g_, mo, d, mo_mark.id(), stack, [&](Dart x) { in_orbit.push_back(x); });
  const size_t n = in_orbit.size();
  if (memo_on_ && n <= kSmallOrbit) {
    for (Dart x : in_orbit) mo_mark.unmark(x);
    mo_mark.set_clean();
    last = {mo, d, true};
    memo_members(e, mc, in_orbit, out);
    return;
  }
  ScopedMarker mc_mark(g_);
  if (e.op == Expr::Op::Collect && collect_by_slots(e, mc, mc_mark, out)) {
    for (Dart x : in_orbit) mo_mark.unmark(x);
    mo_mark.set_clean();
    mc_mark.set_clean();  // collect_by_slots unmarked what it marked
    return;
  }
  for (size_t k = 0; k < n; ++k) {
    const Dart x = in_orbit[k];
    if (mc_mark.test(x)) continue;
    out.push_back(member_value(e, x));
    // eval may have used deeper scratch lists, never this depth's.
    visit_orbit_marked(g_, mc, x, mc_mark.id(), stack, [&](Dart y) { in_classes.push_back(y); });
  }
  for (Dart x : in_orbit) mo_mark.unmark(x);
  for (Dart x : in_classes) mc_mark.unmark(x);
  mo_mark.set_clean();
  mc_mark.set_clean();
}

// Memo mode: the <a,b>-orbit of d (a < b) of a G-map, listed without a marker in the order of
// visit_orbit_marked. Under two involutions the orbit is a cycle or a path, and that depth-first
// walk goes from d along b, a, b, ... until it closes (alpha_a(d) comes last) or ends at a free
// dart, then from alpha_a(d) along b, a, ... to the other end. Returns false (in_orbit unspecified)
// on anything else — a dangling or non-involutive link, more than kSmallOrbit darts — and the
// caller walks with a marker.
bool Evaluator::list_two_dims(DimMask mo, Dart d, std::vector<Dart>& in_orbit) {
  const int a = __builtin_ctz(mo);
  const Dart* const la = g_.links(a).data();
  const Dart* const lb = g_.links(__builtin_ctz(mo & (mo - 1))).data();
  const Dart cap = g_.capacity();
  in_orbit.clear();
  in_orbit.push_back(d);
  // One side: from `from` (d, or alpha_a(d) already listed) along `l` then the other link.
  auto side = [&](Dart from, const Dart* l,
                  const Dart* other) -> int {  // 1 closed, 0 free end, -1 irregular
    for (Dart x = from;;) {
      const Dart y = l[x];
      if (y >= cap || l[y] != x) return -1;
      if (y == x) return 0;
      if (y == d) return 1;
      if (in_orbit.size() == kSmallOrbit) return -1;
      in_orbit.push_back(y);
      x = y;
      std::swap(l, other);
    }
  };
  const int first = side(d, lb, la);
  if (first != 0) return first == 1;
  const Dart y = la[d];
  if (y >= cap || la[y] != d) return false;
  if (y == d) return true;
  if (in_orbit.size() == kSmallOrbit) return false;
  in_orbit.push_back(y);
  return side(y, lb, la) == 0;  // a path cannot come back to d
}

// The value one member contributes: the embedding's value at x for a collect, the body evaluated
// with x bound for a comprehension.
__attribute__((always_inline)) inline Val Evaluator::member_value(const Expr& e, Dart x) {
  if (e.op == Expr::Op::Collect) return value_at(e.embedding, x, e);
  vars_.push_back(x);
  Val v = body_value(e);
  vars_.pop_back();
  return v;
}

// The body of a comprehension or a walk, its variable bound (the last of vars_): its compiled
// program when the enumeration was started by one (bodies_ at the enclosing depth), else the tree.
Val Evaluator::body_value(const Expr& e) {
  const Body& b = bodies_[vars_.size() - 1];
  if (b.begin) return run(b.begin, b.end);
  return eval(*e.args[0]);
}

// Memo mode, the <o>-orbit in in_orbit (this depth's walk, last_walk_): one member per <c>-orbit
// met, at its first dart, the <c>-orbits told apart by their numbers (orbit_ids) instead of
// marking each one met. The first darts are kept with the walk: a second comprehension over the
// same walk and <c> (Loop's count and middle around a vertex) reuses them. A constant body (count's
// [0 | ...]) is not evaluated per member.
void Evaluator::memo_members(const Expr& e, DimMask mc, const std::vector<Dart>& in_orbit,
                             MemberSum& out) {
  const size_t depth = vars_.size();
  LastWalk& last = last_walk_[depth];
  const int kept = last.members[0] == mc ? 0 : last.members[1] == mc ? 1 : -1;
  const int slot = kept >= 0 ? kept : last.replace;
  std::vector<Dart>& firsts = member_darts_[depth][slot];
  if (kept < 0) {
    const OrbitIds& o = orbit_ids(mc);  // copied out: member_value may add entries to ids_
    const uint32_t* const ids = o.numbers ? o.numbers : o.ids->data();
    const uint32_t* const index = o.index;
    uint32_t met[kSmallOrbit];
    size_t count = 0;
    firsts.clear();
    for (const Dart x : in_orbit) {
      const uint32_t id = ids[index ? index[x] : x];
      // Searched from the last met: a walk meets a member's darts one after the other.
      size_t k = count;
      while (k > 0 && met[k - 1] != id) --k;
      if (k > 0) continue;
      met[count++] = id;
      firsts.push_back(x);
    }
    last.members[slot] = mc;
    last.replace = 1 - slot;
  }
  if (e.op == Expr::Op::Comprehension) {
    const Body& b = bodies_[depth];
    const bool constant = b.begin
                              ? (b.end - b.begin == 1 && b.begin->op == Instruction::Op::Constant)
                              : e.args[0]->op == Expr::Op::Number;
    if (constant) {
      const Val v =
          b.begin ? Val{b.begin->value[0], b.begin->value[1], b.begin->value[2], b.begin->value[3]}
                  : Val{e.args[0]->number, 0, 0, 0};
      for (size_t k = 0; k < firsts.size(); ++k)
        out.push_back(v);  // the sum in member order, as the body's
      return;
    }
  }
  if (e.op == Expr::Op::Comprehension && bodies_[depth].begin &&
      bodies_[depth].end - bodies_[depth].begin == 1 &&
      body_of_one_instruction(*bodies_[depth].begin, firsts, out))
    return;
  for (const Dart x : firsts) out.push_back(member_value(e, x));
}

// Memo mode, a comprehension whose compiled body is one instruction that needs no program run per
// member: a node value (Loop's [e@0.position | e in ...]), or the memoised barycentre of a collect
// from the member (Catmull-Clark's [middle(<0,1>_position(f)) | f in ...]) read from its memo
// table, the member's value computed (and the table filled) the usual way when it is not there yet.
// The values are member_value's. Returns false for any other body.
bool Evaluator::body_of_one_instruction(const Instruction& body, const std::vector<Dart>& firsts,
                                        MemberSum& out) {
  const size_t depth = vars_.size();
  if (body.op == Instruction::Op::Load) {
    const LoadRef& l = loads_[body.index];
    vars_.push_back(kNoDart);
    for (const Dart x : firsts) {
      vars_.back() = x;
      out.push_back(load(l));
    }
    vars_.pop_back();
    return true;
  }
  if (body.op != Instruction::Op::AggregateSet || body.index != 0) return false;
  const Expr& call = *body.expr;
  const Expr& arg = *call.args[0];
  // The memo condition of aggregate(), on a collect from this comprehension's variable.
  if (arg.op != Expr::Op::Collect || !arg.word.empty() || (arg.orbit_mask & ~arg.class_mask) == 0 ||
      !arg.ref.is_variable || arg.ref.index != depth)
    return false;
  // The table is found once for the comprehension: a missing value is computed by aggregate_into
  // on this table (a collect's members run no program, so no memo is added meanwhile).
  CollectMemo* const cm = memo_for(call, arg);
  const uint32_t* const at = cm->at->data();
  vars_.push_back(kNoDart);
  for (const Dart x : firsts) {
    Dart d = x;
    for (const int dim : arg.ref.path) d = g_.alpha(dim, d);
    vars_.back() = x;
    out.push_back(at[d] != kNone ? (*cm->values)[at[d]]
                                 : aggregate_into(call, cm, nullptr, nullptr));
  }
  vars_.pop_back();
  return true;
}

// The <o ∩ o_pi>-pieces of the orbit in in_orbit (scratch depth vars_.size()) each lie in one
// pi-orbit. When they hold pairwise different value slots, they are pairwise different pi-orbits
// (every pi-orbit holds one slot, see the header) and the collect is their values, in order;
// otherwise (two pieces share a slot) returns false and the caller marks whole pi-orbits.
bool Evaluator::collect_by_slots(const Expr& e, DimMask mc, const ScopedMarker& mark,
                                 MemberSum& out) {
  const size_t depth = vars_.size();
  const std::vector<Dart>& in_orbit = scratch_[3 * depth];
  std::vector<Dart>& pieces = scratch_[3 * depth + 1];
  std::vector<Dart>& stack = scratch_[3 * depth + 2];
  const EmbeddingField* f = fields_[static_cast<size_t>(e.embedding)];
  if (!f) return false;
  const DimMask inter = e.orbit_mask & mc;
  pieces.clear();
  slots_.clear();
  size_t marked = 0;
  for (Dart x : in_orbit) {
    if (mark.test(x)) continue;
    slots_.push_back(f->values.slot(x));
    pieces.push_back(x);
    if (inter == 0) {
      mark.mark(x);
      ++marked;
    } else {
      marked += visit_orbit_marked(g_, inter, x, mark.id(), stack, [](Dart) {});
    }
  }
  for (Dart x : in_orbit) mark.unmark(x);  // every marked dart is in the <o>-orbit
  (void)marked;
  if (has_duplicate(slots_, sorted_)) {
    pieces.clear();
    return false;
  }
  for (Dart x : pieces) out.push_back(field_value(e.embedding, x, e));
  return true;
}

Val Evaluator::eval(const Expr& e) {
  switch (e.op) {
    case Expr::Op::Number:
      return {e.number, 0, 0, 0};
    case Expr::Op::Constant:
      if (e.let_index >= 0) return lets_[static_cast<size_t>(e.let_index)];
      return {M_PI, 0, 0, 0};
    case Expr::Op::Let: {
      lets_.push_back(eval(*e.args[0]));
      const Val v = eval(*e.args[1]);
      lets_.pop_back();
      return v;
    }
    case Expr::Op::Value:
      return field_value(e.embedding, dart_of(e.ref, e), e);
    case Expr::Op::Collect:
    case Expr::Op::Comprehension:
      fail(e, "a multiset is not a value");
    case Expr::Op::Neg:
      return scale(eval(*e.args[0]), -1.0);
    // Operands evaluated left to right (the order of the errors and of the memo tables' first
    // fills; function arguments would leave it to the compiler).
    case Expr::Op::Add: {
      const Val a = eval(*e.args[0]), b = eval(*e.args[1]);
      return add(a, b);
    }
    case Expr::Op::Sub: {
      const Val a = eval(*e.args[0]), b = eval(*e.args[1]);
      return sub(a, b);
    }
    case Expr::Op::Mul: {
      const Val a = eval(*e.args[0]), b = eval(*e.args[1]);
      if (e.args[0]->type.kind == K::Scalar) return scale(b, a.x);
      return scale(a, b.x);
    }
    case Expr::Op::Div: {
      const Val a = eval(*e.args[0]), b = eval(*e.args[1]);
      if (b.x == 0.0) fail(e, "division by zero", nodes_ ? nodes_[0] : kNoDart);
      return scale(a, 1.0 / b.x);
    }
    case Expr::Op::Call:
      break;
  }
  switch (e.function) {
    case Function::Point:
    case Function::Vector:
    case Function::Colour: {
      const Val x = eval(*e.args[0]), y = eval(*e.args[1]), z = eval(*e.args[2]);
      return {x.x, y.x, z.x, e.function == Function::Point ? 1.0 : 0.0};
    }
    case Function::Middle:
    case Function::Sum:
    case Function::Count: {
      if (e.args.size() == 1 && e.args[0]->type.kind == K::Multiset)
        return aggregate(e, nullptr, nullptr);
      Val acc;
      for (const auto& a : e.args) acc = add(acc, eval(*a));
      if (e.function == Function::Middle && e.args.empty())
        fail(e, "the barycentre of an empty multiset", nodes_ ? nodes_[0] : kNoDart);
      return ops::finish_aggregate(e.function, acc, e.args.size());
    }
    case Function::Cos:
      return {std::cos(eval(*e.args[0]).x), 0, 0, 0};
    case Function::Sin:
      return {std::sin(eval(*e.args[0]).x), 0, 0, 0};
    case Function::Abs:
      return {std::fabs(eval(*e.args[0]).x), 0, 0, 0};
    case Function::Sqrt: {
      const double x = eval(*e.args[0]).x;
      if (x < 0) fail(e, "square root of a negative number", nodes_ ? nodes_[0] : kNoDart);
      return {std::sqrt(x), 0, 0, 0};
    }
    case Function::Dot: {
      const Val a = eval(*e.args[0]), b = eval(*e.args[1]);
      return {a.x * b.x + a.y * b.y + a.z * b.z, 0, 0, 0};
    }
    case Function::Cross: {
      const Val a = eval(*e.args[0]), b = eval(*e.args[1]);
      return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x, 0};
    }
    case Function::Norm: {
      const Val a = eval(*e.args[0]);
      return {std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z), 0, 0, 0};
    }
    case Function::Clamp: {
      const Val a = eval(*e.args[0]);
      auto c = [](double v) { return v < 0 ? 0.0 : v > 1 ? 1.0 : v; };
      return {c(a.x), c(a.y), c(a.z), 0};
    }
    case Function::None:
      break;
  }
  fail(e, "unknown function " + e.name);
}

// middle, sum or count of the multiset call.args[0], its members' values computed by the body's
// program [body, body_end) when given, else by the tree.
Val Evaluator::aggregate(const Expr& e, const Instruction* body, const Instruction* body_end) {
  const Expr& arg = *e.args[0];
  // A memoised collect (memoise_collects): its value is the one of its <o>-orbit.
  const bool memo = memo_on_ && arg.op == Expr::Op::Collect && arg.word.empty() &&
                    (arg.orbit_mask & ~arg.class_mask) != 0;
  CollectMemo* cm = memo ? memo_for(e, arg) : nullptr;
  if (cm) {
    const Dart d = held_dart_of(arg.ref, arg);  // cm: memo mode
    if ((*cm->at)[d] != kNone) return (*cm->values)[(*cm->at)[d]];
  }
  return aggregate_into(e, cm, body, body_end);
}

// aggregate's value computed from the members; kept in the memo table cm when given (the
// collect's <o>-orbit has no value there yet).
__attribute__((always_inline)) inline Val Evaluator::aggregate_into(const Expr& e, CollectMemo* cm,
                                                                    const Instruction* body,
                                                                    const Instruction* body_end) {
  const Expr& arg = *e.args[0];
  const size_t depth = vars_.size();
  MemberSum m;
  bodies_[depth] = {body, body_end};
  members(arg, m);
  const Val acc = m.sum;
  const size_t n = m.n;
  if (e.function == Function::Middle && n == 0)
    fail(e, "the barycentre of an empty multiset", nodes_ ? nodes_[0] : kNoDart);
  const Val r = ops::finish_aggregate(e.function, acc, n);
  if (cm) {
    // members() left the darts of the <o>-orbit in this depth's first scratch list.
    const auto idx = static_cast<uint32_t>(cm->values->size());
    cm->values->push_back(r);
    for (Dart x : scratch_[3 * depth]) (*cm->at)[x] = idx;
  }
  return r;
}

const Val* Evaluator::Kept::find(const Val* lets, size_t n, size_t stride) const {
  for (size_t k = 0; k < used; ++k) {
    const size_t i = k == 0 ? last : (k == last ? 0 : k);  // the last one found first
    const Entry& e = entries[i];
    bool same = e.lets == n;
    for (size_t q = 0; same && q < n; ++q)
      same = std::memcmp(&e.key[q], &lets[q * stride], sizeof(Val)) == 0;
    if (same) {
      last = i;
      return &e.value;
    }
  }
  return nullptr;
}

void Evaluator::Kept::keep(const Val* lets, size_t n, const Val& value) {
  Entry& e = entries[next];
  used = std::max(used, next + 1);
  next = (next + 1) % kKeptEntries;
  e.lets = n;
  std::copy(lets, lets + n, e.key);
  e.value = value;
}

Evaluator::Kept* Evaluator::kept_for(const Instruction* at) {
  const auto offset = static_cast<size_t>(at - code_);
  for (Kept& k : kept_)
    if (k.at == offset && k.program == program_) return &k;
  return nullptr;
}

// A compiled program (program.hpp) on the value stack from top_: the tree's evaluation order,
// operations and errors, without the recursion over the tree.
Val Evaluator::run(const Instruction* pc, const Instruction* end) {
  using Op = Instruction::Op;
  const size_t base = top_;
  Val* sp = stack_.data() + base;
  for (; pc != end; ++pc) {
    const Expr& e = *pc->expr;
    switch (pc->op) {
      case Op::Constant:
        *sp++ = {pc->value[0], pc->value[1], pc->value[2], pc->value[3]};
        break;
      case Op::LetGet:
        *sp++ = lets_[pc->index];
        break;
      case Op::LetBind:
        lets_.push_back(*--sp);
        break;
      case Op::LetDrop:
        lets_.pop_back();
        break;
      case Op::Value: {
        // field_value(dart_of(...)) inlined; their errors on a missing dart or value.
        Dart d = e.ref.is_variable ? vars_[e.ref.index] : nodes_[e.ref.index];
        if (d == kNoDart) d = dart_of(e.ref, e);
        for (const int dim : e.ref.path) d = g_.alpha(dim, d);
        const EmbeddingField* f = fields_[static_cast<size_t>(e.embedding)];
        const uint32_t slot = f ? f->values.slot(d) : Embedding<Vec3>::kNoValue;
        if (slot == Embedding<Vec3>::kNoValue) field_value(e.embedding, d, e);
        *sp++ = from_storage(f->values.value(slot), sigs_[static_cast<size_t>(e.embedding)].type);
        break;
      }
      case Op::Load:
        *sp++ = load(loads_[pc->index]);
        break;
      case Op::Combine:
      case Op::CombineLoads: {
        Val acc = pc->op == Op::Combine
                      ? Val{pc->value[0], pc->value[1], pc->value[2], pc->value[3]}
                      : sp[-1];
        const LoadRef* l = loads_ + pc->index;
        for (uint32_t k = 0; k < pc->count; ++k) acc = add(acc, scale(load(l[k]), l[k].weight));
        if (pc->op == Op::Combine) ++sp;
        sp[-1] = acc;
        break;
      }
      case Op::Accumulate:
        --sp;
        sp[-1] = add(sp[-1], scale(sp[0], pc->value[0]));
        break;
      case Op::Neg:
        sp[-1] = ops::neg(sp[-1]);
        break;
      case Op::Add:
        --sp;
        sp[-1] = add(sp[-1], sp[0]);
        break;
      case Op::Sub:
        --sp;
        sp[-1] = sub(sp[-1], sp[0]);
        break;
      case Op::ScaleLeft:
        --sp;
        sp[-1] = scale(sp[0], sp[-1].x);
        break;
      case Op::ScaleRight:
        --sp;
        sp[-1] = scale(sp[-1], sp[0].x);
        break;
      case Op::Div:
        --sp;
        if (sp[0].x == 0.0) fail(e, "division by zero", nodes_ ? nodes_[0] : kNoDart);
        sp[-1] = ops::divide(sp[-1], sp[0].x);
        break;
      case Op::Make:
        sp -= 2;
        sp[-1] = ops::make(e.function, sp[-1], sp[0], sp[1]);
        break;
      case Op::Cos:
        sp[-1] = ops::cos(sp[-1]);
        break;
      case Op::Sin:
        sp[-1] = ops::sin(sp[-1]);
        break;
      case Op::Abs:
        sp[-1] = ops::abs(sp[-1]);
        break;
      case Op::Sqrt:
        if (sp[-1].x < 0) fail(e, "square root of a negative number", nodes_ ? nodes_[0] : kNoDart);
        sp[-1] = ops::sqrt(sp[-1]);
        break;
      case Op::Norm:
        sp[-1] = ops::norm(sp[-1]);
        break;
      case Op::Clamp:
        sp[-1] = ops::clamp(sp[-1]);
        break;
      case Op::Dot:
        --sp;
        sp[-1] = ops::dot(sp[-1], sp[0]);
        break;
      case Op::Cross:
        --sp;
        sp[-1] = ops::cross(sp[-1], sp[0]);
        break;
      case Op::AggregateArgs: {
        const size_t n = pc->index;
        Val acc;
        const Val* args = sp - n;
        for (size_t k = 0; k < n; ++k) acc = add(acc, args[k]);
        if (e.function == Function::Middle && n == 0)
          fail(e, "the barycentre of an empty multiset", nodes_ ? nodes_[0] : kNoDart);
        sp -= n;
        *sp++ = ops::finish_aggregate(e.function, acc, n);
        break;
      }
      case Op::AggregateSet: {
        top_ = static_cast<size_t>(sp - stack_.data());  // a body runs above the current values
        const Instruction* body = pc + 1;
        const Val v = aggregate(e, body, body + pc->index);
        top_ = base;
        *sp++ = v;
        pc += pc->index;
        break;
      }
      case Op::Pure: {
        const size_t n = lets_.size();
        const Kept* k = kept_for(pc);
        if (const Val* v = k ? k->find(lets_.data(), n, 1) : nullptr) {
          *sp++ = *v;
          pc += pc->index + 1;  // past the code and its PureEnd
        }
        break;
      }
      case Op::PureEnd: {
        ++pure_runs_;
        const size_t n = lets_.size();
        if (n > kKeptLets) break;
        const Instruction* at = pc - pc->index - 1;
        Kept* k = kept_for(at);
        if (!k) {
          kept_.push_back({});
          k = &kept_.back();
          k->program = program_;
          k->at = static_cast<size_t>(at - code_);
        }
        k->keep(lets_.data(), n, sp[-1]);
        break;
      }
      case Op::Unknown:
        fail(e, "unknown function " + e.name);
    }
  }
  return sp[-1];
}

}  // namespace gmr::expr
