#include "model/map_io/validity_report.hpp"

namespace gmr::io {

std::string to_text(const ValidityReport& r) {
  std::string s;
  for (const ConstraintViolation& v : r.violations) s += "  " + gmr::to_text(v) + "\n";
  if (r.truncated) s += "  ... and " + std::to_string(r.truncated) + " more (--limit)\n";
  return s;
}

std::vector<std::string> violation_texts(const ValidityReport& r) {
  std::vector<std::string> texts;
  texts.reserve(r.violations.size());
  for (const ConstraintViolation& v : r.violations) texts.push_back(gmr::to_text(v));
  return texts;
}

nlohmann::ordered_json to_json(const ConstraintViolation& v) {
  nlohmann::ordered_json x;
  x["constraint"] = gmr::to_text(v.constraint);
  x["dart"] = v.at;
  x["i"] = v.i;
  if (v.j >= 0) x["j"] = v.j;
  x["path"] = v.path;
  x["message"] = gmr::to_text(v);
  return x;
}

nlohmann::ordered_json violations_json(const ValidityReport& r) {
  nlohmann::ordered_json vs = nlohmann::ordered_json::array();
  for (const ConstraintViolation& v : r.violations) vs.push_back(to_json(v));
  return vs;
}

}  // namespace gmr::io
