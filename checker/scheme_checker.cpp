#include "checker/scheme_checker.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string_view>
#include <unordered_map>

#include "checker/embedding_check.hpp"
#include "model/words/word_rewriting.hpp"

namespace gmr::checker {
using namespace gmr::scheme;
using words::RewritingSystem;

std::vector<int> gmap_word_normal_form(int n, const std::vector<int>& w) {
  std::vector<int> out;
  for (const words::Letter& l : RewritingSystem::gmap(n).normal_form(words::word_of_dims(w)))
    out.push_back(l.dim);
  return out;
}

namespace {

// The (i,j)-core of one side: per node and label, the out-arc (target, W-letter or -1 for ε).
struct CoreArc {
  bool exists = false;
  uint32_t target = 0;
  int letter = -1;
};

class Checker {
 public:
  Checker(const RuleScheme& s, const SchemeCheckOptions& opt) : s_(s), opt_(opt) {
    rep_.subject = CheckSubject::Scheme;
    rep_.rule = s.name;
    rep_.n = s.dimension;
    index_nodes();
  }

  CheckReport run() {
    const bool structure_ok = structure();
    rep_.conditions.emplace_back("structure", structure_ok);
    rep_.conditions.emplace_back("hooks", hooks());
    if (!structure_ok) return std::move(rep_);
    for (int d = 0; d <= s_.dimension; ++d)
      rep_.conditions.emplace_back(condition_text(symbol(Constraint::IncidentArcs), d),
                                   incident(d));
    for (int d = 0; d <= s_.dimension; ++d)
      rep_.conditions.emplace_back(condition_text(symbol(Constraint::NonOrientation), d), true);
    for (int i = 0; i <= s_.dimension; ++i)
      for (int j = i + 2; j <= s_.dimension; ++j)
        rep_.conditions.emplace_back(condition_text(symbol(Constraint::Cycle), i, j), cycle(i, j));
    bool has_expressions = !s_.embeddings.empty();
    for (const auto& n : s_.right.nodes) has_expressions |= !n.expressions.empty();
    if (has_expressions && opt_.embeddings)
      rep_.conditions.emplace_back("embeddings", check_embeddings(s_, rep_.diagnostics));
    if (!s_.precondition.empty())
      add("S-precondition", Severity::Warning, "structure", std::nullopt, {},
          "the Jerboa precondition is not evaluated; the verdict is about the topology only");
    for (uint32_t v = 0; v < s_.left.size(); ++v)
      if (!right_of(v) && !s_.left.nodes[v].expressions.empty())
        add("S-left-expression", Severity::Warning, "structure", Side::L, {s_.left.nodes[v].name},
            "embedding expression on a deleted node (ignored)");
    return std::move(rep_);
  }

 private:
  Diagnostic& add(std::string code, Severity sev, std::string cond, std::optional<Side> side,
                  std::vector<std::string> nodes, std::string msg) {
    rep_.diagnostics.push_back(Diagnostic{.code = std::move(code),
                                          .severity = sev,
                                          .condition = std::move(cond),
                                          .side = side,
                                          .nodes = std::move(nodes),
                                          .message = std::move(msg)});
    return rep_.diagnostics.back();
  }
  const GraphScheme& side(Side r) const { return r == Side::R ? s_.right : s_.left; }

