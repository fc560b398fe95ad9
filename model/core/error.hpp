// Typed errors raised at every boundary of gmr (parsers, builders, sewing, rules).
// The library never exits; the CLI maps an Error to exit code 2.
#pragma once
#include <stdexcept>
#include <string>

namespace gmr {

enum class ErrorCode {
  Parse,        // malformed text (JSON, OFF, XML, orbit type)
  Schema,       // well-formed but wrong structure or values
  InvalidMap,   // a map breaks a G-map / O-map constraint
  NonManifold,  // mesh input that no G-map represents as asked
  Sew,          // a sew/unsew that would break validity
  Range,        // dart, dimension or index out of range
  Io,           // file system
  Usage,        // wrong use of an API or of the CLI
};

const char* to_string(ErrorCode code);

// An error with a code, a message and a location ("$.darts[3].alpha[1]", "cube.off:12", "dart 7").
class Error : public std::runtime_error {
 public:
  Error(ErrorCode code, std::string message, std::string location = {});
  ErrorCode code() const { return code_; }
  const std::string& message() const { return message_; }
  const std::string& location() const { return location_; }

 private:
  ErrorCode code_;
  std::string message_;
  std::string location_;
};

}  // namespace gmr
