// One parser fuzz target: `fuzz_one(text)` runs a parser (and what a command does next with its
// result) on arbitrary bytes. A gmr::Error is the expected answer to bad input; anything else
// escaping (another exception, a crash, a sanitizer report, a hang) is a finding.
//
// Each target is linked either with libFuzzer (clang, -DGMR_LIBFUZZER=ON;
// tools/fuzzing/campaign.sh) or with replay_main.cpp (any compiler; the CTest runs), which replays
// the seed corpus and deterministic mutations of it.
#pragma once
#include <string_view>

#include "model/core/error.hpp"

namespace gmr::fuzzing {
void fuzz_one(std::string_view text);
}  // namespace gmr::fuzzing
