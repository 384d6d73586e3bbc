#include "tests/support/lib/spatial_sensitivity_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <ostream>
#include <random>
#include <stdexcept>

#include <Eigen/LU>
#include <Eigen/QR>

#include "lib/sensitivity/event_driven_nominal.hpp"

namespace impactbench::test_support {

SpatialScene::SpatialScene(const model::spatial::SpatialSystemSpec& spec, bool parameter_states)
    : system_(spec), system_ad_(spec), model_(system_, system_ad_, parameter_states) {}

Eigen::VectorXd SpatialScene::x0() const {
  return model_.state(system_.initial_positions(), system_.initial_velocities());
}

namespace {

/// One 1 kg body centred at height z with velocity v and world angular velocity w over the
/// ground z = 0; μ, e.
model::spatial::SpatialSystemSpec body_over_ground(model::BodySpec body, double z,
                                                   const Eigen::Vector3d& v,
                                                   const Eigen::Vector3d& w, double friction,
                                                   double restitution) {
  body.mass = 1.0;
  body.position = Eigen::Vector3d(0.0, 0.0, z);
  body.velocity = v;
  body.angular_velocity = w;
  model::spatial::SpatialSystemSpec spec;
  spec.bodies.push_back(body);
  model::StaticPlaneSpec ground;
  ground.normal = Eigen::Vector3d::UnitZ();
  spec.planes.push_back(ground);
  spec.material = {friction, restitution};
  return spec;
}

}  // namespace

model::spatial::SpatialSystemSpec sphere_over_ground(double z, const Eigen::Vector3d& v,
                                                     const Eigen::Vector3d& w, double friction,
                                                     double restitution,
                                                     const std::vector<Eigen::Vector3d>& inputs) {
  model::BodySpec ball;
  ball.name = "ball";
  ball.shape = model::ShapeKind::kSphere;
  ball.radius = 0.1;
  // A generic orientation, so that orientation perturbations are not about a symmetric pose.
  ball.orientation = Eigen::Quaterniond(0.9, 0.2, -0.3, 0.25).normalized();
  model::spatial::SpatialSystemSpec spec = body_over_ground(ball, z, v, w, friction, restitution);
  for (const Eigen::Vector3d& direction : inputs) spec.inputs.push_back({"ball", direction});
  return spec;
}

model::spatial::SpatialSystemSpec cuboid_over_ground(double z,
                                                     const Eigen::Quaterniond& orientation,
                                                     const Eigen::Vector3d& v,
                                                     const Eigen::Vector3d& w, double friction,
                                                     double restitution) {
  model::BodySpec box;
  box.name = "box";
  box.shape = model::ShapeKind::kCuboid;
  box.size = Eigen::Vector3d(0.4, 0.3, 0.2);
  box.orientation = orientation;
  return body_over_ground(box, z, v, w, friction, restitution);
}

std::vector<double> FiniteDifferenceCheck::slopes() const {
  std::vector<double> out;
  for (std::size_t i = 1; i < rows.size(); ++i)
    out.push_back(std::log2(rows[i - 1].error / rows[i].error) /
                  std::log2(rows[i - 1].epsilon / rows[i].epsilon));
  return out;
}

std::ostream& operator<<(std::ostream& out, const FiniteDifferenceCheck& check) {
  out << "[FD " << check.label << "] |P z(T)| = " << check.prediction_norm;
  for (const FiniteDifferenceRow& row : check.rows)
    out << "; eps " << row.epsilon << ": error " << row.error;
  out << "; slopes";
  for (const double s : check.slopes()) out << " " << s;
  return out << "\n";
}

FiniteDifferenceCheck central_difference_check(const EventRuns& runs, const SpatialScene& scene,
                                               const Eigen::VectorXd& x0,
                                               const Eigen::VectorXd& delta,
                                               const std::string& label,
                                               const std::vector<double>& epsilons) {
  const sensitivity::MechanicalHybridModel& model = scene.model();
  const auto final_state = [&](const Eigen::VectorXd& x) {
    const auto r = runs.run(x, runs.input);
    if (!r.succeeded()) throw std::runtime_error(label + ": event-driven run failed: " + r.message);
    return std::make_pair(model.state(r.q, r.v), r);
  };
  const auto [x_end, nominal_run] = final_state(x0);
  const double t_end = nominal_run.final_time;
  const sensitivity::NominalTrajectory nominal = sensitivity::nominal_from_event_run(
      model, scene.system(), nominal_run, runs.input, runs.input_rate, t_end);
  const sensitivity::TrajectorySensitivity sensitivity(model, nominal);
  // δ restricted to the perturbations that keep the initially closed contacts closed (the
  // mode's constraint rows in tangent coordinates), then scaled back to unit length.
  const Eigen::MatrixXd E = model.tangent_basis(x0);
  const Eigen::MatrixXd C = model.mode_constraint_rows(nominal.mode0, x0) * E;
  Eigen::VectorXd admissible = delta;
  if (C.rows() > 0) {
    const Eigen::MatrixXd K = Eigen::FullPivLU<Eigen::MatrixXd>(C).kernel();
    admissible = K * K.colPivHouseholderQr().solve(delta);
  }
  const Eigen::VectorXd z0 = E * admissible.normalized();
  const Eigen::MatrixXd P = model.tangent_projection(x_end);
  const Eigen::VectorXd predicted = P * sensitivity.perturbation(z0, {}, {t_end}).front();
  FiniteDifferenceCheck check;
  check.label = label;
  check.prediction_norm = predicted.lpNorm<Eigen::Infinity>();
  for (const double eps : epsilons) {
    const Eigen::VectorXd up = final_state(x0 + eps * z0).first;
    const Eigen::VectorXd down = final_state(x0 - eps * z0).first;
    const Eigen::VectorXd quotient = P * (up - down) / (2 * eps);
    check.rows.push_back({eps, (quotient - predicted).lpNorm<Eigen::Infinity>()});
  }
  return check;
}

FiniteDifferenceCheck parameter_difference_check(const SceneFactory& make, double friction,
                                                 double restitution, int parameter, double end,
                                                 const sensitivity::InputFunction& input,
                                                 const sensitivity::InputFunction& input_rate,
                                                 const std::string& label,
                                                 const std::vector<double>& epsilons) {
  const auto end_state = [&](const SpatialScene& scene, const Eigen::Vector2d& values,
                             engines::event_driven::EventDrivenResult* keep) {
    EventRuns runs(scene.system(), scene.model(), end);
    const int nq = scene.system().num_positions();
    auto r = runs.run(scene.x0().head(nq + scene.system().num_velocities()), input);
    if (!r.succeeded()) throw std::runtime_error(label + ": event-driven run failed: " + r.message);
    Eigen::VectorXd x(r.q.size() + r.v.size() + 2);
    x << r.q, r.v, values;
    if (keep != nullptr) *keep = std::move(r);
    return x;
  };
  const auto nominal_scene = make(friction, restitution, true);
  const sensitivity::MechanicalHybridModel& model = nominal_scene->model();
  engines::event_driven::EventDrivenResult nominal_run;
  const Eigen::VectorXd x_end =
      end_state(*nominal_scene, Eigen::Vector2d(friction, restitution), &nominal_run);
  const sensitivity::NominalTrajectory nominal = sensitivity::nominal_from_event_run(
      model, nominal_scene->system(), nominal_run, input, input_rate, end);
  const sensitivity::TrajectorySensitivity sensitivity(model, nominal);
  const Eigen::VectorXd z0 =
      Eigen::VectorXd::Unit(model.state_size(), model.state_size() - 2 + parameter);
  const Eigen::MatrixXd P = model.tangent_projection(x_end);
  const Eigen::VectorXd predicted = P * sensitivity.perturbation(z0, {}, {end}).front();
  FiniteDifferenceCheck check;
  check.label = label;
  check.prediction_norm = predicted.lpNorm<Eigen::Infinity>();
  for (const double eps : epsilons) {
    const Eigen::Vector2d step = eps * Eigen::Vector2d::Unit(parameter);
    const Eigen::Vector2d up = Eigen::Vector2d(friction, restitution) + step;
    const Eigen::Vector2d down = Eigen::Vector2d(friction, restitution) - step;
    const Eigen::VectorXd x_up = end_state(*make(up(0), up(1), false), up, nullptr);
    const Eigen::VectorXd x_down = end_state(*make(down(0), down(1), false), down, nullptr);
    const Eigen::VectorXd quotient = P * (x_up - x_down) / (2 * eps);
    check.rows.push_back({eps, (quotient - predicted).lpNorm<Eigen::Infinity>()});
  }
  return check;
}

void expect_parameter_gain(const SceneFactory& make, double friction, double restitution,
                           int parameter, double end, const sensitivity::InputFunction& input,
                           const sensitivity::InputFunction& input_rate, const std::string& label) {
  const FiniteDifferenceCheck check = parameter_difference_check(
      make, friction, restitution, parameter, end, input, input_rate, label);
  std::cout << check;
  EXPECT_GT(check.prediction_norm, 1e-3) << label << ": the parameter moves the end state";
  expect_quadratic(check, 100 * 1e-12 / check.rows.back().epsilon);
}

std::vector<sensitivity::MicroEvent> engine_micro_events(const SpatialScene& scene,
                                                         const EventRuns& runs, double end) {
  const auto r = runs.run(scene.x0(), runs.input);
  EXPECT_TRUE(r.succeeded()) << r.message;
  const sensitivity::NominalTrajectory n = sensitivity::nominal_from_event_run(
      scene.model(), scene.system(), r, runs.input, runs.input_rate, end);
  std::vector<sensitivity::MicroEvent> out;
  for (const sensitivity::NominalEvent& e : n.events)
    for (const sensitivity::MicroEvent& me : e.micro_events) out.push_back(me);
  return out;
}

void expect_spatial_first_order(const SpatialScene& scene, const EventRuns& runs, unsigned seed,
                                const std::string& label, const std::vector<double>& epsilons) {
  const Eigen::VectorXd x0 = scene.x0();
  runs.expect_second_order_from(x0, seed, label.c_str());
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  Eigen::VectorXd delta(2 * scene.system().num_velocities());
  for (Eigen::Index i = 0; i < delta.size(); ++i) delta(i) = normal(rng);
  const FiniteDifferenceCheck check =
      central_difference_check(runs, scene, x0, delta.normalized(), label, epsilons);
  std::cout << check;
  const double floor = 10 * runs.options.relative_tolerance *
                       std::max(1.0, x0.lpNorm<Eigen::Infinity>()) / check.rows.back().epsilon;
  expect_quadratic(check, floor);
}

void expect_quadratic(const FiniteDifferenceCheck& check, double floor) {
  const std::vector<double> slopes = check.slopes();
  for (std::size_t i = 0; i < slopes.size(); ++i) {
    if (check.rows[i + 1].error < floor) {
      // Below the noise floor the ratio is noise; the larger ε's error must still be under the
      // quadratic envelope of the floor (4× per doubling, with slack for the noise itself).
      EXPECT_LT(check.rows[i].error, 5 * floor) << check.label << " eps " << check.rows[i].epsilon;
      continue;
    }
    EXPECT_GE(slopes[i], std::log2(3.0)) << check.label << " eps " << check.rows[i + 1].epsilon;
    EXPECT_LE(slopes[i], std::log2(5.0)) << check.label << " eps " << check.rows[i + 1].epsilon;
  }
}

}  // namespace impactbench::test_support
