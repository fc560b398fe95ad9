// Evaluation of type-checked embedding expressions on a map (thesis §5.5, Algorithm 4 for the
// orbits): the identifier terms read the map as it is (the object before the rewrite), node n
// standing for the dart `node_darts[n]`.
//
// Values are homogeneous: (x, y, z, w) with w the mass of an affine value (1 for a point, 0 for a
// vector; type.hpp); a scalar is x, a colour (x, y, z). A collect or a comprehension visits the
// <o>-orbit of its dart depth-first (Algorithm 4 with markers) and keeps one value per <c>-orbit
// met (c = o_pi for a collect: one value per pi-orbit, not per dart — thesis §5.5.2), marking each
// <c>-orbit whole. A collect first tries a cheaper exact way: the <o ∩ o_pi>-pieces of the
// <o>-orbit each lie in one pi-orbit, and when their value slots are pairwise different they are
// different pi-orbits — valid because every pi-orbit holds a single slot in the maps this library
// builds (readers set one slot per orbit; propagation.hpp gives each orbit one slot); only when two
// pieces share a slot are the pi-orbits marked whole. Run-time errors (a dart without value, an
// empty multiset's barycentre, a point whose mass is not 1) are Error(Schema) located "<where>,
// column <c>, dart <d>". An expression is evaluated either as a tree (eval, the general path) or as
// its compiled program (program.hpp, run): the same operations in the same order, the same members,
// memos and errors.
#pragma once
#include <string>
#include <vector>

#include "model/core/buffer_pool.hpp"
#include "model/core/embedded_map.hpp"
#include "model/core/map.hpp"
#include "model/expr/ast.hpp"
#include "model/expr/program.hpp"
#include "model/expr/type_check.hpp"
#include "model/expr/value_ops.hpp"

namespace gmr::expr {

class Evaluator {
 public:
  static constexpr size_t kMaxNesting = 16;
  // fields[k]: the storage of signature k (nullptr when the map does not have it).
  Evaluator(const Map& g, std::vector<EmbeddingSignature> sigs,
            std::vector<const EmbeddingField*> fields);

  // The value of `e` (a checked expression) with node n at node_darts[n]; `target` is checked
  // (mass of points and vectors). `where` locates errors.
  Val evaluate(const Expr& e, const Dart* node_darts, ValueType target, const std::string& where);
  // The same with e compiled (program.hpp): the same value, the same errors.
  Val evaluate(const Program& p, const Dart* node_darts, ValueType target,
               const std::string& where);

  // Memo mode: a numbering of the <mask>-orbits the caller already has, used instead of a sweep
  // of the map: the dart x is in the orbit numbered numbers[index[x]] (index: the caller's own
  // numbering of the darts, defined on every dart the expressions reach; two darts have the same
  // number iff they are in the same <mask>-orbit). The arrays must outlive the memo mode.
  void share_orbit_numbers(DimMask mask, const uint32_t* numbers, const uint32_t* index);
  // Memo mode, G-maps, two-dimension <mask>-orbits: the darts of the orbit numbered id, in the
  // order of list_two_dims from list[start[id]], are list[start[id] .. start[id + 1]) (numbers:
  // each dart's orbit id). A walk of such an orbit from that first dart reads them there instead
  // of following the links. The arrays must outlive the memo mode.
  void share_orbit_lists(DimMask mask, const uint32_t* list, const uint32_t* start,
                         const uint32_t* numbers);

  // Memoisation of middle/sum/count of a collect (middle(<o>_pi(r)) ...) per <o>-orbit, for the
  // lifetime of the evaluator or until the next call: the value depends only on the orbit, not on
  // the dart it is reached from (up to the order of the floating-point sum). Worth it when the
  // expressions of one application visit most of the map: a table of capacity entries per
  // (function, <o>, pi) is filled lazily (Catmull-Clark reads every face's barycentre from
  // 2k + 1 places). Comprehensions and collects then tell the <c>-orbits met apart by a numbering
  // of all the <c>-orbits of the map (one sweep per <c>) instead of marking each. The map must not
  // change while it is on.
  // While it is on, neither the map nor the values change: the loads read the link arrays and the
  // value tables through pointers taken here (Evaluator::load).
  void memoise_collects(bool on);