  // Node tables built once, so that the checker stays linear in the size of the scheme (inferred
  // schemes have thousands of nodes): the preserved counterpart of every node (by name), and the
  // number of d-arcs at every node (GraphScheme::count_arcs: explicit arcs, a loop once, plus label
  // positions), arcs with a node or dimension out of range left out (reported by structure()).
  static constexpr uint32_t kNone = UINT32_MAX;
  std::vector<uint32_t> counterpart_[2];
  std::vector<uint32_t> arc_count_[2];
  void index_nodes() {
    const auto dims = static_cast<size_t>(std::max(s_.dimension, 0)) + 1;
    std::unordered_map<std::string_view, uint32_t> right_index;
    for (uint32_t v = 0; v < s_.right.size(); ++v) right_index.emplace(s_.right.nodes[v].name, v);
    counterpart_[0].assign(s_.left.size(), kNone);
    counterpart_[1].assign(s_.right.size(), kNone);
    for (uint32_t v = 0; v < s_.left.size(); ++v)
      if (auto it = right_index.find(s_.left.nodes[v].name); it != right_index.end()) {
        counterpart_[0][v] = it->second;
        if (counterpart_[1][it->second] == kNone)
          counterpart_[1][it->second] = v;  // the first, as find()
      }
    for (Side r : graph::kSides) {
      const GraphScheme& g = side(r);
      auto& count = arc_count_[index_of(r)];
      count.assign(g.size() * dims, 0);
      auto in_range = [&](int d) { return d >= 0 && static_cast<size_t>(d) < dims; };
      for (const auto& e : g.arcs) {
        if (!in_range(e.dim) || e.a >= g.size() || e.b >= g.size()) continue;
        ++count[e.a * dims + static_cast<size_t>(e.dim)];
        if (e.b != e.a) ++count[e.b * dims + static_cast<size_t>(e.dim)];
      }
      for (uint32_t v = 0; v < g.size(); ++v)
        for (int x : g.nodes[v].label.dims())
          if (in_range(x)) ++count[v * dims + static_cast<size_t>(x)];
    }
  }
  std::optional<uint32_t> right_of(uint32_t v) const {
    return counterpart_[0][v] == kNone ? std::nullopt : std::optional<uint32_t>(counterpart_[0][v]);
  }
  std::optional<uint32_t> left_of(uint32_t v) const {
    return counterpart_[1][v] == kNone ? std::nullopt : std::optional<uint32_t>(counterpart_[1][v]);
  }
  size_t count_arcs(Side r, uint32_t v, int d) const {
    const auto dims = static_cast<size_t>(std::max(s_.dimension, 0)) + 1;
    return arc_count_[index_of(r)][v * dims + static_cast<size_t>(d)];
  }

  // ---------------------------------------------------------------------------------------------
  bool structure() {
    bool ok = true;
    const int n = s_.dimension;
    std::set<int> seen;
    bool orbit_ok = true;
    for (int x : s_.orbit.dims())
      if (x == OrbitType::kHole || x < 0 || x > n || !seen.insert(x).second) orbit_ok = false;
    if (!orbit_ok) {
      add("S-orbit", Severity::Error, "structure", std::nullopt, {},
          "the rule's orbit type " + s_.orbit.str() + " must list distinct dimensions of 0.." +
              std::to_string(n) + " without `_`");
      ok = false;
    }
    for (Side r : graph::kSides) {
      const GraphScheme& g = side(r);
      std::map<std::string, int> names;
      for (uint32_t v = 0; v < g.size(); ++v) {
        const SchemeNode& nd = g.nodes[v];
        if (++names[nd.name] == 2) {
          add("S-duplicate-name", Severity::Error, "structure", r, {nd.name},
              "two nodes named " + nd.name + " in " + to_string(r));
          ok = false;
        }
        if (nd.label.size() != s_.orbit.size()) {
          add("S-label-arity", Severity::Error, "structure", r, {nd.name},
              "label " + nd.label.str() + " has arity " + std::to_string(nd.label.size()) +
                  ", the orbit type " + s_.orbit.str() + " has " + std::to_string(s_.orbit.size()));
          ok = false;
        }
        for (int x : nd.label.dims())
          if (x != OrbitType::kHole && (x < 0 || x > n)) {
            add("S-dim-range", Severity::Error, "structure", r, {nd.name},
                "label " + nd.label.str() + " uses dimension " + std::to_string(x) +
                    " outside 0.." + std::to_string(n));
            ok = false;
          }
      }
      for (const auto& e : g.arcs) {
        if (e.a >= g.size() || e.b >= g.size()) {
          add("S-dim-range", Severity::Error, "structure", r, {}, "arc end out of range");
          ok = false;
          continue;
        }
        if (e.dim < 0 || e.dim > n) {
          auto& d =
              add("S-dim-range", Severity::Error, "structure", r,
                  {g.nodes[e.a].name, g.nodes[e.b].name},
                  "arc dimension " + std::to_string(e.dim) + " outside 0.." + std::to_string(n));
          d.arcs = {arc_text(g, e)};
          ok = false;
        }
      }
      if (!ok) continue;
      for (uint32_t v = 0; v < g.size(); ++v)
        for (int d = 0; d <= n; ++d) {
          const size_t c = count_arcs(r, v, d);
          if (c > 1) {
            add("S-dim-twice", Severity::Error, "structure", r, {g.nodes[v].name},
                "dimension " + std::to_string(d) + " is used " + std::to_string(c) + " times at " +
                    node_label_text(g.nodes[v]) + " (label positions and explicit arcs)" +
                    (r == Side::R ? "" : ": no match into a G-map exists (E1)"));
            ok = false;
          }
        }
    }
    return ok;
  }

