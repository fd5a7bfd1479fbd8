// Compile-time caps on polyhedron features (thesis section 2.2.1: 32 features, to fit constant
// memory). A convex polyhedron with V, F <= 32 has E = V + F - 2 <= 62 edges; the thesis's 90 is
// kept as the edge cap so shapes it accepted are accepted here.
#pragma once

namespace blaze {

inline constexpr int kMaxVertices = 32;
inline constexpr int kMaxFaces = 32;
inline constexpr int kMaxEdges = 90;

}  // namespace blaze
