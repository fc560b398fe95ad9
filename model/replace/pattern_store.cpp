#include "model/replace/pattern_store.hpp"

#include <stdexcept>

#include "model/core/error.hpp"

namespace gmr::replace {

namespace {

Word key_of(CellSignature s, int cell_dim) {
  Word key = std::move(s.word);
  key.insert(key.begin(), static_cast<uint32_t>(cell_dim));
  return key;
}

}  // namespace

Word store_key(const BoundaryGraph& b, int cell_dim, Mode mode, StoreEntry* entry) {
  CellSignature s = minimal_signature(b, mode);
  if (entry) {
    entry->start = s.start;
    entry->automorphisms = s.automorphisms;
  }
  return key_of(std::move(s), cell_dim);
}

bool boundary_automorphisms_extend(const Pattern& p, Mode mode, const StoreEntry& e) {
  const BoundaryGraph& b = p.boundary;
  const Map& g = p.map.map;
  const Word best = boundary_word(b, e.start);
  const std::vector<uint32_t> ref = boundary_labeling(b, e.start);
  for (uint32_t s = 0; s < b.size(); ++s) {
    if (s == e.start || (mode == Mode::Oriented && !b.positive[s]) || boundary_word(b, s) != best)
      continue;
    // The boundary automorphism ref[k] -> order[k], extended through alpha_0..alpha_n.
    const std::vector<uint32_t> order = boundary_labeling(b, s);
    std::vector<Dart> image(g.capacity(), kNoDart);
    std::vector<Dart> stack;
    for (size_t k = 0; k < ref.size(); ++k) {
      image[b.dart[ref[k]]] = b.dart[order[k]];
      stack.push_back(b.dart[ref[k]]);
    }
    while (!stack.empty()) {
      const Dart x = stack.back();
      stack.pop_back();
      for (int i = 0; i <= g.dimension(); ++i) {
        const Dart y = g.alpha(i, x), fy = g.alpha(i, image[x]);
        if (image[y] == kNoDart) {
          image[y] = fy;
          stack.push_back(y);
        } else if (image[y] != fy) {
          return false;
        }
      }
    }
    std::vector<uint8_t> hit(g.capacity(), 0);
    bool bijective = true;
    g.for_each_dart([&](Dart x) {
      if (image[x] == kNoDart || hit[image[x]] || p.map.flag[x] != p.map.flag[image[x]])
        bijective = false;
      else
        hit[image[x]] = 1;
    });
    if (!bijective) return false;
  }
  return true;
}

void PatternStore::add(Pattern p) {
  if (mode_ == Mode::Oriented && p.positive.empty())
    throw Error(ErrorCode::Schema, "the oriented mode needs orientable patterns", p.name);
  StoreEntry e;
  e.pattern = patterns_.size();
  Word key = store_key(p.boundary, p.cell_dim, mode_, &e);
  e.ambiguous = !boundary_automorphisms_extend(p, mode_, e);
  auto& list = table_[key];
  list.push_back(e);
  const std::vector<uint32_t> ref = boundary_labeling(p.boundary, e.start);
  index_start_words(p, list, ref);
  key_of_.push_back(std::move(key));
  entries_.push_back(e);
  templates_.push_back(compile_replacement(p, e.start));
  patterns_.push_back(std::move(p));
}

// The word of every start dart q of the pattern (the first of automorphic starts only), with the
// ranks of the pattern's template order `ref` in the label order from q.
void PatternStore::index_start_words(const Pattern& p, const std::vector<StoreEntry>& list,
                                     const std::vector<uint32_t>& ref) {
  const BoundaryGraph& b = p.boundary;
  std::vector<uint32_t> order, position(b.size());
  for (uint32_t q : start_darts(b, mode_).darts) {
    Word w{static_cast<uint32_t>(p.cell_dim)};
    boundary_word(b, q, w);
    Lookup& l = lookup_[w];
    if (!l.entries) {
      l.entries = &list;
      lookup_letters_ += w.size();
    }
    // Equal words mean isomorphic boundaries, hence equal keys.
    if (l.entries != &list) throw std::logic_error("a start word of two keys: " + p.name);
    if (l.ranks.size() == list.size()) continue;  // an automorphic start of this pattern came first
    boundary_labeling(b, q, order);
    for (uint32_t k = 0; k < order.size(); ++k) position[order[k]] = k;
    std::vector<uint32_t> rank(ref.size());
    for (size_t k = 0; k < ref.size(); ++k) rank[k] = position[ref[k]];
    l.ranks.push_back(std::move(rank));
  }
}

const std::vector<StoreEntry>* PatternStore::find(const Word& key) const {
  const auto it = table_.find(key);
  return it == table_.end() ? nullptr : &it->second;
}

StoreMatch PatternStore::match(const BoundaryGraph& cell, int cell_dim) const {
  const uint32_t start = first_start_dart(cell, mode_);
  if (start == UINT32_MAX) return {};
  thread_local Word key;
  key.assign(1, static_cast<uint32_t>(cell_dim));
  boundary_word(cell, start, key);
  return match_word(key, start);
}

StoreMatch PatternStore::match_word(const Word& key, uint32_t start) const {
  const auto it = lookup_.find(key);
  if (it == lookup_.end()) return {};
  return {it->second.entries, start, &it->second.ranks};
}

std::vector<std::vector<size_t>> PatternStore::duplicates() const {
  std::vector<std::vector<size_t>> groups;
  for (size_t i = 0; i < patterns_.size(); ++i) {
    const auto& list = table_.at(key_of_[i]);
    if (list.size() > 1 && list.front().pattern == i) {
      groups.emplace_back();
      for (const StoreEntry& e : list) groups.back().push_back(e.pattern);
    }
  }
  return groups;
}

}  // namespace gmr::replace
