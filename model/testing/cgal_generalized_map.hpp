// CGAL's Generalized_map, the test oracle and benchmark peer, included once for every user (tests,
// property tests, benchmarks) with CGAL's own warnings silenced: gmr builds with -Werror and CGAL's
// headers do not compile cleanly under -Wconversion/-Wshadow/-Wpedantic.
// Header only: the library gmr_testing does not link CGAL; the targets that include this do.
#pragma once

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <CGAL/Generalized_map.h>
#pragma GCC diagnostic pop