  static std::string arc_text(const GraphScheme& g, const SchemeArc& e) {
    return g.nodes[e.a].name + " -" + std::to_string(e.dim) + "- " + g.nodes[e.b].name;
  }

  bool hooks() {
    bool ok = true;
    std::vector<uint32_t> comp;
    const size_t k = s_.left.components(comp);
    std::vector<std::vector<std::string>> hooks_of(k);
    for (size_t h = 0; h < s_.hooks.size(); ++h) {
      auto v = s_.left.find(s_.hooks[h]);
      if (!v) {
        add("S-no-hook", Severity::Error, "hooks", Side::L, {s_.hooks[h]},
            "hook " + s_.hooks[h] + " is not an L node");
        ok = false;
        continue;
      }
      hooks_of[comp[*v]].push_back(s_.hooks[h]);
      const OrbitType& lab = s_.left.nodes[*v].label;
      if (lab.has_hole()) {
        add("S-hook-hole", Severity::Error, "hooks", Side::L, {s_.hooks[h]},
            "hook " + node_label_text(s_.left.nodes[*v]) + " has `_` in its label");
        ok = false;
      } else if (h == 0 && lab != s_.orbit) {
        add("S-hook-orbit", Severity::Error, "hooks", Side::L, {s_.hooks[h]},
            "the reference hook's label " + lab.str() + " differs from the rule's orbit type " +
                s_.orbit.str());
        ok = false;
      }
    }
    for (size_t c = 0; c < k; ++c) {
      std::vector<std::string> members;
      for (uint32_t v = 0; v < s_.left.size(); ++v)
        if (comp[v] == c) members.push_back(s_.left.nodes[v].name);
      if (hooks_of[c].empty()) {
        add("S-no-hook", Severity::Error, "hooks", Side::L, members,
            "connected component {" + join(members) + "} of L has no hook");
        ok = false;
      } else if (hooks_of[c].size() > 1) {
        add("S-several-hooks", Severity::Error, "hooks", Side::L, hooks_of[c],
            "connected component {" + join(members) + "} of L has " +
                std::to_string(hooks_of[c].size()) + " hooks (" + join(hooks_of[c]) + ")");
        ok = false;
      }
    }
    return ok;
  }

  static std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (size_t k = 0; k < v.size(); ++k) s += (k ? ", " : "") + v[k];
    return s;
  }

