#include "model/words/word_rewriting.hpp"

#include <algorithm>
#include <cctype>
#include <deque>

#include "model/core/error.hpp"

namespace gmr::words {

PathWord conj(const PathWord& w) {
  PathWord out;
  out.reserve(w.size());
  for (auto it = w.rbegin(); it != w.rend(); ++it) out.push_back(conj(*it));
  return out;
}

PathWord concat(const PathWord& a, const PathWord& b) {
  PathWord out = a;
  out.insert(out.end(), b.begin(), b.end());
  return out;
}

PathWord word_of_dims(const std::vector<int>& dims) {
  PathWord w;
  for (int d : dims) w.push_back({d, false});
  return w;
}

PathWord parse_word(std::string_view text) {
  std::string s;
  for (char c : text)
    if (!std::isspace(static_cast<unsigned char>(c))) s += c;
  if (s.empty() || s == "eps") return {};
  PathWord w;
  bool pending = false;
  for (size_t k = 0; k < s.size(); ++k) {
    const char c = s[k];
    if (c == '~') {
      if (pending)
        throw Error(ErrorCode::Parse, "\"~~\" in a word (write the letter itself)",
                    "word \"" + std::string(text) + "\"");
      pending = true;
    } else if (c >= '0' && c <= '9') {
      w.push_back({c - '0', pending});
      pending = false;
    } else {
      throw Error(ErrorCode::Parse, std::string("unexpected character '") + c + "' in a word",
                  "word \"" + std::string(text) + "\"");
    }
  }
  if (pending)
    throw Error(ErrorCode::Parse, "\"~\" at the end of a word",
                "word \"" + std::string(text) + "\"");
  return w;
}

std::string to_string(const PathWord& w) {
  if (w.empty()) return "eps";
  std::string s;
  for (const Letter& l : w) {
    if (l.conj) s += '~';
    s += std::to_string(l.dim);
  }
  return s;
}

RewritingSystem::RewritingSystem(std::set<int> N, std::set<int> O,
                                 std::vector<std::pair<int, int>> E)
    : N_(std::move(N)), O_(std::move(O)), E_(std::move(E)) {
  for (int d : N_)
    if (O_.count(d))
      throw Error(ErrorCode::Schema,
                  "dimension " + std::to_string(d) + " is both oriented and non-oriented", "N, O");
  auto known = [&](int d) { return N_.count(d) || O_.count(d); };
  for (auto [i, j] : E_)
    if (!(i < j) || !known(i) || !known(j))
      throw Error(ErrorCode::Schema,
                  "exchangeable pair (" + std::to_string(i) + "," + std::to_string(j) +
                      ") must satisfy i < j over N ∪ O",
                  "E");
  // D̄ in the §4.6 convention: N ⊔ O ⊔ ~O.
  std::vector<Letter> letters;
  for (int d : N_) letters.push_back({d, false});
  for (int d : O_) {
    letters.push_back({d, false});
    letters.push_back({d, true});
  }
  std::set<RewriteRule> rules;
  // (i ~i, ε) for i ∈ D̄.
  for (Letter i : letters) rules.insert({{i, normalize(conj(i))}, {}});
  // (ji, ~i~j) for (i,j) ∈ (N∪O)² ∪ (N∪~O)², (||i||,||j||) ∈ E: both letters of the same
  // "polarity", N letters having both.
  for (Letter i : letters)
    for (Letter j : letters) {
      if (std::find(E_.begin(), E_.end(), std::pair{i.dim, j.dim}) == E_.end()) continue;
      const bool i_n = N_.count(i.dim) > 0, j_n = N_.count(j.dim) > 0;
      const bool plain = (i_n || !i.conj) && (j_n || !j.conj);  // (N ∪ O)²
      const bool conjd = (i_n || i.conj) && (j_n || j.conj);    // (N ∪ ~O)²
      if (!plain && !conjd) continue;
      rules.insert({{j, i}, {normalize(conj(i)), normalize(conj(j))}});
    }
  rules_.assign(rules.begin(), rules.end());
}

// N: the involutive (non-oriented) labels, O: the oriented ones, E: the cycle pairs of the kind.
RewritingSystem RewritingSystem::of(const MapSpec& spec) {
  std::set<int> N, O;
  for (int i : spec.labels()) (spec.is_involutive_dim(i) ? N : O).insert(i);
  return RewritingSystem(N, O, spec.cycle_pairs());
}

RewritingSystem RewritingSystem::gmap(int n) { return of({n, MapKind::GMap}); }

RewritingSystem RewritingSystem::omap(int n) { return of({n, MapKind::OMap}); }

Letter RewritingSystem::normalize(Letter l) const {
  if (N_.count(l.dim)) return {l.dim, false};
  if (O_.count(l.dim)) return l;
  throw Error(ErrorCode::Range, "dimension " + std::to_string(l.dim) + " is neither in N nor in O",
              "letter");
}

PathWord RewritingSystem::normalize(const PathWord& w) const {
  PathWord out;
  out.reserve(w.size());
  for (Letter l : w) out.push_back(normalize(l));
  return out;
}

const RewritingSystem::RewriteRule* RewritingSystem::rule_for(Letter a, Letter b) const {
  const PathWord lhs{normalize(a), normalize(b)};
  for (const RewriteRule& r : rules_)
    if (r.lhs == lhs) return &r;
  return nullptr;
}

namespace {
PathWord rewrite_at(const PathWord& w, size_t k, const PathWord& rhs) {
  PathWord out(w.begin(), w.begin() + static_cast<long>(k));
  out.insert(out.end(), rhs.begin(), rhs.end());
  out.insert(out.end(), w.begin() + static_cast<long>(k) + 2, w.end());
  return out;
}
}  // namespace

std::vector<PathWord> RewritingSystem::one_step(const PathWord& w0) const {
  const PathWord w = normalize(w0);
  std::vector<PathWord> out;
  for (size_t k = 0; k + 1 < w.size(); ++k)
    if (const RewriteRule* r = rule_for(w[k], w[k + 1])) out.push_back(rewrite_at(w, k, r->rhs));
  return out;
}

bool RewritingSystem::is_normal(const PathWord& w) const { return one_step(w).empty(); }

std::vector<PathWord> RewritingSystem::normal_forms(const PathWord& w) const {
  std::set<PathWord> seen{normalize(w)}, normal;
  std::deque<PathWord> todo{normalize(w)};
  while (!todo.empty()) {
    PathWord v = std::move(todo.front());
    todo.pop_front();
    const auto next = one_step(v);
    if (next.empty()) normal.insert(v);
    for (const PathWord& x : next)
      if (seen.insert(x).second) todo.push_back(x);
  }
  return {normal.begin(), normal.end()};
}

std::vector<PathWord> RewritingSystem::leftmost_derivation(const PathWord& w0) const {
  std::vector<PathWord> chain{normalize(w0)};
  for (;;) {
    const PathWord& w = chain.back();
    bool stepped = false;
    for (size_t k = 0; k + 1 < w.size(); ++k)
      if (const RewriteRule* r = rule_for(w[k], w[k + 1])) {
        chain.push_back(rewrite_at(w, k, r->rhs));
        stepped = true;
        break;
      }
    if (!stepped) return chain;
  }
}

}  // namespace gmr::words
