#pragma once
// Siconos' MoreauJeanOSI on the project's own model of a scenario (engines::build_system):
// Siconos integrates a LagrangianDS whose mass and forces are the model's (M, F = S u − H,
// springs and dampers included), with one Interaction per potential contact of the model whose
// gap and Jacobian are the model's contact kinematics (siconos_lagrangian_model.hpp). Used for
// one planar body against planes (relations nonlinear in the angle: boxes may turn), for the
// plank–box, whose hinge, torsional spring and damper are part of the model's coordinates and
// forces (its two contacts C_L and C_R always present), and for one sphere against planes
// (FrictionContact of dimension 3; orientation carried by the adapter, see the .cpp).
#include "lib/engines/run_result.hpp"
#include "lib/scenario/scenario.hpp"
#include "tools/engines/siconos/siconos_settings.hpp"

namespace impactbench::adapters {

/// Whether run_siconos_system states the scenario: the plank–box, and with scheme moreau_jean
/// the planar scenes of one body against planes.
bool siconos_states_as_system(const scenario::Scenario& scenario,
                              const engines::SiconosSettings& settings);

/// Runs the scenario with Siconos' MoreauJeanOSI in fixed steps of settings.dt for `duration`.
/// Throws UnsupportedScene for scheme event_driven on the plank–box (frictional contacts, not
/// stated there) and for a planar solver on a sphere (fc3d: nsgs only).
engines::RunResult run_siconos_system(const scenario::Scenario& scenario,
                                      const engines::SiconosSettings& settings, double duration,
                                      const engines::RecordingOptions& recording);

}  // namespace impactbench::adapters
