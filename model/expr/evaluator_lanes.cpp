// Evaluator::run_classes (evaluator.hpp): a compiled program (program.hpp) evaluated for kLanes
// classes at a time, instruction by instruction: each instruction does, lane after lane, what run
// does for one class, so the dispatch and the set-up are paid once per instruction and batch
// instead of once per class (Loop's vertex mask: ~2,000 instructions per class through run).
//
// The values are run's bit for bit: every lane performs run's floating-point operations in run's
// order. A comprehension over a listed orbit of the hook (share_orbit_lists) whose body is a
// constant or a node value of its variable (Loop's count and middle around a vertex) takes its
// members as memo_members does: the listed orbit in order, one member per <c>-orbit met (told
// apart by the shared numbers), at its first dart, summed in that order; the members are found
// once per batch for the comprehensions of the same orbit, classes and start. Any other aggregate,
// and a dart-free sub-expression none of whose kept results matches the lane's let values (Pure),
// is computed for that lane by run's own code (aggregate, run). A batch in which anything fails (a
// missing dart or value, a division by zero, an empty barycentre, a wrong mass) appends nothing:
// the caller evaluates its classes one by one, and the failing one reports run's error.
#include <cmath>
#include <cstring>

#include "model/core/error.hpp"
#include "model/expr/evaluator.hpp"

