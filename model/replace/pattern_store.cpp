#include "model/replace/pattern_store.hpp"

#include "model/core/error.hpp"

namespace gmr::replace {

Word store_key(const BoundaryGraph& b, int cell_dim, Mode mode, StoreEntry* entry) {
  const CellSignature s = minimal_signature(b, mode);
  Word key;
  key.reserve(s.word.size() + 1);
  key.push_back(static_cast<uint32_t>(cell_dim));
  key.insert(key.end(), s.word.begin(), s.word.end());
  if (entry) {
    entry->start = s.start;
    entry->automorphisms = s.automorphisms;
  }
  return key;
}

bool boundary_automorphisms_extend(const Pattern& p, Mode mode, const StoreEntry& e) {
  const BoundaryGraph& b = p.boundary;
  const GMap& g = p.map.map;
  const Word best = boundary_word(b, e.start);
  const std::vector<uint32_t> ref = boundary_labeling(b, e.start);
  for (uint32_t s = 0; s < b.size(); ++s) {
    if (s == e.start || (mode == Mode::Oriented && !b.positive[s]) || boundary_word(b, s) != best) continue;
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
      if (image[x] == kNoDart || hit[image[x]] || p.map.flag[x] != p.map.flag[image[x]]) bijective = false;
      else hit[image[x]] = 1;
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
  table_[key].push_back(e);
  key_of_.push_back(std::move(key));
  entries_.push_back(e);
  patterns_.push_back(std::move(p));
}

const std::vector<StoreEntry>* PatternStore::find(const Word& key) const {
  const auto it = table_.find(key);
  return it == table_.end() ? nullptr : &it->second;
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
