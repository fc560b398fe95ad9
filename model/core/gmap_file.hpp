// The content of a gmr.gmap file (io_json.hpp): a G-map or O-map with named embeddings whose
// values are arbitrary JSON (typed views such as positions are derived from them, position.hpp).
#pragma once
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/core/embedding.hpp"
#include "model/core/map.hpp"

namespace gmr {

using JsonEmbedding = Embedding<nlohmann::json>;

struct GMapFile {
  Map map{2};
  std::vector<JsonEmbedding> embeddings;

  // The embedding called `name`, or nullptr.
  const JsonEmbedding* find(std::string_view name) const {
    for (const auto& e : embeddings)
      if (e.name() == name) return &e;
    return nullptr;
  }
};

}  // namespace gmr
