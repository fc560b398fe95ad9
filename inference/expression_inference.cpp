#include "inference/expression_inference.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/expr/compiled_scheme.hpp"
#include "model/scheme/scheme_engine.hpp"

namespace gmr::inference {
using namespace gmr::scheme;

namespace {

using Q = mpq_class;
using Vec = std::array<Q, 3>;

// The simplest rational within 1e-9 (relative to max(1, |x|)) of x with a denominator up to 10^6
// (continued fractions), else x exactly.
Q rationalize(double x) {
  const double tol = 1e-9 * std::max(1.0, std::fabs(x));
  long long h0 = 0, h1 = 1, k0 = 1, k1 = 0;
  double r = x;
  for (int it = 0; it < 64; ++it) {
    const double a = std::floor(r);
    if (std::fabs(a) > 1e15) break;
    const long long ai = static_cast<long long>(a);
    const long long h2 = ai * h1 + h0, k2 = ai * k1 + k0;
    if (k2 > 1000000) break;
    h0 = h1;
    h1 = h2;
    k0 = k1;
    k1 = k2;
    if (std::fabs(static_cast<double>(h1) / static_cast<double>(k1) - x) <= tol) {
      Q q(static_cast<long>(h1), static_cast<unsigned long>(k1));
      q.canonicalize();
      return q;
    }
    const double frac = r - a;
    if (frac == 0) break;
    r = 1.0 / frac;
  }
  return Q(x);
}

// Per dart: the index of its <mask>-orbit.
std::vector<uint32_t> orbit_ids(const Map& g, DimMask mask) {
  std::vector<uint32_t> id(g.capacity(), UINT32_MAX);
  uint32_t n = 0;
  visit_all_orbits(
      g, mask, [&](Dart) { ++n; }, [&](Dart x) { id[x] = n - 1; });
  return id;
}

// Exact Gaussian elimination of the augmented system [A | y] (rows x (cols + 1)). Returns the
// rank of A and, when consistent, a solution (free unknowns 0).
struct Solve {
  size_t rank = 0;
  bool consistent = false;
  std::vector<Q> x;
};
Solve solve(std::vector<std::vector<Q>> m, size_t cols) {
  Solve out;
  const size_t rows = m.size();
  std::vector<size_t> pivot_col;
  size_t r = 0;
  for (size_t c = 0; c < cols && r < rows; ++c) {
    size_t p = r;
    while (p < rows && m[p][c] == 0) ++p;
    if (p == rows) continue;
    std::swap(m[p], m[r]);
    const Q inv = 1 / m[r][c];
    for (size_t k = c; k <= cols; ++k) m[r][k] *= inv;
    for (size_t i = 0; i < rows; ++i)
      if (i != r && m[i][c] != 0) {
        const Q f = m[i][c];
        for (size_t k = c; k <= cols; ++k) m[i][k] -= f * m[r][k];
      }
    pivot_col.push_back(c);
    ++r;
  }
  out.rank = r;
  out.consistent = true;
  for (size_t i = r; i < rows; ++i)
    if (m[i][cols] != 0) out.consistent = false;
  if (out.consistent) {
    out.x.assign(cols, 0);
    for (size_t i = 0; i < r; ++i) out.x[pivot_col[i]] = m[i][cols];
  }
  return out;
}

std::string q_text(const Q& q) {
  if (q.get_den() == 1) return q.get_num().get_str();
  return "(" + q.get_num().get_str() + "/" + q.get_den().get_str() + ")";
}

std::vector<uint32_t> classes(const GraphScheme& g, DimMask mask) {
  std::vector<uint32_t> p(g.size());
  std::iota(p.begin(), p.end(), 0u);
  std::function<uint32_t(uint32_t)> find = [&](uint32_t x) {
    return p[x] == x ? x : p[x] = find(p[x]);
  };
  for (const auto& a : g.arcs)
    if (mask >> a.dim & 1u) p[std::max(find(a.a), find(a.b))] = std::min(find(a.a), find(a.b));
  for (uint32_t v = 0; v < g.size(); ++v) p[v] = find(v);
  return p;
}

}  // namespace

ExpressionInference infer_expressions(const RuleScheme& s, const EmbeddedMap& before,
                                      const std::vector<Dart>& hooks, const EmbeddedMap& after,
                                      const std::string& embedding) {
  const EmbeddingField* fb = before.find(embedding);
  const EmbeddingField* fa = after.find(embedding);
  if (!fb || !fa)
    throw Error(ErrorCode::Usage, "both objects need the embedding '" + embedding + "'",
                "embedding");
  const OrbitType pos_orbit = fb->orbit();
  const DimMask mask = pos_orbit.mask();
  // 1. The associated darts: the scheme applied to a copy of G gives H.
  Map g = before.map;
  const SchemeApplication app = scheme::apply(SchemeEngine(s), g, hooks);
  if (!app)
    throw Error(ErrorCode::Usage, "the scheme does not apply to the object before: " + app.why,
                "scheme " + s.name);
  bool same = g.capacity() == after.map.capacity() && g.dimension() == after.map.dimension();
  for (Dart d = 0; same && d < g.capacity(); ++d) {
    same = g.alive(d) == after.map.alive(d);
    for (int i = 0; same && g.alive(d) && i <= g.dimension(); ++i)
      same = g.alpha(i, d) == after.map.alpha(i, d);
  }
  if (!same)
    throw Error(ErrorCode::Usage,
                "the object after is not the scheme's result on the object before (dart for dart)",
                "scheme " + s.name);
  const Map& G = before.map;
  const size_t sz = app.orbit_size();
  const int n = G.dimension();
  // Points of interest (Table 8.1's representatives): <>, <0>, <0,1>, ..., <0..n>.
  std::vector<OrbitType> pois;
  for (int k = 0; k <= n + 1; ++k)
    pois.push_back(k == 0 ? OrbitType{} : OrbitType::range(0, k - 1));
  const std::vector<uint32_t> vertex = orbit_ids(G, mask);
  std::vector<Vec> vertex_pos(*std::max_element(vertex.begin(), vertex.end()) + 1);
  for (Dart d = 0; d < G.capacity(); ++d)
    if (G.alive(d) && fb->values.has(d)) {
      const Vec3& p = fb->values.get(d);
      vertex_pos[vertex[d]] = {rationalize(p[0]), rationalize(p[1]), rationalize(p[2])};
    }
  auto poi = [&](const OrbitType& o, Dart d) {
    std::vector<uint32_t> seen;
    Vec sum{0, 0, 0};
    for (Dart x : orbit(G, o, d))
      if (std::find(seen.begin(), seen.end(), vertex[x]) == seen.end()) {
        seen.push_back(vertex[x]);
        for (size_t c = 0; c < 3; ++c) sum[c] += vertex_pos[vertex[x]][c];
      }
    for (auto& c : sum) c /= static_cast<long>(seen.size());
    return sum;
  };
  auto after_value = [&](Dart d) {
    const Vec3& p = fa->values.get(d);
    return Vec{rationalize(p[0]), rationalize(p[1]), rationalize(p[2])};
  };
  // L class representatives.
  const auto lc = classes(s.left, mask);
  std::vector<uint32_t> reps;
  for (uint32_t v = 0; v < s.left.size(); ++v)
    if (lc[v] == v) reps.push_back(v);
  // Columns: (rep, poi) values per orbit dart, computed once.
  struct Column {
    uint32_t rep;
    size_t poi;
    std::vector<Vec> value;  // per b
  };
  std::vector<Column> columns;
  for (uint32_t r : reps)
    for (size_t p = 0; p < pois.size(); ++p) {
      Column c{r, p, {}};
      for (uint32_t b = 0; b < sz; ++b) c.value.push_back(poi(pois[p], app.match_at(r, b)));
      columns.push_back(std::move(c));
    }
  const auto rc = classes(s.right, mask);
  std::vector<bool> solved(s.right.size(), false);
  ExpressionInference out;
  out.scheme = s;
  if (!out.scheme.find_embedding(embedding))
    out.scheme.embeddings.push_back({embedding, pos_orbit, "point"});
  const auto sigs = expr::embedding_signatures(out.scheme);
  const auto ctx = expr::check_context(out.scheme, sigs);
  const expr::EmbeddingSignature* sig = nullptr;
  for (const auto& x : sigs)
    if (x.name == embedding) sig = &x;
  out.nodes.resize(s.right.size());
  auto solve_class = [&](uint32_t v) {
    for (uint32_t w = 0; w < s.right.size(); ++w)
      if (rc[w] == rc[v]) solved[w] = true;
  };
  // Step 1: kept values.
  for (uint32_t v = 0; v < s.right.size(); ++v) {
    out.nodes[v].node = s.right.nodes[v].name;
    const auto l = s.left_of(v);
    if (!l) continue;
    bool kept = true;
    for (uint32_t b = 0; b < sz && kept; ++b)
      kept = after_value(app.comatch_at(v, b)) == poi(OrbitType{}, app.match_at(*l, b));
    if (kept) {
      out.nodes[v].status = InferredExpression::Status::Kept;
      solve_class(v);
    }
  }
  // Step 3: one system per unsolved node.
  for (uint32_t v = 0; v < s.right.size(); ++v) {
    InferredExpression& res = out.nodes[v];
    if (res.status == InferredExpression::Status::Kept) continue;
    if (solved[v]) {
      res.status = InferredExpression::Status::Inherited;
      continue;
    }
    solve_class(v);  // "regardless of the existence of a solution" (§8.2.3)
    std::vector<Vec> y;
    for (uint32_t b = 0; b < sz; ++b) y.push_back(after_value(app.comatch_at(v, b)));
    const size_t rows = 3 * sz;
    auto system = [&](const std::vector<size_t>& cols, bool translation) {
      const size_t nc = cols.size() + (translation ? 3 : 0);
      std::vector<std::vector<Q>> m(rows, std::vector<Q>(nc + 1, 0));
      for (uint32_t b = 0; b < sz; ++b)
        for (size_t c = 0; c < 3; ++c) {
          auto& row = m[3 * b + c];
          for (size_t k = 0; k < cols.size(); ++k) row[k] = columns[cols[k]].value[b][c];
          if (translation) row[cols.size() + c] = 1;
          row[nc] = y[b][c];
        }
      return std::make_pair(m, nc);
    };
    std::vector<size_t> all(columns.size());
    std::iota(all.begin(), all.end(), 0);
    {
      auto [m, nc] = system(all, true);
      const Solve full = solve(m, nc);
      res.rank = full.rank;
      res.unknowns = nc;
      res.equations = rows;
      res.unique = full.rank == nc;
      if (!full.consistent) continue;  // NoSolution
    }
    // Sparsest solution first, as an expression of mass 1.
    std::vector<size_t> support;
    std::function<bool(size_t, size_t, bool)> search = [&](size_t start, size_t left,
                                                           bool translation) -> bool {
      if (left == 0) {
        auto [m, nc] = system(support, translation);
        const Solve sol = solve(m, nc);
        if (!sol.consistent) return false;
        Q mass = 0;
        for (size_t k = 0; k < support.size(); ++k) mass += sol.x[k];
        if (mass != 1 && !(translation && mass == 0)) return false;
        std::string code;
        for (size_t k = 0; k < support.size(); ++k) {
          if (sol.x[k] == 0) continue;
          const Column& c = columns[support[k]];
          const std::string node = s.left.nodes[c.rep].name;
          const std::string term =
              c.poi == 0 ? node + ".position"
                         : "middle(" + pois[c.poi].str() + "_" + embedding + "(" + node + "))";
          code += (code.empty() ? "" : " + ") +
                  (sol.x[k] == 1 ? term : q_text(sol.x[k]) + " * " + term);
        }
        if (translation) {
          const std::string t = q_text(sol.x[support.size()]) + ", " +
                                q_text(sol.x[support.size() + 1]) + ", " +
                                q_text(sol.x[support.size() + 2]);
          code = mass == 0 ? (code.empty() ? "" : code + " + ") + "point(" + t + ")"
                           : code + " + vector(" + t + ")";
        }
        if (code.empty()) return false;
        try {
          expr::compile_expression(code, *sig, ctx, "");
        } catch (const Error&) {
          return false;
        }
        res.code = code;
        return true;
      }
      for (size_t k = start; k < columns.size(); ++k) {
        support.push_back(k);
        if (search(k + 1, left - 1, translation)) return true;
        support.pop_back();
      }
      return false;
    };
    bool found = false;
    for (bool translation : {false, true})
      for (size_t k = translation ? 0 : 1; k <= 3 && !found; ++k) {
        support.clear();
        found = search(0, k, translation);
      }
    if (!found) continue;
    res.status = InferredExpression::Status::Solved;
    auto& exprs = out.scheme.right.nodes[v].expressions;
    exprs.erase(std::remove_if(exprs.begin(), exprs.end(),
                               [&](const auto& x) { return x.embedding == embedding; }),
                exprs.end());
    exprs.push_back({embedding, res.code, {}, {}});
  }
  return out;
}

}  // namespace gmr::inference
