#include "checker/smt/symbolic_validation.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

#include "checker/rule_check.hpp"
#include "checker/smt/counterexample.hpp"
#include "checker/smt/cycle_components.hpp"
#include "checker/smt/cycle_table.hpp"
#include "checker/smt/rule_space.hpp"
#include "checker/smt/symbolic_cycle.hpp"
#include "checker/smt/symbolic_derivation.hpp"
#include "model/core/error.hpp"

namespace gmr::smt {
using graph::Node;

std::optional<ThesisParts> symbolic_condition_parts(const std::string& name) {
  // The cycle reading of a name is symbolic_cycle_reading's; without cycle pairs
  // "thesis-per-constraint" and "wrong-cycle-without-completion" coincide with "thesis".
  if (name == "thesis" || name == "thesis-per-constraint" ||
      name == "wrong-cycle-without-completion")
    return ThesisParts{};
  if (name == "wrong-incident-without-dangling") return ThesisParts{.dangling = false};
  if (name == "wrong-orientation-dropped") return ThesisParts{.orientation = false};
  return std::nullopt;
}

CycleReading symbolic_cycle_reading(const std::string& name) {
  if (name == "thesis-per-constraint") return CycleReading::IjCompletion;
  if (name == "wrong-cycle-without-completion") return CycleReading::AsWritten;
  return CycleReading::ModelCompletion;  // check_rule, and thesis_conditions' other variants
}

bool cycle_condition(const Rule& r, CycleReading reading) {
  const auto pairs = r.spec().cycle_pairs();
  std::vector<checker::Diagnostic> d;
  const Rule c = reading == CycleReading::ModelCompletion ? checker::complete_for_model(r) : r;
  for (auto [i, j] : pairs) {
    const bool ok = reading == CycleReading::AsWritten ? checker::check_cycle_as_written(c, i, j, d)
                                                       : checker::check_cycle(c, i, j, d);
    if (!ok) return false;
  }
  return true;
}

namespace {
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
unsigned numeral(const z3::expr& e) {
  unsigned v = 0;
  if (!e.is_numeral_u(v))
    throw std::logic_error("SMT model: a dart is not a numeral: " + e.to_string());
  return v;
}

z3::expr condition(const SymbolicRule& rule, const ThesisParts& parts,
                   const ExtraCondition& extra) {
  return extra ? rule.condition(parts) && extra(rule) : rule.condition(parts);
}

// How the named condition reads C_r, and the condition itself (for the cross-check).
struct CondSpec {
  CycleReading reading;
  const BuiltinCondition* builtin;
};

// The common part of both queries: the symbolic rule, a symbolic map and its derivation, with the
// query's own solver (query_solver); the condition is the formula of Theorems 1-2 (`theorems12`)
// and, with cycle pairs, the Boolean `cycle_holds` standing for C_r, which solve() ties to the
// concrete checker lazily.
struct Query {
  z3::context& ctx;
  SymbolicRule rule;
  MapEncoding map;
  SymbolicDerivation der;
  z3::solver solver;
  z3::expr theorems12, cycle_holds;
  std::vector<int> cycle_label_set;
  SymbolicCycle cycle;  // C_r by components (symbolic_cycle.hpp)
  CycleReading reading;
  const BuiltinCondition* builtin;  // the whole condition, to cross-check (nullptr: extra given)
  size_t* lemmas;
  std::function<bool()> out_of_time;  // checked between lemmas
  Query(z3::context& c, z3::solver s, const ValidationOptions& o, const std::string& prefix,
        const ThesisParts& parts, const ExtraCondition& extra, const CondSpec& cs,
        size_t* lemma_count)
      : ctx(c),
        rule(ctx, MapSpec{o.n, o.kind}, o.max_nodes, o.labels),
        map(ctx, MapSpec{o.n, o.kind}, o.bound, static_cast<unsigned>(o.max_nodes),
            DartSort::BitVec, prefix),
        der(map, rule, prefix),
        solver(std::move(s)),
        theorems12(condition(rule, parts, extra)),
        cycle_holds(MapSpec{o.n, o.kind}.cycle_pairs().empty() ? ctx.bool_val(true)
                                                               : ctx.bool_const("cycle_holds")),
        cycle_label_set(cycle_labels(MapSpec{o.n, o.kind})),
        cycle(rule, cycle_label_set),
        reading(cs.reading),
        builtin(extra ? nullptr : cs.builtin),
        lemmas(lemma_count) {
    solver.add(rule.family());
    solver.add(map.constraints());
    solver.add(der.match());
    if (!cycle_label_set.empty()) {
      solver.add(z3::implies(cycle_untouched(), cycle_holds));
      // Theorems 1-2 include w-I_r on the cycle labels: C_r is then the conjunction over the
      // components (cycle_components.hpp).
      solver.add(cycle.axioms(theorems12, cycle_holds));
    }
  }
  // No added node and no deleted or added arc on the labels of the cycle pairs: C_r holds in every
  // reading (the completions add preserved arcs only, so there is no optimal path, no rewired
  // preserved node and no added node, Def. 40), without asking the oracle.
  z3::expr cycle_untouched() const {
    z3::expr_vector all(rule.ctx());
    for (int x = 0; x < rule.slots(); ++x) {
      all.push_back(!rule.added(x));
      for (int l : cycle_label_set)
        for (int y = 0; y < rule.slots(); ++y)
          all.push_back(!rule.deleted_arc(l, x, y) && !rule.added_arc(l, x, y));
    }
    return z3::mk_and(all);
  }
  // The whole condition: Theorems 1-2 and C_r.
  z3::expr whole() const { return theorems12 && cycle_holds; }
  z3::check_result check(const z3::expr_vector& assumptions) {
    const z3::check_result r = solver.check(assumptions);
    if (r == z3::unknown) throw std::logic_error("Z3 returned unknown: " + solver.reason_unknown());
    return r;
  }
  // check() whose models give `cycle_holds` the concrete checker's verdict on their rule whenever
  // Theorems 1-2 hold (when they fail, C_r does not matter): in a model that disagrees, some
  // component's `ok` differs from the checker's verdict on that component; each such component
  // yields the lemma "every placement of this component's pattern has ok = verdict"
  // (symbolic_cycle.hpp; valid for the whole family) and the query is solved again.
  // z3::unknown: the time limit hit between lemmas.
  z3::check_result solve(const z3::expr_vector& assumptions) {
    while (true) {
      if (out_of_time && out_of_time()) return z3::unknown;
      if (check(assumptions) == z3::unsat) return z3::unsat;
      if (cycle_label_set.empty()) return z3::sat;
      const z3::model m = solver.get_model();
      if (!m.eval(theorems12, true).is_true()) return z3::sat;
      const Rule r = rule.extract(m, "oracle");
      const bool verdict = cycle_condition(r, reading);
      if (builtin && builtin->holds(r) != verdict)
        throw std::logic_error("the cycle oracle disagrees with condition " + builtin->name +
                               " on " + rule_text(r) + " (encoding error)");
      if (m.eval(cycle_holds, true).is_true() == verdict) return z3::sat;
      size_t learnt = 0;
      for (const auto& nodes : rule_components(r, cycle_label_set)) {
        const unsigned mask = cycle.mask_of(nodes);
        if (!m.eval(cycle.component(mask), true).is_true())
          throw std::logic_error("a component of " + rule_text(r) +
                                 " is not one in the symbolic rule (encoding error)");
        const bool ok = cycle_condition(restrict_rule(r, nodes, cycle_label_set), reading);
        if (m.eval(cycle.ok(mask), true).is_true() == ok) continue;
        solver.add(cycle.lemma(m, mask, ok));
        ++learnt;
      }
      if (learnt == 0)
        throw std::logic_error("C_r of " + rule_text(r) +
                               " is not the conjunction over its components (encoding error)");
      *lemmas += learnt;
    }
  }
  Map map_of(const z3::model& m) const {
    const unsigned size = numeral(m.eval(map.size(), true));
    Map G(map.spec().n, map.spec().kind);
    G.add_darts(size);
    for (int i : map.spec().labels())
      for (unsigned d = 0; d < size; ++d)
        G.set_alpha(i, d, numeral(m.eval(map.alpha(i, map.dart(d)), true)));
    return G;
  }
};

// An assumption literal standing for `e` (so that bounds can be lowered without popping).
z3::expr assume(z3::solver& s, const z3::expr& e, const std::string& name) {
  const z3::expr p = s.ctx().bool_const(name.c_str());
  s.add(z3::implies(p, e));
  return p;
}

// A family of at most 2 nodes: there, set-up is most of a validation's time, so both queries share
// one Z3 context and use Z3's SMT core alone (z3::solver::simple()), 2-4x faster than a context per
// query with Z3's default solver (which sets up a tactic solver beside its SMT core). On larger
// families the default solver and a context per query are faster: the tactic's preprocessing
// pays there (docs/verify.md, "Solvers of the symbolic queries").
bool small_family(const ValidationOptions& o) { return o.max_nodes <= 2; }
z3::solver query_solver(z3::context& ctx, const ValidationOptions& o) {
  return small_family(o) ? z3::solver(ctx, z3::solver::simple()) : z3::solver(ctx);
}

// Sound: no rule satisfying the condition has a breaking match within the bounds.
void decide_sound(z3::context& ctx, SymbolicReport& rep, const ThesisParts& parts,
                  const ExtraCondition& extra, const CondSpec& cs, const CycleTable& table,
                  const std::vector<PatternCube>& cubes, const std::function<bool()>& out_of_time) {
  const auto t0 = std::chrono::steady_clock::now();
  const ValidationOptions& o = rep.options;
  Query q(ctx, query_solver(ctx, o), o, "", parts, extra, cs, &rep.cycle_lemmas);
  q.out_of_time = out_of_time;
  // The tabulated failing components as cubes (cycle_table.hpp): valid here, where Theorems 1-2
  // hold; no oracle call for components of at most table.max_nodes nodes.
  if (!q.cycle_label_set.empty())
    q.solver.add(q.cycle.cube_lemmas(table, cubes, q.ctx.bool_val(true)));
  q.solver.add(q.der.h_definitions());
  q.solver.add(q.whole());
  q.solver.add(q.der.breaks_consistency());
  z3::expr_vector none(q.ctx);
  const z3::check_result first = q.solve(none);
  if (first == z3::unknown) {
    rep.sound_seconds = since(t0);
    return;
  }
  if (first == z3::sat) {
    // The smallest witness: fewest nodes, then fewest darts.
    for (int m = 1; m <= o.max_nodes && !rep.smallest_unsound; ++m)
      for (unsigned b = 1; b <= o.bound && !rep.smallest_unsound; ++b) {
        z3::expr_vector a(q.ctx);
        a.push_back(assume(q.solver, q.rule.nodes_exactly(m), "nodes" + std::to_string(m)));
        a.push_back(assume(q.solver, q.map.size() == q.map.dart(b), "darts" + std::to_string(b)));
        const z3::check_result res = q.solve(a);
        if (res == z3::unknown) {
          rep.sound_seconds = since(t0);
          return;
        }
        if (res != z3::sat) continue;
        const z3::model model = q.solver.get_model();
        const Rule r = q.rule.extract(model, "unsound");
        rewrite::NodeMap nodes;
        for (Node v : r.left().nodes())
          nodes.push_back(graph::node_of(v.index()));  // slot x on dart x
        auto c = replay(r, q.map_of(model), nodes, Engine::Smt, Semantics::Consistency);
        if (!c)
          throw std::logic_error("symbolic counterexample does not replay (encoding error): " +
                                 rule_text(r));
        rep.smallest_unsound = ValidationWitness{r, 0, std::move(c)};
      }
    if (!rep.smallest_unsound)
      throw std::logic_error("symbolic soundness query: no witness within the bounds");
  }
  rep.sound_decided = true;
  rep.sound_seconds = since(t0);
}

// G relabelled so that the match is the identity on the L nodes (the symbolic match's shape).
Map relabel(const Map& G, const std::vector<Node>& match) {
  const size_t size = G.size();
  const Dart none = static_cast<Dart>(-1);
  std::vector<Dart> to(size, none);
  Dart next = 0;
  for (Node v : match) to[graph::dart_of(v)] = next++;
  for (Dart d = 0; d < size; ++d)
    if (to[d] == none) to[d] = next++;
  Map out(G.dimension(), G.kind());
  out.add_darts(size);
  for (int i : MapSpec{G.dimension(), G.kind()}.labels())
    for (Dart d = 0; d < size; ++d) out.set_alpha(i, to[d], to[G.alpha(i, d)]);
  return out;
}

// The labels whose links no cycle pair of the model reads and which are involutions: on them a
// map may take any involution (the map constraints of Def. 32 are independent of it).
std::vector<int> free_labels(const MapSpec& spec) {
  const std::vector<int> cyc = cycle_labels(spec);
  std::vector<int> out;
  for (int i : spec.labels())
    if (spec.is_involutive_dim(i) && std::find(cyc.begin(), cyc.end(), i) == cyc.end())
      out.push_back(i);
  return out;
}

// alpha_i(d) of the map G_r: G with, on a free label i, the involution that the rule's L i-arcs
// ask for on the matched darts (slot x on dart x) and loops elsewhere, when L's i-arcs can be
// matched at all on G's darts (no arc to a slot beyond G, no path x -> y -> z with z != x);
// otherwise G's own alpha_i. Either way an involution: G_r is a map, whatever the rule.
z3::expr free_label_target(Query& q, const MapEncoding& M, const Map& G, int i, Dart d) {
  const SymbolicRule& r = q.rule;
  const int slots = r.slots();
  z3::expr_vector realizable(q.ctx);
  for (int x = 0; x < slots; ++x)
    for (int y = 0; y < slots; ++y) {
      if (static_cast<size_t>(x) >= G.size() || static_cast<size_t>(y) >= G.size())
        realizable.push_back(!r.arc(false, i, x, y));
      for (int z = 0; z < slots; ++z)
        if (z != x) realizable.push_back(!(r.arc(false, i, x, y) && r.arc(false, i, y, z)));
    }
  z3::expr target = M.dart(d);
  if (d < static_cast<Dart>(slots))
    for (int y = 0; y < slots && static_cast<size_t>(y) < G.size(); ++y) {
      target = z3::ite(r.arc(false, i, y, static_cast<int>(d)), M.dart(static_cast<unsigned>(y)),
                       target);
      target = z3::ite(r.arc(false, i, static_cast<int>(d), y), M.dart(static_cast<unsigned>(y)),
                       target);
    }
  return z3::ite(z3::mk_and(realizable), target, M.dart(G.alpha(i, d)));
}

// "The match of the rule on this concrete map glues and yields a map" as a constraint on the rule.
// With `generalise`, the map is G_r (free_label_target): the constraint then also speaks of the
// rules that differ from the candidate on the free labels' arcs, each on its own map G_r.
void refine(Query& q, const ValidationOptions& o, const Map& G, size_t t, bool generalise,
            std::vector<std::unique_ptr<MapEncoding>>& maps,
            std::vector<std::unique_ptr<SymbolicDerivation>>& ders) {
  const std::string prefix = "r" + std::to_string(t) + "_";
  maps.push_back(std::make_unique<MapEncoding>(q.ctx, MapSpec{o.n, o.kind}, o.bound,
                                               static_cast<unsigned>(o.max_nodes), DartSort::BitVec,
                                               prefix));
  const MapEncoding& M = *maps.back();
  const std::vector<int> free = generalise ? free_labels(M.spec()) : std::vector<int>{};
  q.solver.add(M.size() == M.dart(static_cast<unsigned>(G.size())));
  for (int i : M.spec().labels())
    for (Dart d = 0; d < G.size(); ++d) {
      if (std::find(free.begin(), free.end(), i) != free.end()) {
        q.solver.add(M.alpha(i, M.dart(d)) == free_label_target(q, M, G, i, d));
        continue;
      }
      q.solver.add(M.alpha(i, M.dart(d)) == M.dart(G.alpha(i, d)));
      if (!M.spec().is_involutive_dim(i)) {
        for (Dart e = 0; e < G.size(); ++e)
          if (G.alpha(i, e) == d) q.solver.add(M.alpha_inverse(i, M.dart(d)) == M.dart(e));
      }
    }
  ders.push_back(std::make_unique<SymbolicDerivation>(M, q.rule, prefix));
  const SymbolicDerivation& D = *ders.back();
  q.solver.add(D.h_definitions());
  q.solver.add(z3::implies(D.match(), !D.breaks_consistency()));
}

// Complete: every rule failing the condition and matching some map has a breaking match.
void decide_complete(z3::context& ctx, SymbolicReport& rep, const ThesisParts& parts,
                     const ExtraCondition& extra, const CondSpec& cs, const CycleTable& table,
                     const std::vector<PatternCube>& cubes,
                     const std::vector<PatternCube>& holding_cubes,
                     std::chrono::steady_clock::time_point start) {
  const auto t0 = std::chrono::steady_clock::now();
  const ValidationOptions& o = rep.options;
  // The witness map "w_": a match exists.
  Query q(ctx, query_solver(ctx, o), o, "w_", parts, extra, cs, &rep.cycle_lemmas);
  // The tabulated verdicts (cycle_table.hpp) as cubes of both verdicts, under a literal equal to
  // Theorems 1-2 (which may fail here).
  if (!q.cycle_label_set.empty()) {
    const z3::expr t12 = q.ctx.bool_const("w_theorems12");
    q.solver.add(t12 == q.theorems12);
    q.solver.add(q.cycle.cube_lemmas(table, cubes, t12));
    q.solver.add(q.cycle.cube_lemmas(table, holding_cubes, t12));
  }
  q.out_of_time = [&] { return o.time_limit > 0 && since(start) > o.time_limit; };
  q.solver.add(!q.whole());
  // ... and it glues and preserves: a witness has only preserving matches, so this loses none,
  // and it excludes at once every failing rule that breaks on every map it matches (the rules
  // failing Theorems 1-2), leaving the refinements to the others.
  q.solver.add(q.der.h_definitions());
  q.solver.add(!q.der.breaks_consistency());
  EncodingOptions eo;
  eo.semantics = Semantics::Consistency;
  std::optional<SmtSession> session;  // made at the first candidate: most validations have none
  std::vector<std::unique_ptr<MapEncoding>> maps;
  std::vector<std::unique_ptr<SymbolicDerivation>> ders;
  for (int m = 1; m <= o.max_nodes; ++m) {
    z3::expr_vector a(q.ctx);
    a.push_back(assume(q.solver, q.rule.nodes_exactly(m), "nodes" + std::to_string(m)));
    while (true) {
      if (o.time_limit > 0 && since(start) > o.time_limit) {
        rep.complete_seconds = since(t0);
        return;
      }
      const z3::check_result res = q.solve(a);
      if (res == z3::unknown) {
        rep.complete_seconds = since(t0);
        return;
      }
      if (res == z3::unsat) break;
      const z3::model model = q.solver.get_model();
      const Rule r = q.rule.extract(model, "candidate");
      if (!session)
        session.emplace(MapSpec{o.n, o.kind}, o.bound, static_cast<unsigned>(o.max_nodes), eo);
      const VerifyResult v = session->verify(r);
      if (v.preserves) {
        if (!v.applicable)
          throw std::logic_error("symbolic candidate matches no map (encoding error): " +
                                 rule_text(r));
        rep.smallest_incomplete = ValidationWitness{r, 0, std::nullopt};
        rep.complete_decided = true;
        rep.complete_seconds = since(t0);
        return;
      }
      // The refinement on G_r first; the candidate's own G if that does not exclude it.
      const Map G = relabel(v.counterexample->G, v.counterexample->match.node);
      const bool generalise = !free_labels(MapSpec{o.n, o.kind}).empty();
      refine(q, o, G, rep.refinements++, generalise, maps, ders);
      // The refinement must exclude the candidate (else the loop would not progress).
      z3::expr_vector fixed(q.ctx);  // a new vector: copies of an expr_vector share it
      for (const auto& e : a) fixed.push_back(e);
      fixed.push_back(
          assume(q.solver, q.rule.equals(model), "candidate" + std::to_string(rep.refinements)));
      if (generalise && q.check(fixed) != z3::unsat)
        refine(q, o, G, rep.refinements++, false, maps, ders);
      if (q.check(fixed) != z3::unsat)
        throw std::logic_error("a refinement does not exclude its candidate (encoding error): " +
                               rule_text(r));
    }
  }
  rep.complete_decided = true;
  rep.complete_seconds = since(t0);
}
}  // namespace

SymbolicReport validate_symbolic(const std::string& condition, const ValidationOptions& opt) {
  const auto parts = symbolic_condition_parts(condition);
  if (!parts)
    throw Error(ErrorCode::Usage,
                "condition '" + condition + "' has no symbolic form (engines smt and enum take it)",
                "--engine symbolic");
  return validate_symbolic(condition, *parts, nullptr, opt);
}

SymbolicReport validate_symbolic(const std::string& condition, const ThesisParts& parts,
                                 const ExtraCondition& extra, const ValidationOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  if (opt.shards != 1 || opt.random != 0)
    throw Error(ErrorCode::Usage, "--shard and --random do not apply to the symbolic engine",
                "--engine symbolic");
  SymbolicReport rep;
  rep.condition = condition;
  rep.options = opt;
  for (int m = 1; m <= opt.max_nodes; ++m) rep.rules += count_rules(m, opt.labels.size());
  const CondSpec cs{symbolic_cycle_reading(condition), find_builtin_condition(condition)};
  const MapSpec spec{opt.n, opt.kind};
  CycleTable table;
  std::vector<PatternCube> cubes, holding_cubes;
  if (!spec.cycle_pairs().empty() && opt.cycle_table_nodes > 0) {
    const auto t0 = std::chrono::steady_clock::now();
    table = cycle_table(spec, opt.labels, std::min(opt.max_nodes, opt.cycle_table_nodes), parts,
                        cs.reading);
    cubes = failing_cubes(table);
    holding_cubes = verdict_cubes(table, true);
    rep.cycle_table_seconds = since(t0);
  }
  rep.cycle_patterns = table.patterns.size();
  rep.cycle_cubes = cubes.size() + holding_cubes.size();
  std::optional<z3::context> ctx(std::in_place);
  decide_sound(*ctx, rep, parts, extra, cs, table, cubes,
               [&] { return opt.time_limit > 0 && since(start) > opt.time_limit; });
  if (!small_family(opt)) {  // a context per query (small_family)
    ctx.reset();
    ctx.emplace();
  }
  decide_complete(*ctx, rep, parts, extra, cs, table, cubes, holding_cubes, start);
  return rep;
}

}  // namespace gmr::smt