namespace gmr::expr {

namespace {

using Op = Instruction::Op;

// A node value of the program (not of a comprehension variable): the left node 0, the hook.
bool reads_hook(const LoadRef& r) { return !r.variable && r.index == 0; }

}  // namespace

// The program's own instructions (not those of aggregate bodies and dart-free sub-expressions,
// which run for one lane at a time) are all of run's except Value and Unknown, read the hook only,
// and bind at most kLaneLets let variables.
bool Evaluator::runs_in_lanes(const Program& p) {
  size_t lets = 0;
  for (size_t i = 0; i < p.code.size(); ++i) {
    const Instruction& ins = p.code[i];
    switch (ins.op) {
      case Op::Value:
      case Op::Unknown:
      case Op::PureEnd:
        return false;
      case Op::LetBind:
        if (++lets > kLaneLets) return false;
        break;
      case Op::LetDrop:
        --lets;
        break;
      case Op::Load:
        if (!reads_hook(p.loads[ins.index])) return false;
        break;
      case Op::Combine:
      case Op::CombineLoads:
        for (uint32_t k = 0; k < ins.count; ++k)
          if (!reads_hook(p.loads[ins.index + k])) return false;
        break;
      case Op::AggregateSet:
        i += ins.index;
        break;
      case Op::Pure:
        i += ins.index + 1;
        break;
      default:
        break;
    }
  }
  return !p.code.empty();
}

size_t Evaluator::run_classes(const Program& p, const Dart* nodes, size_t n, ValueType target,
                              std::vector<Vec3>& out) {
  if (!memo_on_ || !runs_in_lanes(p)) return 0;
  where_ = nullptr;
  loads_ = p.loads.data();
  program_ = p.id;
  code_ = p.code.data();
  if (stack_.size() < p.max_stack) stack_.resize(p.max_stack);
  lane_stack_.resize(p.max_stack * kLanes);
  lane_lets_.resize(kLaneLets * kLanes);
  for (LaneMembers& lm : lane_members_) lm.darts.resize(kLanes * kSmallOrbit);
  for (size_t j = 0; j < n; j += kLanes) {
    const size_t m = std::min(kLanes, n - j);
    try {
      if (!run_lanes(p, nodes + j, m, target, out)) return j;
    } catch (const Error&) {
      return j;
    }
  }
  return n;
}

// load() on a given dart: false where load() fails.
inline bool Evaluator::lane_load(const LoadRef& r, Dart d, Val& v) const {
  if (d == kNoDart) return false;
  for (uint8_t k = 0; k < r.length; ++k) d = held_links_[r.path[k]][d];
  const HeldField& f = held_fields_[r.embedding];
  if (d >= f.size || f.slots[d] == Embedding<Vec3>::kNoValue) return false;
  v = from_storage(f.values[f.slots[d]], f.type);
  return true;
}

// The members of `comprehension` (from the hook) at each lane: memo_members' first darts. fast is
// false when a lane's orbit is not a listed one starting at its dart (the lanes then aggregate one
// by one).
const Evaluator::LaneMembers& Evaluator::lane_members(const Expr& comprehension, const Dart* nodes,
                                                      size_t m) {
  const Expr& e = comprehension;
  for (const LaneMembers& lm : lane_members_) {
    const Expr* o = lm.comprehension;
    if (o && o->orbit_mask == e.orbit_mask && o->class_mask == e.class_mask &&
        o->ref.is_variable == e.ref.is_variable && o->ref.index == e.ref.index &&
        o->ref.path == e.ref.path)
      return lm;
  }
  LaneMembers& lm = lane_members_[lane_members_next_];
  lane_members_next_ = 1 - lane_members_next_;
  lm.comprehension = &e;
  lm.fast = false;
  size_t listed_darts = 0;
  if (!e.word.empty() || e.ref.is_variable || e.ref.index != 0 || g_.kind() != MapKind::GMap ||
      __builtin_popcount(e.orbit_mask) != 2)
    return lm;
  const OrbitLists* listed = nullptr;  // listed_orbit's list, read in place
  for (const OrbitLists& l : lists_)
    if (l.mask == e.orbit_mask) {
      listed = &l;
      break;
    }
  if (!listed) return lm;
  const OrbitIds& o = orbit_ids(e.class_mask);
  const uint32_t* const ids = o.numbers ? o.numbers : o.ids->data();
  const uint32_t* const index = o.index;
  for (size_t j = 0; j < m; ++j) {
    lm.start[j] = static_cast<uint32_t>(listed_darts);
    Dart d = nodes[j];
    if (d == kNoDart) return lm;
    for (const int dim : e.ref.path) d = held_links_[dim][d];
    const uint32_t orbit = listed->numbers[d];
    const uint32_t* const in_orbit = listed->list + listed->start[orbit];
    const size_t n = listed->start[orbit + 1] - listed->start[orbit];
    if (in_orbit[0] != d || n > kSmallOrbit) return lm;  // as listed_orbit: d must start its list
    uint32_t met[kSmallOrbit];
    size_t count = 0;
    for (size_t i = 0; i < n; ++i) {
      const Dart x = in_orbit[i];
      const uint32_t id = ids[index ? index[x] : x];
      size_t k = count;
      while (k > 0 && met[k - 1] != id) --k;
      if (k > 0) continue;
      met[count++] = id;
      lm.darts[listed_darts++] = x;  // sized for kLanes orbits of kSmallOrbit darts (run_classes)
    }
  }
  lm.start[m] = static_cast<uint32_t>(listed_darts);
  lm.fast = true;
  return lm;
}

// One lane's value by run's own code: the aggregate at pc (aggregate) or the code [pc, end) (run),
// with the lane's node dart and let values.
Val Evaluator::lane_scalar(const Instruction* pc, const Instruction* end, const Dart* node,
                           size_t lets, size_t lane, bool aggregate_at_pc) {
  nodes_ = node;
  vars_.clear();
  lets_.clear();
  for (size_t q = 0; q < lets; ++q) lets_.push_back(lane_lets_[q * kLanes + lane]);
  top_ = 0;
  if (aggregate_at_pc) return aggregate(*pc->expr, pc + 1, pc + 1 + pc->index);
  return run(pc, end);
}

// The program at the m classes of nodes[0..m): true and their values appended, or false (nothing
// appended) when one of them fails.
bool Evaluator::run_lanes(const Program& p, const Dart* nodes, size_t m, ValueType target,
                          std::vector<Vec3>& out) {
  Val* const stack = lane_stack_.data();
  Val* const lets = lane_lets_.data();
  auto row = [&](size_t r) { return stack + r * kLanes; };
  size_t sp = 0, nl = 0;  // rows on the stack, let variables bound
  for (LaneMembers& lm : lane_members_) lm.comprehension = nullptr;
  const Instruction* const end = p.code.data() + p.code.size();
  for (const Instruction* pc = p.code.data(); pc != end; ++pc) {
    const Expr& e = *pc->expr;
    Val* const top = row(sp);  // the next row
    Val* const a = sp >= 2 ? row(sp - 2) : nullptr;
    Val* const b = sp >= 1 ? row(sp - 1) : nullptr;
    // An operation of one value (the top one, replaced) or of two (the two top ones, replaced by
    // the result), lane after lane.
    auto unary = [&](auto f) {
      for (size_t j = 0; j < m; ++j) b[j] = f(b[j]);
    };
    auto binary = [&](auto f) {
      for (size_t j = 0; j < m; ++j) a[j] = f(a[j], b[j]);
      --sp;
    };
    switch (pc->op) {
      case Op::Constant: {
        const Val c{pc->value[0], pc->value[1], pc->value[2], pc->value[3]};
        for (size_t j = 0; j < m; ++j) top[j] = c;
        ++sp;
        break;
      }
      case Op::LetGet:
        std::memcpy(top, lets + pc->index * kLanes, m * sizeof(Val));
        ++sp;
        break;
      case Op::LetBind:
        std::memcpy(lets + nl++ * kLanes, b, m * sizeof(Val));
        --sp;
        break;
      case Op::LetDrop:
        --nl;
        break;
      case Op::Load: {
        const LoadRef& r = loads_[pc->index];
        for (size_t j = 0; j < m; ++j)
          if (!lane_load(r, nodes[j], top[j])) return false;
        ++sp;
        break;
      }
      case Op::Combine:
      case Op::CombineLoads: {
        const LoadRef* l = loads_ + pc->index;
        Val* const to = pc->op == Op::Combine ? top : b;
        for (size_t j = 0; j < m; ++j) {
          Val acc = pc->op == Op::Combine
                        ? Val{pc->value[0], pc->value[1], pc->value[2], pc->value[3]}
                        : b[j];
          for (uint32_t k = 0; k < pc->count; ++k) {
            Val v;
            if (!lane_load(l[k], nodes[j], v)) return false;
            acc = ops::add(acc, ops::scale(v, l[k].weight));
          }
          to[j] = acc;
        }
        if (pc->op == Op::Combine) ++sp;
        break;
      }
      case Op::Accumulate: {
        const double w = pc->value[0];
        binary([w](const Val& x, const Val& y) { return ops::add(x, ops::scale(y, w)); });
        break;
      }
      case Op::Neg:
        unary([](const Val& x) { return ops::neg(x); });
        break;
      case Op::Add:
        binary([](const Val& x, const Val& y) { return ops::add(x, y); });
        break;
      case Op::Sub:
        binary([](const Val& x, const Val& y) { return ops::sub(x, y); });
        break;
      case Op::ScaleLeft:
        binary([](const Val& x, const Val& y) { return ops::scale(y, x.x); });
        break;
      case Op::ScaleRight:
        binary([](const Val& x, const Val& y) { return ops::scale(x, y.x); });
        break;
      case Op::Div:
        for (size_t j = 0; j < m; ++j) {
          if (b[j].x == 0.0) return false;
          a[j] = ops::divide(a[j], b[j].x);
        }
        --sp;
        break;
      case Op::Make: {
        Val* const x = row(sp - 3);
        for (size_t j = 0; j < m; ++j) x[j] = ops::make(e.function, x[j], a[j], b[j]);
        sp -= 2;
        break;
      }
      case Op::Cos:
        unary([](const Val& x) { return ops::cos(x); });
        break;
      case Op::Sin:
        unary([](const Val& x) { return ops::sin(x); });
        break;
      case Op::Abs:
        unary([](const Val& x) { return ops::abs(x); });
        break;
      case Op::Sqrt:
        for (size_t j = 0; j < m; ++j) {
          if (b[j].x < 0) return false;
          b[j] = ops::sqrt(b[j]);
        }
        break;
      case Op::Norm:
        unary([](const Val& x) { return ops::norm(x); });
        break;
      case Op::Clamp:
        unary([](const Val& x) { return ops::clamp(x); });
        break;
      case Op::Dot:
        binary([](const Val& x, const Val& y) { return ops::dot(x, y); });
        break;
      case Op::Cross:
        binary([](const Val& x, const Val& y) { return ops::cross(x, y); });
        break;
      case Op::AggregateArgs: {
        const size_t n = pc->index;
        if (e.function == Function::Middle && n == 0) return false;
        Val* const first = row(sp - n);
        for (size_t j = 0; j < m; ++j) {
          Val acc;
          for (size_t k = 0; k < n; ++k) acc = ops::add(acc, first[k * kLanes + j]);
          first[j] = ops::finish_aggregate(e.function, acc, n);
        }
        sp = sp - n + 1;
        break;
      }
      case Op::AggregateSet: {
        const Expr& arg = *e.args[0];
        const Instruction* const body = pc + 1;
        const bool one_instruction_body =
            arg.op == Expr::Op::Comprehension && pc->index == 1 &&
            (body->op == Op::Constant || (body->op == Op::Load && loads_[body->index].variable &&
                                          loads_[body->index].index == 0));
        const LaneMembers* lm = one_instruction_body ? &lane_members(arg, nodes, m) : nullptr;
        if (lm && lm->fast && body->op == Op::Constant) {
          const Val c{body->value[0], body->value[1], body->value[2], body->value[3]};
          for (size_t j = 0; j < m; ++j) {
            MemberSum s;
            for (uint32_t k = lm->start[j]; k < lm->start[j + 1]; ++k) s.push_back(c);
            if (e.function == Function::Middle && s.n == 0) return false;
            top[j] = ops::finish_aggregate(e.function, s.sum, s.n);
          }
        } else if (lm && lm->fast) {
          // lane_load with what it reads taken once: the held link arrays of the path, the field.
          const LoadRef& r = loads_[body->index];
          const Dart* step[LoadRef::kMaxPath];
          for (uint8_t q = 0; q < r.length; ++q) step[q] = held_links_[r.path[q]];
          const HeldField& f = held_fields_[r.embedding];
          const Dart* const darts = lm->darts.data();
          for (size_t j = 0; j < m; ++j) {
            MemberSum s;
            for (uint32_t k = lm->start[j]; k < lm->start[j + 1]; ++k) {
              Dart d = darts[k];
              for (uint8_t q = 0; q < r.length; ++q) d = step[q][d];
              if (d >= f.size || f.slots[d] == Embedding<Vec3>::kNoValue) return false;
              s.push_back(from_storage(f.values[f.slots[d]], f.type));
            }
            if (e.function == Function::Middle && s.n == 0) return false;
            top[j] = ops::finish_aggregate(e.function, s.sum, s.n);
          }
        } else {
          for (size_t j = 0; j < m; ++j) top[j] = lane_scalar(pc, nullptr, nodes + j, nl, j, true);
        }
        ++sp;
        pc += pc->index;
        break;
      }
      case Op::Pure: {
        const Instruction* const code_end = pc + pc->index + 2;  // past its PureEnd
        for (size_t j = 0; j < m; ++j) {
          const Kept* k = kept_for(pc);
          const Val* kept = k ? k->find(lets + j, nl, kLanes) : nullptr;
          top[j] = kept ? *kept : lane_scalar(pc, code_end, nodes + j, nl, j, false);
        }
        ++sp;
        pc = code_end - 1;
        break;
      }
      default:
        return false;  // runs_in_lanes excludes the others
    }
  }
  const Val* const v = row(sp - 1);
  for (size_t j = 0; j < m; ++j)
    if ((target == ValueType::Point && std::fabs(v[j].w - 1.0) > 1e-9) ||
        (target == ValueType::Vector && std::fabs(v[j].w) > 1e-9))
      return false;
  for (size_t j = 0; j < m; ++j) out.push_back(to_storage(v[j]));
  return true;
}

}  // namespace gmr::expr