  // Memo mode: the values of p at the classes whose left node 0 is at nodes[0..n), appended to out,
  // when p is one affine combination of node values (combines_node_values; evaluator_batch.cpp):
  // run's values bit for bit, without a run per class. Returns the number of classes done (values
  // appended): n, or the first class that fails (no dart, no value, wrong mass), which evaluate()
  // then reports; 0 when p is not of that form or memo mode is off.
  static bool combines_node_values(const Program& p);
  size_t combine_classes(const Program& p, const Dart* nodes, size_t n, ValueType target,
                         std::vector<Vec3>& out) const;
  // Memo mode: the values of any program without unresolved node values (Instruction::Op::Value)
  // at the classes whose left node 0 is at nodes[0..n), appended to out, evaluated kLanes classes
  // at a time, instruction by instruction (evaluator_lanes.cpp): run's values bit for bit. Returns
  // the number of classes done: n, or the first class of a batch that fails (an error of run, which
  // evaluate() then reports); 0 when p does not run in lanes or memo mode is off.
  static bool runs_in_lanes(const Program& p);
  size_t run_classes(const Program& p, const Dart* nodes, size_t n, ValueType target,
                     std::vector<Vec3>& out);

  // The dart-free sub-expressions computed so far (program.hpp, Pure) rather than found kept.
  size_t pure_runs() const { return pure_runs_; }

  // Storage conversion of a value of type t, and back.
  static Vec3 to_storage(const Val& v) { return {v.x, v.y, v.z}; }
  static Val from_storage(const Vec3& s, ValueType t) {
    return {s[0], t == ValueType::Scalar ? 0.0 : s[1], t == ValueType::Scalar ? 0.0 : s[2],
            t == ValueType::Point ? 1.0 : 0.0};
  }

 private:
  Val eval(const Expr& e);
  Val run(const Instruction* pc, const Instruction* end);
  Val aggregate(const Expr& call, const Instruction* body, const Instruction* body_end);
  Val checked(Val v, const Expr& e, ValueType target) const;
  [[noreturn]] __attribute__((noinline, cold)) void fail_mass(const Expr& e, double mass,
                                                              ValueType target) const;
  Val body_value(const Expr& e);
  void members(const Expr& e, MemberSum& out);
  bool collect_by_slots(const Expr& e, DimMask mc, const ScopedMarker& mark, MemberSum& out);
  Dart dart_of(const NodeRef& r, const Expr& e);
  Dart held_dart_of(const NodeRef& r, const Expr& e);
  Val load(const LoadRef& r);
  __attribute__((noinline)) Val load_from_map(const LoadRef& r, Dart d);
  Val field_value(int embedding, Dart d, const Expr& e);
  Val value_at(int embedding, Dart d, const Expr& e);
  [[noreturn]] void fail(const Expr& e, const std::string& msg, Dart d = kNoDart) const;

