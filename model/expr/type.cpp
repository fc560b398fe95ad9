#include "model/expr/type.hpp"

#include <cmath>

namespace gmr::expr {

const char* to_string(ValueType t) {
  switch (t) {
    case ValueType::Scalar:
      return "scalar";
    case ValueType::Point:
      return "point";
    case ValueType::Vector:
      return "vector";
    case ValueType::Colour:
      return "colour";
  }
  return "?";
}

std::optional<ValueType> parse_value_type(std::string_view name) {
  // Qualified Java names (fr.ensma.lias.jerboa.embeddings.Vec3, java.awt.Color): the last part.
  if (const auto dot = name.rfind('.'); dot != std::string_view::npos) name = name.substr(dot + 1);
  if (name == "scalar" || name == "double" || name == "float" || name == "Double" ||
      name == "Float")
    return ValueType::Scalar;
  if (name == "point" || name == "Vec3" || name == "Point3") return ValueType::Point;
  if (name == "vector") return ValueType::Vector;
  if (name == "colour" || name == "color" || name == "Color" || name == "Color3")
    return ValueType::Colour;
  return std::nullopt;
}

StaticType StaticType::of(ValueType t) {
  switch (t) {
    case ValueType::Scalar:
      return scalar();
    case ValueType::Point:
      return affine(1.0);
    case ValueType::Vector:
      return affine(0.0);
    case ValueType::Colour:
      return colour();
  }
  return scalar();
}

namespace {
std::string kind_text(StaticType::Kind k, std::optional<double> mass) {
  switch (k) {
    case StaticType::Kind::Scalar:
      return "scalar";
    case StaticType::Kind::Colour:
      return "colour";
    case StaticType::Kind::Multiset:
      return "multiset";
    case StaticType::Kind::Affine:
      if (!mass) return "affine combination";
      if (*mass == 1.0) return "point";
      if (*mass == 0.0) return "vector";
      {
        std::string m = std::to_string(*mass);
        while (m.size() > 1 && m.back() == '0') m.pop_back();
        if (!m.empty() && m.back() == '.') m.pop_back();
        return "affine combination of mass " + m;
      }
  }
  return "?";
}
}  // namespace

std::string StaticType::str() const {
  if (kind == Kind::Multiset) return "multiset of " + kind_text(element, mass);
  return kind_text(kind, mass);
}

}  // namespace gmr::expr
