// A validity report (model/core/validity.hpp) as text and JSON, the one writer of the commands
// that print one (`gmr validate`, `gmr apply`, `gmr apply-scheme`).
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "model/core/validity.hpp"

namespace gmr::io {

// One violation per line, indented by two spaces, then "  ... and N more (--limit)" when some
// were not stored.
std::string to_text(const ValidityReport& r);

// The stored violations as their texts (to_text of constraint_violation.hpp).
std::vector<std::string> violation_texts(const ValidityReport& r);

// One violation located at a dart: {"constraint": "cycle", "dart": 3, "i": 0, "j": 2 (when set),
// "path": [...], "message": its text}.
nlohmann::ordered_json to_json(const ConstraintViolation& v);

// The stored violations, an array of to_json(ConstraintViolation).
nlohmann::ordered_json violations_json(const ValidityReport& r);

}  // namespace gmr::io
