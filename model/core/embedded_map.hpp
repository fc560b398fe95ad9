// A map with its embeddings (thesis Def. 72: a Pi-embedded G-map or O-map; CGAL's map with
// attributes): the one carrier of a map and its values, for files, rule applications, diagrams and
// query-replace alike.
//
// Each embedding is named, sits on an orbit type and holds one value per orbit (embedding.hpp: per
// dart, the slot of its orbit's value). Values are numbers or triples [x, y, z] (points, vectors,
// colours: the rules that write them say which), stored as Vec3 (a number in the first component);
// any other JSON value read from a file (a boolean, a string, an object, a mix of numbers and
// triples) keeps the whole embedding as JSON, written back unchanged and not evaluated by rule
// expressions. Per-dart flags (Damiand & Nivoliers 2022 §3) are the embedding "flag" on <>.
#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/core/embedding.hpp"
#include "model/core/map.hpp"
#include "model/core/vec3.hpp"

namespace gmr {

using JsonEmbedding = Embedding<nlohmann::json>;

inline constexpr const char* kPositionName = "position";

// One named embedding of an EmbeddedMap.
struct EmbeddingField {
  int arity = 3;           // 1: numbers, 3: triples, 0: JSON values (`json` holds them)
  Embedding<Vec3> values;  // the numbers (first component) or triples; empty when arity is 0
  std::optional<JsonEmbedding> json;  // arity 0 only: the values as read
  // Every number read from the file was an integer: integral values are written back as integers.
  bool integral = false;

  // A numeric embedding (arity 1 or 3) without values.
  static EmbeddingField numeric(std::string name, OrbitType orbit, int arity = 3);
  // A JSON embedding without values.
  static EmbeddingField of_json(std::string name, OrbitType orbit);

  const std::string& name() const { return values.name(); }
  const OrbitType& orbit() const { return values.orbit_type(); }
  bool is_numeric() const { return arity != 0; }
  bool has(Dart d) const { return is_numeric() ? values.has(d) : json->has(d); }
  size_t num_values() const { return is_numeric() ? values.num_values() : json->num_values(); }
  // The value of d's orbit as written in files (d must have one).
  nlohmann::json value_json(Dart d) const;
  // Every orbit whose darts do not all hold one value (Embedding::check).
  std::vector<EmbeddingIssue> check(const Map& g) const;
};

struct EmbeddedMap {
  Map map{2};
  std::vector<EmbeddingField> fields;

  EmbeddedMap() = default;
  explicit EmbeddedMap(Map m) : map(std::move(m)) {}

  // The embedding called `name`, or nullptr.
  EmbeddingField* find(std::string_view name);
  const EmbeddingField* find(std::string_view name) const;
  // The vertex positions: the numeric triple embedding "position". Throws Error(Schema) naming
  // what is missing or, for a JSON embedding of that name, its first value that is not [x, y, z].
  Embedding<Vec3>& position();
  const Embedding<Vec3>& position() const;
  bool has_position() const;
  // Adds a numeric embedding without values (Error(Usage) if the name is taken) and returns it.
  EmbeddingField& add_numeric(std::string name, OrbitType orbit, int arity = 3);
  // Adds the position embedding on the vertex orbit <1..n> (position.hpp) and returns it.
  Embedding<Vec3>& add_position();
};

// The embedding read from (dart, JSON value) pairs, one per orbit: numeric when every value is a
// finite number (arity 1) or every value an array of three (arity 3) — integers beyond 2^53 and
// mixes stay JSON — else JSON.
EmbeddingField field_from_json(const Map& g, std::string name, OrbitType orbit,
                               const std::vector<std::pair<Dart, nlohmann::json>>& values);
// Why a JSON value is not a number or a triple of finite numbers (arity 1 or 3), or nullopt.
std::optional<std::string> numeric_value_problem(const nlohmann::json& v, int& arity);

}  // namespace gmr
