// A G-map with any number of named numeric embeddings (thesis Def. 72, a Pi-embedded G-map), the
// object rule applications with expressions rewrite.
//
// Each embedding stores, per dart, the slot of its orbit's value (model/core/embedding.hpp);
// values are Vec3 (scalars use the first component). The conversion from a gmr.gmap file accepts
// embeddings whose values are all numbers (arity 1) or all arrays of three numbers (arity 3); other
// JSON values are not carried through rule applications (Error(Schema) naming the embedding and a
// dart). Whether a triple is a point, a vector or a colour is said by the rules that write it.
#pragma once
#include <string_view>
#include <vector>

#include "model/core/gmap_file.hpp"
#include "model/core/vec3.hpp"

namespace gmr::expr {

struct EmbeddingField {
  int arity = 3;  // 1: scalar values, 3: triples
  Embedding<Vec3> values;
  const std::string& name() const { return values.name(); }
  const OrbitType& orbit() const { return values.orbit_type(); }
};

struct EmbeddedMap {
  Map map{2};
  std::vector<EmbeddingField> fields;

  EmbeddingField* find(std::string_view name);
  const EmbeddingField* find(std::string_view name) const;
};

EmbeddedMap to_embedded_map(const GMapFile& f);
// One JSON value per orbit that has one (a number or [x, y, z]).
GMapFile to_gmap_file(const EmbeddedMap& m);

}  // namespace gmr::expr