  // ---------------------------------------------------------------------------------------------
  bool incident(int d) {
    bool ok = true;
    const std::string cond = condition_text(symbol(Constraint::IncidentArcs), d);
    const std::string ds = std::to_string(d);
    for (uint32_t v = 0; v < s_.left.size(); ++v) {
      const size_t cl = count_arcs(Side::L, v, d);
      const std::string& nm = s_.left.nodes[v].name;
      if (cl > 1) {
        ok = false;  // reported as S-dim-twice
        continue;
      }
      if (auto r = right_of(v)) {
        const size_t cr = count_arcs(Side::R, *r, d);
        if (cr > 1) {
          ok = false;
          continue;
        }
        if (cr != cl) {
          add("I-preserved-node", Severity::Error, cond, cl ? Side::L : Side::R, {nm},
              "preserved node " + nm +
                  (cl ? " has a " + ds + "-arc in L but none in R"
                      : " gains a " + ds + "-arc in R it does not have in L") +
                  " (E2): its instances would have " + (cl ? "no " : "two ") + ds + "-links");
          ok = false;
        }
      } else if (cl != 1) {
        add("I-deleted-node", Severity::Error, cond, Side::L, {nm},
            "deleted node " + nm + " has no " + ds +
                "-arc in L (E3, gluing condition): the links of its darts "
                "outside the match would dangle, so the rule never applies");
        ok = false;
      }
    }
    for (uint32_t v = 0; v < s_.right.size(); ++v) {
      if (left_of(v)) continue;
      const size_t cr = count_arcs(Side::R, v, d);
      if (cr == 0) {
        add("I-added-node", Severity::Error, cond, Side::R, {s_.right.nodes[v].name},
            "added node " + s_.right.nodes[v].name + " has no " + ds + "-arc in R (E4)");
        ok = false;
      } else if (cr > 1) {
        ok = false;  // S-dim-twice
      }
    }
    return ok;
  }

  // ---------------------------------------------------------------------------------------------
  // (i,j)-core of a side.
  std::vector<std::array<CoreArc, 2>> core(Side r, int i, int j) const {
    const GraphScheme& g = side(r);
    std::vector<std::array<CoreArc, 2>> out(g.size());
    const int lab[2] = {i, j};
    // Label positions first, then explicit arcs in order (the last one wins, as in a per-node
    // scan).
    for (uint32_t v = 0; v < g.size(); ++v)
      for (int k = 0; k < 2; ++k)
        for (size_t p = 0; p < g.nodes[v].label.size(); ++p)
          if (g.nodes[v].label[p] == lab[k]) out[v][k] = CoreArc{true, v, s_.orbit[p]};
    for (const auto& e : g.arcs)
      for (int k = 0; k < 2; ++k)
        if (e.dim == lab[k]) {
          out[e.a][k] = CoreArc{true, e.b, -1};
          out[e.b][k] = CoreArc{true, e.a, -1};
        }
    return out;
  }

  struct SideData {
    std::vector<std::array<CoreArc, 2>> core;
    std::vector<std::array<bool, 2>> changed;   // out-arc deleted (L) / added (R)
    std::vector<std::array<bool, 2>> on_cycle;  // on an alternating cycle of length 2 or 4
    std::vector<std::array<bool, 2>> on_path;   // on an optimal path
    struct Path {
      std::vector<std::pair<uint32_t, int>> arcs;  // (source node, label index)
      uint32_t src, tgt;
      std::vector<int> labels, word;
    };
    std::vector<Path> paths;
  };

  // Is `this_arc` (an out-arc on side `this_side`, towards the node named tgt_name) preserved, i.e.
  // is `other_arc` (the same node's out-arc with the same label on the other side) the same arc:
  // same letter and a target of the same name, the target name being read on the other side.
  bool same_arc(const CoreArc& other_arc, const std::string& tgt_name, const CoreArc& this_arc,
                Side this_side) const {
    return other_arc.exists && this_arc.exists && other_arc.letter == this_arc.letter &&
           side(other(this_side)).nodes[other_arc.target].name == tgt_name;
  }

  // C_S(i,j) is evaluated on simple (i,j)-cores only: a node with two i- or j-arcs (already an
  // S-dim-twice error) is reported as C-skipped. Returns true when skipped.
  bool has_branching(int i, int j, const std::string& cond) {
    for (Side r : graph::kSides)
      for (uint32_t v = 0; v < side(r).size(); ++v)
        if (count_arcs(r, v, i) > 1 || count_arcs(r, v, j) > 1) {
          add("C-skipped", Severity::Note, cond, r, {side(r).nodes[v].name},
              cond + " not evaluated: a node has two " + std::to_string(i) + "- or " +
                  std::to_string(j) + "-arcs");
          return true;
        }
    return false;
  }

