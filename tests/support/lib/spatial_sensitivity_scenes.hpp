#pragma once
// Spatial scenes for the sensitivity tests, built from specs (no scenario file): a sphere
// launched onto the ground, a sphere resting on it under an input force, cuboids dropped on a
// corner, an edge or flat. Each holds the double and AD systems, the hybrid model, and the
// central finite-difference check of the end-point sensitivity in tangent coordinates.
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/model/spatial/spatial_system.hpp"
#include "lib/model/spatial/spatial_system_autodiff.hpp"
#include "lib/sensitivity/mechanical_hybrid_model.hpp"
#include "lib/sensitivity/trajectory_sensitivity.hpp"
#include "tests/support/lib/event_driven_runs.hpp"

namespace impactbench::test_support {

class SpatialScene {
 public:
  /// `parameter_states`: μ and e join the model's state (MechanicalHybridModel).
  explicit SpatialScene(const model::spatial::SpatialSystemSpec& spec,
                        bool parameter_states = false);
  SpatialScene(const SpatialScene&) = delete;
  SpatialScene& operator=(const SpatialScene&) = delete;

  const model::spatial::SpatialRigidBodySystem<double>& system() const { return system_; }
  const sensitivity::MechanicalHybridModel& model() const { return model_; }
  Eigen::VectorXd x0() const;

 private:
  model::spatial::SpatialRigidBodySystem<double> system_;
  model::spatial::SpatialRigidBodySystem<sensitivity::AutoDiff> system_ad_;
  sensitivity::MechanicalHybridModel model_;
};

/// One sphere (R = 0.1 m, 1 kg) at height `z` with velocity v and world angular velocity w over
/// the ground z = 0; μ, e; optional force inputs on it (world directions).
model::spatial::SpatialSystemSpec sphere_over_ground(
    double z, const Eigen::Vector3d& v, const Eigen::Vector3d& w, double friction,
    double restitution, const std::vector<Eigen::Vector3d>& inputs = {});

/// One cuboid (0.4 × 0.3 × 0.2 m, 1 kg) with its centre at height `z` and the given orientation,
/// velocity v and world angular velocity w, over the ground z = 0; μ, e.
model::spatial::SpatialSystemSpec cuboid_over_ground(double z,
                                                     const Eigen::Quaterniond& orientation,
                                                     const Eigen::Vector3d& v,
                                                     const Eigen::Vector3d& w, double friction,
                                                     double restitution);

/// The central finite-difference check of one scene at the end time T of `runs`: for the unit
/// tangent direction δ (per body δc, δθ, δv, δω; model.tangent_basis) and each ε, the difference
/// quotient P (x(T; x0 + ε z0) − x(T; x0 − ε z0)) / (2ε) of two event-driven runs against the
/// first-order prediction P z(T) (P = tangent_projection at the nominal end state), with the
/// parameter `p` (μ or e, when `parameter` is given) perturbed as an extra state of zero flow.
struct FiniteDifferenceRow {
  double epsilon = 0.0;
  double error = 0.0;  ///< ‖FD − prediction‖∞
};
struct FiniteDifferenceCheck {
  std::string label;
  double prediction_norm = 0.0;  ///< ‖P z(T)‖∞
  std::vector<FiniteDifferenceRow> rows;
  /// log2(error(2ε)/error(ε)) for consecutive rows (2 values for 3 ε).
  std::vector<double> slopes() const;
};
std::ostream& operator<<(std::ostream& out, const FiniteDifferenceCheck& check);

FiniteDifferenceCheck central_difference_check(
    const EventRuns& runs, const SpatialScene& scene, const Eigen::VectorXd& x0,
    const Eigen::VectorXd& delta, const std::string& label,
    const std::vector<double>& epsilons = {4e-3, 2e-3, 1e-3});
/// The same check for the contact parameters, on whole runs: `make(μ, e)` builds the scene
/// (with parameter states for the nominal), the prediction is P z(T) for z0 the unit
/// perturbation of μ (`parameter` 0) or e (1), the quotient that of runs at μ ± ε (e ± ε).
using SceneFactory = std::function<std::unique_ptr<SpatialScene>(
    double friction, double restitution, bool parameter_states)>;
FiniteDifferenceCheck parameter_difference_check(
    const SceneFactory& make, double friction, double restitution, int parameter, double end,
    const sensitivity::InputFunction& input, const sensitivity::InputFunction& input_rate,
    const std::string& label, const std::vector<double>& epsilons = {4e-3, 2e-3, 1e-3});

/// parameter_difference_check printed and held to expect_quadratic, with the engine's noise on
/// a difference quotient of runs at tolerance 1e-12 (a hundred tolerances of a unit-size state
/// over the smallest ε) as floor; the parameter must move the end state (‖P z(T)‖ > 1e-3).
void expect_parameter_gain(const SceneFactory& make, double friction, double restitution,
                           int parameter, double end, const sensitivity::InputFunction& input,
                           const sensitivity::InputFunction& input_rate, const std::string& label);

/// The micro events of the engine's run of `scene` under runs.input, as the module maps them.
std::vector<sensitivity::MicroEvent> engine_micro_events(const SpatialScene& scene,
                                                         const EventRuns& runs, double end);

/// Both ε-checks for one scene: runs.expect_second_order_from (whole trajectory) and
/// central_difference_check of a random unit tangent direction drawn with `seed`, whose floor
/// is the engine's noise on a difference quotient (ten tolerances of the state's size over the
/// smallest ε); the check is printed.
void expect_spatial_first_order(const SpatialScene& scene, const EventRuns& runs, unsigned seed,
                                const std::string& label,
                                const std::vector<double>& epsilons = {4e-3, 2e-3, 1e-3});

/// gtest expectations on a check: every slope within [log2 3, log2 5] (error ratio 4 ± 1 per
/// halving of ε, the project's ε² criterion), unless the error at the smaller ε is below the
/// integration-noise floor `floor` (then the larger one must be under 5 × floor). δ is first
/// restricted to the perturbations that keep the initially closed contacts closed.
void expect_quadratic(const FiniteDifferenceCheck& check, double floor);

}  // namespace impactbench::test_support
