#include "model/core/error.hpp"

namespace gmr {

const char* to_string(ErrorCode code) {
  switch (code) {
    case ErrorCode::Parse:
      return "parse";
    case ErrorCode::Schema:
      return "schema";
    case ErrorCode::InvalidMap:
      return "invalid-map";
    case ErrorCode::NonManifold:
      return "non-manifold";
    case ErrorCode::Sew:
      return "sew";
    case ErrorCode::Range:
      return "range";
    case ErrorCode::Io:
      return "io";
    case ErrorCode::Usage:
      return "usage";
  }
  return "unknown";
}

static std::string compose(ErrorCode code, const std::string& message,
                           const std::string& location) {
  std::string s = std::string("[") + to_string(code) + "] ";
  if (!location.empty()) s += location + ": ";
  return s + message;
}

Error::Error(ErrorCode code, std::string message, std::string location)
    : std::runtime_error(compose(code, message, location)),
      code_(code),
      message_(std::move(message)),
      location_(std::move(location)) {}

}  // namespace gmr
