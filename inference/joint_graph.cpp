#include "inference/joint_graph.hpp"

#include <algorithm>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"

namespace gmr::inference {

std::string dimension_text(int d) { return d == kKappa ? "κ" : std::to_string(d); }

void JointGraph::reserve(size_t darts) {
  for (auto& l : link_) l.reserve(darts);
  kappa_.reserve(darts);
  side_.reserve(darts);
  origin_.reserve(darts);
}

uint32_t JointGraph::add_dart(Side side, Dart origin) {
  const auto x = static_cast<uint32_t>(side_.size());
  for (auto& l : link_) l.push_back(kUndefined);
  kappa_.push_back(kUndefined);
  side_.push_back(side);
  origin_.push_back(origin);
  if (side == Side::R) has_after_ = true;
  return x;
}

void JointGraph::link(int d, uint32_t x, uint32_t y) {
  set_nbr(x, d, y);
  set_nbr(y, d, x);
}

std::string JointGraph::describe(uint32_t x) const {
  const std::string id = std::to_string(origin_[x]);
  if (!has_after_) return id;
  return (side_[x] == Side::L ? "before " : "after ") + id;
}

JointGraph joint_from_map(const Map& g, JointIndex* index) {
  if (g.is_omap()) throw Error(ErrorCode::Usage, "topological folding works on G-maps, not O-maps");
  JointGraph j(g.dimension());
  j.reserve(g.size());
  std::vector<uint32_t> idx(g.capacity(), kUndefined);
  g.for_each_dart([&](Dart d) { idx[d] = j.add_dart(Side::L, d); });
  g.for_each_dart([&](Dart d) {
    for (int i = 0; i <= g.dimension(); ++i) {
      const Dart e = g.alpha(i, d);
      j.set_nbr(idx[d], i, e < idx.size() ? idx[e] : kUndefined);
    }
  });
  if (index) index->before = std::move(idx);
  return j;
}

JointGraph joint_from_component(const Map& g, Dart d, JointIndex* index) {
  if (g.is_omap()) throw Error(ErrorCode::Usage, "topological folding works on G-maps, not O-maps");
  if (!g.alive(d)) throw Error(ErrorCode::Range, "no dart " + std::to_string(d));
  std::vector<Dart> comp = orbit(g, OrbitType::range(0, g.dimension()), d);
  std::sort(comp.begin(), comp.end());
  JointGraph j(g.dimension());
  std::vector<uint32_t> idx(g.capacity(), kUndefined);
  for (Dart e : comp) idx[e] = j.add_dart(Side::L, e);
  for (Dart e : comp)
    for (int i = 0; i <= g.dimension(); ++i) {
      const Dart f = g.alpha(i, e);
      j.set_nbr(idx[e], i, f < idx.size() ? idx[f] : kUndefined);
    }
  if (index) index->before = std::move(idx);
  return j;
}

}  // namespace gmr::inference