  // The (i,j)-cores of L and R, and which of their arcs are changed (deleted in L, added in R): an
  // arc is preserved iff the same node has an arc with the same label, letter and target name on
  // the other side (Def. 46).
  void cores_and_changed_arcs(SideData (&sd)[2], int i, int j) const {
    for (Side r : graph::kSides) sd[index_of(r)].core = core(r, i, j);
    for (Side r : graph::kSides) {
      const GraphScheme& g = side(r);
      sd[index_of(r)].changed.assign(g.size(), {false, false});
      sd[index_of(r)].on_cycle.assign(g.size(), {false, false});
      sd[index_of(r)].on_path.assign(g.size(), {false, false});
      for (uint32_t v = 0; v < g.size(); ++v) {
        const auto counterpart = r == Side::L ? right_of(v) : left_of(v);
        for (int k = 0; k < 2; ++k) {
          const CoreArc& a = sd[index_of(r)].core[v][k];
          if (!a.exists) continue;
          const bool preserved =
              counterpart &&
              same_arc(sd[index_of(other(r))].core[*counterpart][k], g.nodes[a.target].name, a, r);
          sd[index_of(r)].changed[v][k] = !preserved;
        }
      }
    }
  }

  // Alternating (i,j)-cycles of each side (Alg. 3): length in {2,4} (E10) and a W-word whose
  // normal form under R_{N,E} (Def. 52) is ε (E11). Marks the arcs on cycles.
  bool check_alternating_cycles(SideData (&sd)[2], int i, int j, const std::string& cond) {
    const int lab[2] = {i, j};
    bool ok = true;
    std::set<std::string> reported;
    for (Side r : graph::kSides) {
      const GraphScheme& g = side(r);
      const auto& c = sd[index_of(r)].core;
      for (uint32_t v = 0; v < g.size(); ++v)
        for (int k0 = 0; k0 < 2; ++k0) {
          // Walk alternately from v, first label k0, until return at an even step or dead end.
          uint32_t x = v;
          int k = k0;
          size_t steps = 0;
          bool closed = false;
          const size_t limit = 2 * g.size() + 4;
          std::vector<uint32_t> nodes{v};
          while (steps < limit) {
            if (!c[x][k].exists) break;
            x = c[x][k].target;
            k = 1 - k;
            ++steps;
            if (x == v && steps % 2 == 0) {
              closed = true;
              break;
            }
            nodes.push_back(x);
          }
          if (!closed) continue;
          std::vector<std::string> names;
          for (uint32_t y : nodes) names.push_back(g.nodes[y].name);
          if (steps != 2 && steps != 4) {
            std::vector<std::string> key = names;
            std::sort(key.begin(), key.end());
            if (reported.insert("len" + std::string(to_string(r)) + join(key)).second) {
              auto& d = add("C-cycle-length", Severity::Error, cond, r, names,
                            "alternating (" + std::to_string(i) + "," + std::to_string(j) +
                                ")-cycle of length " + std::to_string(steps) + " through " +
                                join(names) + " (E10): its instances cannot be ijij-cycles");
              d.path = names;
            }
            ok = false;
            continue;
          }
          // The full ijij traversal (length-2 cycles twice), marking arcs and reading the word.
          std::vector<int> word;
          x = v;
          k = k0;
          for (int t = 0; t < 4; ++t) {
            sd[index_of(r)].on_cycle[x][k] = true;
            if (c[x][k].letter >= 0) word.push_back(c[x][k].letter);
            x = c[x][k].target;
            k = 1 - k;
          }
          if (!gmap_word_normal_form(s_.dimension, word).empty()) {
            std::vector<std::string> key = names;
            std::sort(key.begin(), key.end());
            if (reported.insert("word" + std::string(to_string(r)) + join(key)).second) {
              auto& d = add("C-cycle-word", Severity::Error, cond, r, names,
                            "the (" + std::to_string(lab[k0]) + "," + std::to_string(lab[1 - k0]) +
                                ")-cycle through " + join(names) + " reads the word " +
                                word_text(word) + ", whose normal form " +
                                word_text(gmap_word_normal_form(s_.dimension, word)) +
                                " is not ε (E11): its instances do not close");
              d.path = names;
            }
            ok = false;
          }
        }
    }
    return ok;
  }

