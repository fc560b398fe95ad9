#include "model/validity.hpp"

namespace gmr {

const char* to_string(ViolationKind k) {
  switch (k) {
    case ViolationKind::DanglingLink: return "incident-arcs";
    case ViolationKind::NotInvolution: return "non-orientation";
    case ViolationKind::NotPermutation: return "incident-arcs";
    case ViolationKind::Cycle: return "cycle";
  }
  return "?";
}

std::string Violation::describe() const {
  std::string s = std::string(to_string(kind)) + " at dart " + std::to_string(dart) + ": ";
  switch (kind) {
    case ViolationKind::DanglingLink:
      s += "its " + std::to_string(i) + "-link targets " + std::to_string(path.back()) +
           ", which is not a dart";
      break;
    case ViolationKind::NotInvolution:
      s += "alpha_" + std::to_string(i) + " is not an involution: " + std::to_string(path[0]) +
           " -> " + std::to_string(path[1]) + " -> " + std::to_string(path[2]);
      break;
    case ViolationKind::NotPermutation:
      s += "dart is the target of several 1-arcs (beta_1 not a permutation), from " +
           std::to_string(path[0]) + " and " + std::to_string(path[1]);
      break;
    case ViolationKind::Cycle: {
      s += "the " + std::to_string(i) + std::to_string(j) + std::to_string(i) + std::to_string(j) +
           "-path does not close:";
      for (Dart d : path) s += " " + std::to_string(d);
      break;
    }
  }
  return s;
}

ValidityReport check_validity(const GMap& g, size_t limit) {
  ValidityReport r;
  auto add = [&](Violation v) {
    if (r.violations.size() < limit) r.violations.push_back(std::move(v));
    else ++r.truncated;
  };
  const int lo = g.lowest_dim(), n = g.dimension();
  // A dimension is usable for the cycle check only if all its links are in range.
  std::vector<bool> dim_ok(static_cast<size_t>(n) + 1, true);
  for (int i = lo; i <= n; ++i) {
    const auto& l = g.links(i);
    const bool invol = g.is_involutive_dim(i);
    g.for_each_dart([&](Dart d) {
      const Dart e = l[d];
      if (!g.alive(e)) {
        dim_ok[i] = false;
        add({ViolationKind::DanglingLink, d, i, -1, {d, e}});
        return;
      }
      if (invol && l[e] != d) add({ViolationKind::NotInvolution, d, i, -1, {d, e, l[e]}});
    });
    if (!invol && dim_ok[i]) {
      // beta_1 must be a permutation: every dart has exactly one incoming 1-arc.
      std::vector<Dart> from(g.capacity(), kNoDart);
      g.for_each_dart([&](Dart d) {
        const Dart e = l[d];
        if (from[e] != kNoDart) add({ViolationKind::NotPermutation, e, i, -1, {from[e], d}});
        else from[e] = d;
      });
    }
  }
  for (int i = lo; i <= n; ++i) {
    for (int j = i + 2; j <= n; ++j) {
      if (!dim_ok[i] || !dim_ok[j]) continue;
      const auto& li = g.links(i);
      const auto& lj = g.links(j);
      g.for_each_dart([&](Dart d) {
        const Dart a = li[d], b = lj[a], c = li[b], e = lj[c];
        if (e != d) add({ViolationKind::Cycle, d, i, j, {d, a, b, c, e}});
      });
    }
  }
  return r;
}

bool is_valid(const GMap& g) { return check_validity(g, 0).ok(); }

}  // namespace gmr
