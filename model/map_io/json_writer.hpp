// Layout of the JSON text written by gmr (all gmr.* files): members keep their insertion order
// (nlohmann::ordered_json, so that "format" and "version" come first),
// objects and arrays are broken over indented lines, except that arrays of scalars (dart arrays of
// any length) and values whose compact form fits in 100 characters stay on one line.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace gmr::io {

std::string dump_json(const nlohmann::ordered_json& value);

}  // namespace gmr::io
