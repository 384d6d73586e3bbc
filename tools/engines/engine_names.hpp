#pragma once
// Every engine's name as the command line and the scenario files spell it, written here once.
// The registry (registry/engine_registry.cpp) lists the engines with these in its order; an
// engine's own unit labels its messages and results with its constant, and a command that gives
// an engine a role (the event-driven engine as the reference, Moreau–Jean as the equal-work
// baseline) names it through its constant. Adding an engine adds one line here.
namespace impactbench::engine_name {

inline constexpr char kMoreau[] = "moreau";
inline constexpr char kEvent[] = "event";
inline constexpr char kBox2d[] = "box2d";
inline constexpr char kBullet[] = "bullet";
inline constexpr char kOde[] = "ode";
inline constexpr char kMujoco[] = "mujoco";
inline constexpr char kSiconos[] = "siconos";

}  // namespace impactbench::engine_name
