// Value types of the embedding expression language (thesis §5.5; docs/embeddings.md).
//
// An embedding pi : <o_pi> -> tau_pi stores values of one *value type*: scalar, point, vector or
// colour. Points and vectors form an affine space and are typed together as *affine* values with a
// mass (homogeneous coordinate): a point has mass 1, a vector mass 0, and a linear combination
// sum(k_i x_i) has mass sum(k_i m_i). So 0.25*a + 0.75*b is a point, a - b a vector, a + b (mass 2)
// neither. Colours are a vector space of their own ([0,1]^3 is not closed under it: clamp() brings
// a colour back). Multisets (collects) exist only inside expressions, never as attributes.
#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace gmr::expr {

// The type of an embedding's values.
enum class ValueType { Scalar, Point, Vector, Colour };
const char* to_string(ValueType t);
// "scalar", "point", "vector", "colour" (also "color"); the Jerboa types "Vec3", "Point3"
// (points), "Color", "Color3", "java.awt.Color" (colours) and their qualified names. nullopt
// otherwise.
std::optional<ValueType> parse_value_type(std::string_view name);
// Number of components stored per value (1 for scalars, 3 otherwise).
inline int arity(ValueType t) { return t == ValueType::Scalar ? 1 : 3; }

// The static type of a sub-expression.
struct StaticType {
  enum class Kind { Scalar, Affine, Colour, Multiset };
  Kind kind = Kind::Scalar;
  Kind element = Kind::Scalar;     // of a multiset
  std::optional<double> mass;      // of an affine value (or a multiset's elements), when known
  std::optional<double> constant;  // of a scalar, when known statically

  static StaticType scalar(std::optional<double> c = {}) {
    return {Kind::Scalar, Kind::Scalar, {}, c};
  }
  static StaticType affine(std::optional<double> m) { return {Kind::Affine, Kind::Scalar, m, {}}; }
  static StaticType colour() { return {Kind::Colour, Kind::Scalar, {}, {}}; }
  static StaticType multiset(const StaticType& e) { return {Kind::Multiset, e.kind, e.mass, {}}; }
  static StaticType of(ValueType t);
  StaticType element_type() const { return {element, Kind::Scalar, mass, {}}; }
  // "scalar", "point", "vector", "affine combination of mass 2", "colour", "multiset of point"
  std::string str() const;
};

}  // namespace gmr::expr
