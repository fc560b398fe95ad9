#include "checker/diagnostic.hpp"

#include <algorithm>

namespace gmr::checker {

const char* to_string(Severity s) {
  switch (s) {
    case Severity::Error:
      return "error";
    case Severity::Warning:
      return "warning";
    case Severity::Note:
      return "note";
  }
  return "?";
}

std::string word_text(const std::vector<int>& w) {
  if (w.empty()) return "ε";
  std::string s;
  for (int x : w) s += std::to_string(x);
  return s;
}

std::string Diagnostic::side_str() const { return side ? to_string(*side) : ""; }

bool CheckReport::ok() const { return errors() == 0; }

size_t CheckReport::errors() const {
  return static_cast<size_t>(
      std::count_if(diagnostics.begin(), diagnostics.end(),
                    [](const Diagnostic& d) { return d.severity == Severity::Error; }));
}

size_t CheckReport::warnings() const {
  return static_cast<size_t>(
      std::count_if(diagnostics.begin(), diagnostics.end(),
                    [](const Diagnostic& d) { return d.severity == Severity::Warning; }));
}

bool CheckReport::holds(const std::string& condition) const {
  for (const auto& [c, h] : conditions)
    if (c == condition) return h;
  return false;
}

size_t CheckReport::count(const std::string& code) const {
  size_t k = 0;
  for (const auto& d : diagnostics) k += d.code == code;
  return k;
}

}  // namespace gmr::checker
