// A shared library without the entry symbol gmr_condition_v1 (bad-input test).
#include "checker/smt/condition_api.hpp"

extern "C" bool some_other_symbol(const gmr::condition::RuleView& r) { return r.n > 0; }
