#pragma once
// The sizes MuJoCo 2.2.2 fixes when it compiles a model: its contact list (nconmax) and its
// constraint rows (njmax). 2.2.2 allocates the constraint arrays densely in one buffer whose
// size is an int of bytes: efc_AR and its column indices are njmax × njmax (12 bytes a cell),
// the Jacobian, its transpose and their column indices njmax × nv (24 bytes a cell). A model
// whose buffer passes 2 GiB cannot have its mjData ("could not create mjData").
#include <cstdint>

#include "tools/engines/fixed_step/reference_scene.hpp"

namespace impactbench::adapters {

struct MujocoSizes {
  int nconmax = 0;                ///< contacts MuJoCo can hold in one step
  int njmax = 0;                  ///< constraint rows: nconmax × rows per contact
  std::int64_t geometric = 0;     ///< contacts the scene's shapes can have at once (bound)
  std::int64_t buffer_bytes = 0;  ///< the dense constraint arrays of njmax and nv [bytes]
};

/// Constraint rows of one contact of dimension 3: 3 on the elliptic cone, 4 on the pyramid.
int rows_per_contact(bool elliptic);

/// nconmax from the shapes (each round body: half its kissing number of neighbours, 6 in space
/// and 3 in the plane, plus one contact per boundary it can touch at once; a box: 8 points with
/// each of up to 12 neighbours, halved, and 4 per boundary), lowered to what MuJoCo 2.2.2's
/// buffer can address when the bound does not fit.
MujocoSizes mujoco_sizes(const ReferenceScene& scene, bool elliptic);

}  // namespace impactbench::adapters
