#include "checker/smt/rule_verifier.hpp"

#include <chrono>
#include <stdexcept>

#include "checker/semantic.hpp"
#include "checker/smt/derivation_encoding.hpp"
#include "model/core/error.hpp"
#include "model/graph/map_family.hpp"
#include "model/rewrite/dpo.hpp"

namespace gmr::smt {
using graph::Node;

const char* to_string(Engine e) { return e == Engine::Smt ? "smt" : "enum"; }

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
}  // namespace

std::optional<Counterexample> replay(const Rule& r, const Map& G, const rewrite::NodeMap& nodes,
                                     Engine e) {
  return replay(r, G, nodes, e, Semantics::Preservation);
}

std::optional<Counterexample> replay(const Rule& r, const Map& G, const rewrite::NodeMap& nodes,
                                     Engine e, Semantics sem) {
  const DGraph Gd = graph::to_dgraph(G);
  auto m = rewrite::match_from_nodes(r.left(), Gd, nodes);
  if (!m) return std::nullopt;
  Counterexample c;
  c.G = G;
  c.engine = e;
  if (!rewrite::satisfies_gluing(r, Gd, *m)) {
    if (sem == Semantics::Preservation) return std::nullopt;
    c.match = std::move(*m);
    c.gluing_fails = true;
    return c;
  }
  rewrite::Derivation d = rewrite::derive(r, Gd, *m, rewrite::Construction::Rewriting);
  auto viol = graph::check_map_constraints(d.H, r.dimension(), r.kind());
  if (viol.empty()) return std::nullopt;
  c.match = std::move(*m);
  c.H = std::move(d.H);
  c.violations = std::move(viol);
  return c;
}

namespace {
// The verification of one rule on a map encoding. `shared`: a solver holding the map constraints
// (the rule's assertions go in a push/pop scope); null: own solvers (fresh per bound unless
// opt.incremental).
VerifyResult verify_on(z3::context& ctx, const MapEncoding& map, z3::solver* shared, const Rule& r,
                       const EncodingOptions& opt, bool applicable_check) {
  const auto t0 = std::chrono::steady_clock::now();
  VerifyResult res;
  res.engine = Engine::Smt;
  res.bound = map.capacity();
  const unsigned nl = static_cast<unsigned>(r.left().num_nodes());
  const unsigned lo = std::max(1u, nl);
  if (lo > map.capacity()) {  // L has more nodes than any map of the bound has darts
    res.seconds = since(t0);
    return res;
  }
  DerivationEncoding der(map, r, opt.fixed_match);
  const bool consistency = opt.semantics == Semantics::Consistency;
  auto rule_assertions = [&](bool with_violation) {
    z3::expr_vector v = der.match_constraints();
    if (with_violation) {
      for (const auto& e : der.h_definitions()) v.push_back(e);
      const z3::expr breaks = opt.local_violations ? der.breaks_model_local() : der.breaks_model();
      v.push_back(consistency ? (!der.dangling_condition() || breaks)
                              : (der.dangling_condition() && breaks));
    } else if (!consistency) {
      v.push_back(der.dangling_condition());
    }
    return v;
  };
  // Runs the query for every bound from lo; returns the first model.
  auto search = [&](bool with_violation) -> std::optional<z3::model> {
    const z3::expr_vector rule = rule_assertions(with_violation);
    std::optional<z3::solver> own;
    z3::solver* s = shared;
    auto fresh = [&] {
      own.emplace(ctx);
      own->add(map.constraints());
      own->add(rule);
      s = &*own;
    };
    if (shared) {
      s->push();
      s->add(rule);
    } else if (opt.incremental) {
      fresh();
    }
    std::optional<z3::model> found;
    for (unsigned b = lo; b <= map.capacity() && !found; ++b) {
      if (!shared && !opt.incremental) fresh();
      s->push();
      s->add(map.size() == map.dart(b));
      const z3::check_result cr = s->check();
      if (cr == z3::unknown) throw std::logic_error("Z3 returned unknown: " + s->reason_unknown());
      if (cr == z3::sat) found = s->get_model();
      s->pop();
    }
    if (shared) s->pop();
    return found;
  };
  if (auto model = search(true)) {
    const unsigned size = numeral(model->eval(map.size(), true));
    Map G(r.dimension(), r.kind());
    G.add_darts(size);
    for (int i : r.spec().labels())
      for (unsigned d = 0; d < size; ++d)
        G.set_alpha(i, d, numeral(model->eval(map.alpha(i, map.dart(d)), true)));
    rewrite::NodeMap nodes;  // the model matches L node v on a dart of G: its node in to_dgraph(G)
    for (Node v : r.left().nodes())
      nodes.push_back(graph::node_of(numeral(model->eval(der.match(v), true))));
    auto c = replay(r, G, nodes, Engine::Smt, opt.semantics);
    if (!c)
      throw std::logic_error("SMT counterexample of rule " + r.name() +
                             " does not replay (encoding error)");
    res.preserves = false;
    res.applicable = true;
    res.counterexample = std::move(c);
  } else if (applicable_check) {
    res.applicable = search(false).has_value();
  }
  res.seconds = since(t0);
  return res;
}
}  // namespace

