#pragma once
// Checks of a loaded scene as a whole, made before anything is allocated: parameters that are
// numbers at all (no NaN), probes that can see the domain.
#include "engine/model/model.hpp"
#include "engine/model/parameters.hpp"

namespace washout::lua {

// The first parameter holding NaN (or a non-finite gravity), or "" if none.
std::string non_finite_parameter(const ParameterSet& set);

// Throws SceneError (at the probe's line) for a probe whose point lies outside the domain: the
// domain_min/max box if set, else the bounding box of every shape plus 2 h.
void check_probes(const Model& model);

// Particles the scene would make, estimated from its shapes without filling any lattice: fluid
// regions by volume, walls and bodies by the shell of `layers` spacings inside their bounds.
// An upper bound up to overlaps (and the bounding box of round shapes).
double estimate_particles(const Model& model);

// Throws SceneError when estimate_particles exceeds the max_particles parameter, with the count
// and the memory it would take.
void check_particle_budget(const Model& model);

}  // namespace washout::lua
