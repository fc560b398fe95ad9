// The rule-scheme engine of a generated scheme, or the case discarded: the generators also draw
// schemes the engine refuses (SchemeEngine's constructor throws Error).
#pragma once
#include <rapidcheck.h>

#include <optional>

#include "model/core/error.hpp"
#include "model/scheme/scheme_engine.hpp"

namespace gmr::prop {

// Constructs the engine of `s` into `engine`, or discards the case (RC_DISCARD) with `reason`.
inline void emplace_engine_or_discard(std::optional<scheme::SchemeEngine>& engine,
                                      const scheme::RuleScheme& s, const char* reason) {
  try {
    engine.emplace(s);
  } catch (const Error&) {
    RC_DISCARD(reason);
  }
}

}  // namespace gmr::prop
