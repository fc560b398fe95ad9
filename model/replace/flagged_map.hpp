// A map with dart flags (Damiand & Nivoliers 2022 §3, §4.3.2): flags are optional dart marks that
// matched darts must share. In files, flags are the embedding "flag" on the orbit type <> (one
// value per dart): true or a positive integer flags the dart, false, 0 or no value leave it
// unflagged. Vertex positions (the embedding "position", position.hpp) are carried when present;
// other embeddings are not.
#pragma once
#include <cstdint>
#include <vector>

#include "model/core/embedded_map.hpp"
#include "model/core/vec3.hpp"

namespace gmr::replace {

inline constexpr const char* kFlagEmbedding = "flag";

struct FlaggedMap {
  Map map{2};
  std::vector<uint32_t> flag;  // indexed by dart, 0: unflagged (sized to map.capacity())
  std::vector<Vec3> position;  // per dart (its vertex's position); empty: no geometry

  bool positioned() const { return !position.empty(); }
  // A flag (0) and a position (the origin) for every dart of the map.
  void resize_flags() {
    grow_flags(map.capacity());
    flag.resize(map.capacity(), 0);
    if (positioned()) position.resize(map.capacity(), Vec3{0, 0, 0});
  }
  // Room for the flags and positions of `darts` darts, grown geometrically (at least twice the
  // room they had) in huge pages (huge_pages.hpp: fresh pages are faulted in 2 MiB, not 4 KiB).
  void grow_flags(size_t darts);
  size_t flagged() const;
  // Room for `darts` darts in the links, flags and positions, exactly (a sequence of replacements
  // whose growth is bounded beforehand then grows no array, query_replace.hpp).
  void reserve(size_t darts);
};

// Reads the flags of a gmr.gmap content; throws Error(Schema) at `where` for an embedding "flag"
// on another orbit type or with a value that is not a boolean or a non-negative integer.
FlaggedMap flagged_map(const EmbeddedMap& f, const std::string& where = {});
// The map with its flags as the embedding "flag" (every dart gets a value: false when unflagged)
// and its positions, if any.
EmbeddedMap to_embedded_map(const FlaggedMap& m);

}  // namespace gmr::replace