struct SmtSession::State {
  EncodingOptions opt;
  unsigned max_added;
  z3::context ctx;
  MapEncoding map;
  z3::solver solver;
  State(MapSpec spec, unsigned bound, unsigned added, const EncodingOptions& o)
      : opt(o), max_added(added), map(ctx, spec, bound, added, o.sort), solver(ctx) {
    solver.add(map.constraints());
  }
};

SmtSession::SmtSession(MapSpec spec, unsigned bound, unsigned max_added, const EncodingOptions& opt)
    : s_(std::make_unique<State>(spec, bound, max_added, opt)) {}
SmtSession::~SmtSession() = default;
const MapSpec& SmtSession::spec() const { return s_->map.spec(); }
unsigned SmtSession::bound() const { return s_->map.capacity(); }

VerifyResult SmtSession::verify(const Rule& r, bool applicable_check) {
  if (r.spec() != s_->map.spec())
    throw Error(ErrorCode::Usage, "the rule and the session have different models",
                "rule " + r.name());
  // The added nodes are numerals after the darts: the dart sort was sized for max_added of them.
  if (r.added_nodes().size() > s_->max_added)
    throw Error(ErrorCode::Usage, "the rule adds more nodes than the session reserved",
                "rule " + r.name());
  return verify_on(s_->ctx, s_->map, &s_->solver, r, s_->opt, applicable_check);
}

VerifyResult verify_smt(const Rule& r, unsigned bound, const EncodingOptions& opt) {
  return verify_smt(r, bound, opt, true);
}

VerifyResult verify_smt(const Rule& r, unsigned bound, const EncodingOptions& opt,
                        bool applicable_check) {
  z3::context ctx;
  MapEncoding map(ctx, r.spec(), bound, static_cast<unsigned>(r.added_nodes().size()), opt.sort);
  return verify_on(ctx, map, nullptr, r, opt, applicable_check);
}

VerifyResult verify_enum(const Rule& r, unsigned bound, Semantics sem) {
  const auto t0 = std::chrono::steady_clock::now();
  VerifyResult res = verify_enum(r, graph::map_family(r.dimension(), r.kind(), bound), sem);
  res.seconds = since(t0);
  return res;
}

VerifyResult verify_enum(const Rule& r, const graph::MapFamily& fam, Semantics sem) {
  const auto t0 = std::chrono::steady_clock::now();
  VerifyResult res;
  res.engine = Engine::Enum;
  res.bound = static_cast<unsigned>(fam.max_darts);
  if (sem == Semantics::Consistency) {
    // Every match, in the family's order (smallest maps first); a gluing failure is a break.
    for (size_t k = 0; k < fam.graphs.size() && res.preserves; ++k) {
      rewrite::for_each_match(r.left(), fam.graphs[k], [&](const Match& m) {
        res.applicable = true;
        if (auto c = replay(r, fam.maps[k], m.node, Engine::Enum, sem)) {
          res.preserves = false;
          res.counterexample = std::move(c);
          return false;
        }
        return true;
      });
    }
    res.seconds = since(t0);
    return res;
  }
  const checker::SemanticVerdict v = checker::semantic_verdict(r, fam);
  res.preserves = v.preserves;
  res.applicable = v.applicable();
  if (v.witness) {
    Counterexample c;
    c.G = fam.maps[v.witness->map_index];
    c.match = v.witness->match;
    c.H = v.witness->H;
    c.violations = v.witness->violations;
    c.engine = Engine::Enum;
    res.counterexample = std::move(c);
  }
  res.seconds = since(t0);
  return res;
}

}  // namespace gmr::smt
