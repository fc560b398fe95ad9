// GMR_BENCH_SCALE (environment, default 1.0): the factor the benchmarks of tools/bench apply to
// their map sizes, e.g. 0.05 for a quick run (run.sh).
#pragma once
#include <cstdlib>

namespace gmr::bench {

inline double scale() {
  const char* s = std::getenv("GMR_BENCH_SCALE");
  return s ? std::atof(s) : 1.0;
}

}  // namespace gmr::bench
