#include "checker/smt/rule_verifier.hpp"

#include <chrono>
#include <stdexcept>

#include "checker/semantic.hpp"
#include "checker/smt/derivation_encoding.hpp"
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
  if (!e.is_numeral_u(v)) throw std::logic_error("SMT model: a dart is not a numeral: " + e.to_string());
  return v;
}
}  // namespace

std::optional<Counterexample> replay(const Rule& r, const GMap& G, const std::vector<Node>& nodes, Engine e) {
  const DGraph Gd = graph::to_dgraph(G);
  auto m = rewrite::match_from_nodes(r.left(), Gd, nodes);
  if (!m || !rewrite::satisfies_gluing(r, Gd, *m)) return std::nullopt;
  rewrite::Derivation d = rewrite::derive_in_place(r, Gd, *m);
  auto viol = graph::check_gmap_constraints(d.H, r.dimension(), r.kind());
  if (viol.empty()) return std::nullopt;
  Counterexample c;
  c.G = G;
  c.match = std::move(*m);
  c.H = std::move(d.H);
  c.violations = std::move(viol);
  c.engine = e;
  return c;
}

VerifyResult verify_smt(const Rule& r, unsigned bound, const EncodingOptions& opt) {
  return verify_smt(r, bound, opt, true);
}

VerifyResult verify_smt(const Rule& r, unsigned bound, const EncodingOptions& opt, bool applicable_check) {
  const auto t0 = std::chrono::steady_clock::now();
  VerifyResult res;
  res.engine = Engine::Smt;
  res.bound = bound;
  const unsigned nl = static_cast<unsigned>(r.left().num_nodes());
  const unsigned lo = std::max(1u, nl);
  if (lo > bound) {  // L has more nodes than any map of the bound has darts
    res.seconds = since(t0);
    return res;
  }
  z3::context ctx;
  const unsigned added = static_cast<unsigned>(r.added_nodes().size());
  MapEncoding map(ctx, r.spec(), bound, added, opt.sort);
  DerivationEncoding der(map, r, opt.fixed_match);
  const z3::expr_vector base = [&] {
    z3::expr_vector v = map.constraints();
    for (const auto& e : der.match_constraints()) v.push_back(e);
    v.push_back(der.dangling_condition());
    return v;
  }();
  auto make_solver = [&](bool with_violation) {
    z3::solver s(ctx);
    s.add(base);
    if (with_violation) {
      s.add(der.h_definitions());
      s.add(der.breaks_model());
    }
    return s;
  };
  // Runs the query for every bound from lo; returns the first model.
  auto search = [&](bool with_violation) -> std::optional<z3::model> {
    std::optional<z3::solver> s;
    if (opt.incremental) s.emplace(make_solver(with_violation));
    for (unsigned b = lo; b <= bound; ++b) {
      if (!opt.incremental) s.emplace(make_solver(with_violation));
      s->push();
      s->add(map.size() == map.dart(b));
      const z3::check_result cr = s->check();
      if (cr == z3::unknown) throw std::logic_error("Z3 returned unknown: " + s->reason_unknown());
      if (cr == z3::sat) return s->get_model();
      s->pop();
    }
    return std::nullopt;
  };
  if (auto model = search(true)) {
    const unsigned size = numeral(model->eval(map.size(), true));
    GMap G(r.dimension(), r.kind());
    G.add_darts(size);
    for (int i : r.spec().labels())
      for (unsigned d = 0; d < size; ++d) G.set_alpha(i, d, numeral(model->eval(map.alpha(i, map.dart(d)), true)));
    std::vector<Node> nodes;
    for (unsigned v = 0; v < nl; ++v) nodes.push_back(numeral(model->eval(der.match(v), true)));
    auto c = replay(r, G, nodes, Engine::Smt);
    if (!c) throw std::logic_error("SMT counterexample of rule " + r.name() + " does not replay (encoding error)");
    res.preserves = false;
    res.applicable = true;
    res.counterexample = std::move(c);
  } else if (applicable_check) {
    res.applicable = search(false).has_value();
  }
  res.seconds = since(t0);
  return res;
}

VerifyResult verify_enum(const Rule& r, unsigned bound) {
  const auto t0 = std::chrono::steady_clock::now();
  VerifyResult res;
  res.engine = Engine::Enum;
  res.bound = bound;
  const graph::MapFamily fam = graph::map_family(r.dimension(), r.kind(), bound);
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
