#include "model/core/constraint_violation.hpp"

namespace gmr {

namespace {

// The names of each constraint, in the order of the enumeration: text, symbol.
constexpr const char* kNames[][2] = {
    {"incident-arcs", "I"}, {"non-orientation", "O"}, {"cycle", "C"}};

}  // namespace

const char* to_text(Constraint c) { return kNames[static_cast<int>(c)][0]; }

const char* symbol(Constraint c) { return kNames[static_cast<int>(c)][1]; }

std::string condition_text(std::string_view name, int i, int j) {
  std::string s(name);
  if (i < 0) return s;
  s += "(" + std::to_string(i);
  if (j >= 0) s += "," + std::to_string(j);
  return s + ")";
}

std::string to_text(const ConstraintViolation& v) {
  return std::string(to_text(v.constraint)) + " at dart " + std::to_string(v.at) + ": " + v.message;
}

}  // namespace gmr