  // The (i,j)-optimal paths of each side (Def. 39): maximal alternating chains of changed arcs, not
  // overlapping, not made of cycle arcs only. Marks the arcs on optimal paths.
  void collect_optimal_paths(SideData (&sd)[2], int i, int j) const {
    const int lab[2] = {i, j};
    for (Side r : graph::kSides) {
      const auto& c = sd[index_of(r)].core;
      const auto& ch = sd[index_of(r)].changed;
      const size_t nv = c.size();
      auto has_pred = [&](uint32_t v, int k) {
        // in-arc of v with the other label = reverse of the out-arc (v, 1-k)
        const CoreArc& o = c[v][1 - k];
        if (!o.exists) return false;
        const uint32_t u = o.target;
        return c[u][1 - k].exists && c[u][1 - k].target == v && ch[u][1 - k];
      };
      for (uint32_t v = 0; v < nv; ++v)
        for (int k = 0; k < 2; ++k) {
          if (!c[v][k].exists || !ch[v][k] || has_pred(v, k)) continue;
          SideData::Path p;
          p.src = v;
          std::set<std::pair<uint32_t, int>> used;
          uint32_t x = v;
          int kk = k;
          while (c[x][kk].exists && ch[x][kk] && !used.count({x, kk})) {
            used.insert({x, kk});
            p.arcs.push_back({x, kk});
            p.labels.push_back(lab[kk]);
            if (c[x][kk].letter >= 0) p.word.push_back(c[x][kk].letter);
            x = c[x][kk].target;
            kk = 1 - kk;
          }
          p.tgt = x;
          bool all_on_cycles = true;
          for (auto [y, l] : p.arcs)
            all_on_cycles = all_on_cycles && sd[index_of(r)].on_cycle[y][l];
          if (all_on_cycles) continue;
          for (auto [y, l] : p.arcs) sd[index_of(r)].on_path[y][l] = true;
          sd[index_of(r)].paths.push_back(std::move(p));
        }
    }
  }

  // Strong coherence (Def. 40.1, Def. 55): every optimal path has exactly one coherent optimal path
  // on the other side (E8) and their W-words are congruent (E9).
  bool check_strong_coherence(const SideData (&sd)[2], int i, int j, const std::string& cond) {
    bool ok = true;
    for (Side r : graph::kSides) {
      const GraphScheme& g = side(r);
      const GraphScheme& h = side(other(r));
      for (const auto& p : sd[index_of(r)].paths) {
        std::vector<const SideData::Path*> partners;
        for (const auto& q : sd[index_of(other(r))].paths)
          if (h.nodes[q.src].name == g.nodes[p.src].name &&
              h.nodes[q.tgt].name == g.nodes[p.tgt].name && q.labels == p.labels)
            partners.push_back(&q);
        std::vector<std::string> names{g.nodes[p.src].name};
        for (size_t t = 0; t < p.arcs.size(); ++t)
          names.push_back(g.nodes[c_target(sd[index_of(r)], p.arcs[t])].name);
        std::string lw;
        for (int l : p.labels) lw += std::to_string(l);
        const std::string what = "the (" + std::to_string(i) + "," + std::to_string(j) +
                                 ")-optimal path " + join(names) + " of " + to_string(r) +
                                 " (labels " + lw + ")";
        if (partners.size() != 1) {
          auto& d =
              add(partners.empty() ? "C-incoherent" : "C-ambiguous", Severity::Error, cond, r,
                  {g.nodes[p.src].name, g.nodes[p.tgt].name},
                  what +
                      (partners.empty()
                           ? " has no coherent optimal path in " + std::string(to_string(other(r)))
                           : " has " + std::to_string(partners.size()) +
                                 " coherent optimal paths in " + to_string(other(r))) +
                      " (E8): some instance of an ijij-cycle through it is broken");
          d.path = names;
          ok = false;
        } else if (gmap_word_normal_form(s_.dimension, p.word) !=
                   gmap_word_normal_form(s_.dimension, partners[0]->word)) {
          auto& d =
              add("C-word", Severity::Error, cond, r, {g.nodes[p.src].name, g.nodes[p.tgt].name},
                  what + " reads the word " + word_text(p.word) + ", its partner " +
                      word_text(partners[0]->word) +
                      ": not congruent (E9), the instances end at different darts");
          d.path = names;
          ok = false;
        }
      }
    }
    return ok;
  }

