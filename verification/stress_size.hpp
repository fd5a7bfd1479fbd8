// Cases sized for CI that `make stress` (BLAZE_STRESS=full) runs at full size: the stress suite
// (test_stress.cpp, its sizes there), the elastic polyhedron collisions
// (test_polyhedron_dynamics.cpp) and the settled beds of Fig 3.27 (test_contact_types.cpp), both
// sizes of these two in tolerances.hpp with what the CI size still resolves.
#pragma once
#include <cstdlib>
#include <string>

namespace blaze::test {

// True under `make stress`.
inline bool full_size() {
  const char* e = std::getenv("BLAZE_STRESS");
  return e && std::string(e) == "full";
}

}  // namespace blaze::test