  const Map& g_;
  std::vector<EmbeddingSignature> sigs_;
  std::vector<const EmbeddingField*> fields_;
  std::vector<ValueType> types_;    // sigs_[k].type
  const LoadRef* loads_ = nullptr;  // the loads of the program run (evaluate)
  const Dart* nodes_ = nullptr;
  std::vector<Dart> vars_;
  std::vector<Val> lets_;
  const std::string* where_ = nullptr;
  std::vector<std::vector<Dart>> scratch_;
  std::vector<uint32_t> slots_, sorted_;
  struct CollectMemo {
    Function function;
    DimMask orbit;
    int embedding;
    ScratchTable<uint32_t> at;  // per dart: index in values, or kNone
    ScratchTable<Val> values;
  };
  static constexpr uint32_t kNone = UINT32_MAX;
  CollectMemo* memo_for(const Expr& call, const Expr& collect);
  Val aggregate_into(const Expr& call, CollectMemo* cm, const Instruction* body,
                     const Instruction* body_end);
  // Memo mode: the number of the <mask>-orbit of every dart (one sweep of the map, on first use).
  struct OrbitIds {
    DimMask mask;
    ScratchTable<uint32_t> ids;         // the number of every dart's orbit, or:
    const uint32_t* numbers = nullptr;  // share_orbit_numbers
    const uint32_t* index = nullptr;
  };
  const OrbitIds& orbit_ids(DimMask mask);
  std::vector<OrbitIds> ids_;
  void memo_members(const Expr& e, DimMask mc, const std::vector<Dart>& in_orbit, MemberSum& out);
  Val member_value(const Expr& e, Dart x);
  bool list_two_dims(DimMask mo, Dart d, std::vector<Dart>& in_orbit);
  bool listed_orbit(DimMask mo, Dart d, std::vector<Dart>& in_orbit) const;
  struct OrbitLists {
    DimMask mask;
    const uint32_t* list;
    const uint32_t* start;
    const uint32_t* numbers;
  };
  std::vector<OrbitLists> lists_;
  bool body_of_one_instruction(const Instruction& body, const std::vector<Dart>& firsts,
                               MemberSum& out);
  struct LastWalk {
    DimMask mask = 0;
    Dart dart = kNoDart;
    bool valid = false;
    // The two last <c> whose first darts are in member_darts_ (memo_members; Catmull-Clark's vertex
    // point alternates <0,2> and <0,1> over one walk), and the one to replace next.
    DimMask members[2] = {kNoMembers, kNoMembers};
    int replace = 0;
  };
  static constexpr DimMask kNoMembers = ~DimMask(0);
  std::vector<Dart> member_darts_[kMaxNesting][2];
  LastWalk last_walk_[kMaxNesting];  // memo mode: the <o>-orbit left in each depth's scratch list
  static constexpr size_t kSmallOrbit = 64;  // beyond, met orbits are marked (no quadratic search)
  bool memo_on_ = false;
  // Memo mode: the map's link arrays and each field's slot and value tables, held for the loads.
  struct HeldField {
    const uint32_t* slots = nullptr;
    size_t size = 0;  // darts with a slot entry (0: no field)
    const Vec3* values = nullptr;
    ValueType type = ValueType::Scalar;
  };
  const Dart* held_links_[kMaxDim] = {};
  std::vector<HeldField> held_fields_;
  void hold_tables();
  size_t combine_classes_in_lanes(const Program& p, const Dart* nodes, size_t n, ValueType target,
                                  std::vector<Vec3>& out) const;
  std::vector<CollectMemo> memos_;
  // Evaluation in lanes (run_classes): the value stack and the let values of kLanes classes,
  // row-major (row r of lane j at r * kLanes + j), and the members of the comprehensions of the
  // batch (up to two kinds of them, as member_darts_).
  static constexpr size_t kLanes = 64;
  static constexpr size_t kLaneLets = 8;  // more let variables in scope: not run in lanes
  std::vector<Val> lane_stack_, lane_lets_;
  struct LaneMembers {
    const Expr* comprehension = nullptr;  // its orbit, classes and start (equal ones share)
    std::vector<Dart> darts;  // the first darts of the members, lane after lane (from start[lane])
    uint32_t start[kLanes + 1] = {};
    bool fast = false;  // every lane's members listed (else aggregate per lane)
  };
  LaneMembers lane_members_[2];
  int lane_members_next_ = 0;
  bool run_lanes(const Program& p, const Dart* nodes, size_t m, ValueType target,
                 std::vector<Vec3>& out);
  bool lane_load(const LoadRef& r, Dart d, Val& v) const;
  const LaneMembers& lane_members(const Expr& comprehension, const Dart* nodes, size_t m);
  Val lane_scalar(const Instruction* pc, const Instruction* end, const Dart* node, size_t lets,
                  size_t lane, bool aggregate);
  // Compiled bodies: the program of the comprehension or walk whose members are enumerated at
  // each depth (nullptr: the tree), and the value stack of the programs.
  struct Body {
    const Instruction* begin = nullptr;
    const Instruction* end = nullptr;
  };
  Body bodies_[kMaxNesting + 1];
  std::vector<Val> stack_;
  size_t top_ = 0;
  // The last results of each dart-free sub-expression run (program.hpp, Pure), with the let values
  // they were computed from: kKeptEntries per sub-expression, the oldest replaced (Loop's vertex
  // weight is a function of the valence, and a mesh mixes a few valences in any order).
  static constexpr size_t kKeptLets = 4;  // more let values in scope: not kept
  static constexpr size_t kKeptEntries = 8;
  struct Kept {
    uint64_t program = 0;  // Program::id
    size_t at = 0;         // the Pure instruction's offset in its code
    struct Entry {
      size_t lets = 0;
      Val key[kKeptLets];
      Val value;
    };
    Entry entries[kKeptEntries];
    size_t used = 0, next = 0;
    mutable size_t last = 0;  // the entry found last
    // The value kept for the n let values lets[0], lets[stride], ..., or nullptr.
    const Val* find(const Val* lets, size_t n, size_t stride) const;
    void keep(const Val* lets, size_t n, const Val& value);
  };
  std::vector<Kept> kept_;
  size_t pure_runs_ = 0;
  Kept* kept_for(const Instruction* at);
  uint64_t program_ = 0;  // the program run (evaluate): its id and code
  const Instruction* code_ = nullptr;
};

}  // namespace gmr::expr