  // Def. 40.2 and 40.3 (E12, E13): a preserved node with a deleted i-arc (j-arc) — any i-arc with
  // algorithm3_strict, Alg. 3 lines 24–27 — and an added node have their i-arc (j-arc) of R on an
  // alternating cycle or an optimal path.
  bool check_changed_nodes_covered(const SideData (&sd)[2], int i, int j, const std::string& cond) {
    const int lab[2] = {i, j};
    bool ok = true;
    for (uint32_t v = 0; v < s_.right.size(); ++v) {
      auto l = left_of(v);
      for (int k = 0; k < 2; ++k) {
        bool concerned;
        if (l) {
          const CoreArc& la = sd[0].core[*l][k];
          concerned = la.exists && (opt_.algorithm3_strict || sd[0].changed[*l][k]);
        } else {
          concerned = true;
        }
        if (!concerned) continue;
        const CoreArc& ra = sd[1].core[v][k];
        if (ra.exists && (sd[1].on_cycle[v][k] || sd[1].on_path[v][k])) continue;
        const std::string& nm = s_.right.nodes[v].name;
        const std::string ds = std::to_string(lab[k]);
        std::string msg;
        if (!ra.exists)
          msg = "has no " + ds + "-arc in R";
        else
          msg = "gets in R a " + ds + "-arc (to " + s_.right.nodes[ra.target].name +
                ") that is neither on an alternating (" + std::to_string(i) + "," +
                std::to_string(j) + ")-cycle nor on an optimal path";
        if (l)
          add("C-preserved-node", Severity::Error, cond, Side::R, {nm},
              "preserved node " + nm + (opt_.algorithm3_strict ? " with a " : " with a deleted ") +
                  ds + "-arc in L " + msg +
                  (opt_.algorithm3_strict ? " (E12, Algorithm 3)" : " (E12, Def. 40.2)"));
        else
          add("C-added-node", Severity::Error, cond, Side::R, {nm},
              "added node " + nm + " " + msg + " (E13)");
        ok = false;
      }
    }
    return ok;
  }

  // C_S(i,j), i+2 <= j (Def. 40 with Def. 55, Alg. 3), in its phases.
  bool cycle(int i, int j) {
    const std::string cond = condition_text(symbol(Constraint::Cycle), i, j);
    if (has_branching(i, j, cond)) return false;
    SideData sd[2];
    cores_and_changed_arcs(sd, i, j);
    bool ok = check_alternating_cycles(sd, i, j, cond);
    collect_optimal_paths(sd, i, j);
    ok = check_strong_coherence(sd, i, j, cond) && ok;
    ok = check_changed_nodes_covered(sd, i, j, cond) && ok;
    return ok;
  }

  static uint32_t c_target(const SideData& sd, std::pair<uint32_t, int> a) {
    return sd.core[a.first][a.second].target;
  }

  const RuleScheme& s_;
  SchemeCheckOptions opt_;
  CheckReport rep_;
};

}  // namespace

CheckReport check_scheme(const RuleScheme& s, const SchemeCheckOptions& opt) {
  return Checker(s, opt).run();
}

}  // namespace gmr::checker
