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

void PatternStore::add(Pattern p) {
  if (mode_ == Mode::Oriented && p.positive.empty())
    throw Error(ErrorCode::Schema, "the oriented mode needs orientable patterns", p.name);
  StoreEntry e;
  e.pattern = patterns_.size();
  Word key = store_key(p.boundary, p.cell_dim, mode_, &e);
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
