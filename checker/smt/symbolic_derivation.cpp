#include "checker/smt/symbolic_derivation.hpp"

namespace gmr::smt {

SymbolicDerivation::SymbolicDerivation(const MapEncoding& map, const SymbolicRule& rule,
                                       const std::string& prefix)
    : map_(map), rule_(rule) {
  for (int i = 0; i <= map_.spec().n; ++i)
    h_.push_back(
        map_.ctx().function((prefix + "h" + std::to_string(i)).c_str(), map_.sort(), map_.sort()));
}

z3::expr SymbolicDerivation::h_node(int x) const {
  return z3::ite(rule_.in_left(x), dart(x), map_.dart(map_.capacity() + static_cast<unsigned>(x)));
}

z3::expr SymbolicDerivation::match() const {
  z3::expr_vector all(map_.ctx());
  for (int x = 0; x < rule_.slots(); ++x) {
    all.push_back(z3::implies(rule_.in_left(x), map_.active_term(dart(x))));
    for (int i : rule_.labels())
      for (int y = 0; y < rule_.slots(); ++y)
        all.push_back(z3::implies(rule_.arc(false, i, x, y), map_.alpha(i, dart(x)) == dart(y)));
  }
  return z3::mk_and(all);
}

z3::expr SymbolicDerivation::dangling_condition() const {
  z3::context& c = map_.ctx();
  z3::expr_vector all(c);
  for (int x = 0; x < rule_.slots(); ++x)
    for (int i : map_.spec().labels()) {
      z3::expr_vector out(c), in(c);
      for (int y = 0; y < rule_.slots(); ++y) {
        out.push_back(rule_.arc(false, i, x, y) && map_.alpha(i, dart(x)) == dart(y));
        in.push_back(rule_.arc(false, i, y, x) && map_.alpha_inverse(i, dart(x)) == dart(y));
      }
      all.push_back(z3::implies(rule_.deleted(x), z3::mk_or(out) && z3::mk_or(in)));
    }
  return z3::mk_and(all);
}

z3::expr SymbolicDerivation::alive_dart(const z3::expr& X) const {
  z3::expr_vector gone(map_.ctx());
  for (int x = 0; x < rule_.slots(); ++x) gone.push_back(rule_.deleted(x) && X == dart(x));
  return map_.active_term(X) && !z3::mk_or(gone);
}

z3::expr SymbolicDerivation::alive(unsigned x) const {
  if (x < map_.capacity()) return alive_dart(map_.dart(x));
  return rule_.added(static_cast<int>(x - map_.capacity()));
}

std::vector<SymbolicDerivation::Candidate> SymbolicDerivation::arcs(const z3::expr& X, int i,
                                                                    bool incoming) const {
  z3::context& c = map_.ctx();
  std::vector<Candidate> out;
  // G's i-arc at X survives unless a deleted L-arc is matched onto it (false for an added node's
  // numeral, which is not an active dart).
  z3::expr_vector removed(c);
  for (int x = 0; x < rule_.slots(); ++x)
    for (int y = 0; y < rule_.slots(); ++y)
      removed.push_back(rule_.deleted_arc(i, x, y) && X == dart(incoming ? y : x));
  out.push_back({alive_dart(X) && !z3::mk_or(removed),
                 incoming ? map_.alpha_inverse(i, X) : map_.alpha(i, X)});
  for (int x = 0; x < rule_.slots(); ++x)
    for (int y = 0; y < rule_.slots(); ++y) {
      const z3::expr here = h_node(incoming ? y : x), there = h_node(incoming ? x : y);
      out.push_back({rule_.added_arc(i, x, y) && here == X, there});
    }
  return out;
}

z3::expr SymbolicDerivation::exactly_one(const std::vector<Candidate>& cs) const {
  z3::context& c = map_.ctx();
  z3::expr_vector any(c), pairs(c);
  for (size_t k = 0; k < cs.size(); ++k) {
    any.push_back(cs[k].present);
    for (size_t l = k + 1; l < cs.size(); ++l) pairs.push_back(!(cs[k].present && cs[l].present));
  }
  return z3::mk_or(any) && z3::mk_and(pairs);
}

z3::expr_vector SymbolicDerivation::h_definitions() const {
  z3::expr_vector out(map_.ctx());
  const unsigned nodes = map_.capacity() + static_cast<unsigned>(rule_.slots());
  for (int i : map_.spec().labels())
    for (unsigned x = 0; x < nodes; ++x) {
      const z3::expr X = map_.dart(x);
      const auto cs = arcs(X, i, false);
      z3::expr target = cs.back().end;
      for (size_t k = cs.size() - 1; k-- > 0;) target = z3::ite(cs[k].present, cs[k].end, target);
      out.push_back(z3::implies(alive(x), h_[i](X) == target));
    }
  return out;
}

z3::expr SymbolicDerivation::breaks_model_local() const {
  z3::expr_vector any(map_.ctx());
  const MapSpec& s = map_.spec();
  for (int x = 0; x < rule_.slots(); ++x) {
    const z3::expr X = h_node(x);
    z3::expr_vector here(map_.ctx());
    for (int i : s.labels()) {
      here.push_back(!(exactly_one(arcs(X, i, false)) && exactly_one(arcs(X, i, true))));
      if (s.is_involutive_dim(i)) here.push_back(h_[i](h_[i](X)) != X);
    }
    for (auto [i, j] : s.cycle_pairs()) {
      here.push_back(h_[j](h_[i](h_[j](h_[i](X)))) != X);
      here.push_back(h_[i](h_[j](h_[i](h_[j](X)))) != X);
    }
    any.push_back(rule_.in_right(x) && z3::mk_or(here));
  }
  return z3::mk_or(any);
}

}  // namespace gmr::smt
