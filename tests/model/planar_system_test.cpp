// Mass, bias forces, inputs, energy and naming of the planar system, and rejection of invalid
// specifications with messages that name the body, the field and the value as given (shortest
// round-trip text, never a fixed six decimals).
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "lib/model/planar/planar_system.hpp"

namespace impactbench::model::planar {
namespace {

using System = PlanarRigidBodySystemd;
constexpr double kG = 9.81;

BodySpec disk(const std::string& name, double radius, double mass) {
  BodySpec b;
  b.name = name;
  b.radius = radius;
  b.mass = mass;
  return b;
}

BodySpec box(const std::string& name, double width, double height, double mass) {
  BodySpec b;
  b.name = name;
  b.shape = ShapeKind::kBox;
  b.size = {width, height, 0.0};
  b.mass = mass;
  return b;
}

TEST(PlanarSystem, MassMatrixAndBiasForcesFollowTheShapes) {
  ForceInputSpec push{"block", Eigen::Vector3d(0.6, 0.8, 0.0)};
  const System system({disk("ball", 0.2, 3.0), box("block", 0.4, 0.3, 2.0)}, {}, kG, {}, {push});
  const Eigen::VectorXd q = Eigen::VectorXd::Zero(6);
  const Eigen::VectorXd m = Eigen::MatrixXd(system.mass_matrix(q)).diagonal();
  Eigen::VectorXd expected(6);
  expected << 3.0, 3.0, 0.5 * 3.0 * 0.04, 2.0, 2.0, 2.0 * (0.16 + 0.09) / 12.0;
  EXPECT_LT((m - expected).norm(), 1e-15);
  EXPECT_EQ(system.mass_matrix(q).nonZeros(), 6);

  Eigen::VectorXd h(6);
  h << 0.0, 3.0 * kG, 0.0, 0.0, 2.0 * kG, 0.0;  // M v̇ + H = 0 gives v̇_y = −g
  EXPECT_LT((system.bias_forces(q, Eigen::VectorXd::Ones(6)) - h).norm(), 1e-14);

  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(6, 1);
  s(3, 0) = 0.6;
  s(4, 0) = 0.8;
  EXPECT_EQ(system.input_matrix(q), s);
  EXPECT_EQ(system.num_inputs(), 1);
  EXPECT_EQ(system.tangent_dim(), 1);
}

// The system says M and H do not depend on the state (an integrator then forms M⁻¹ f once):
// both are the same, to the bit, at states far apart.
TEST(PlanarSystem, MassAndBiasForcesAreTheSameAtEveryStateAsItSays) {
  const System system({disk("ball", 0.2, 3.0), box("block", 0.4, 0.3, 2.0)}, {}, kG, {});
  ASSERT_TRUE(system.mass_matrix_is_constant());
  ASSERT_TRUE(system.bias_forces_are_constant());
  const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(6), v0 = Eigen::VectorXd::Zero(6);
  Eigen::VectorXd q(6), v(6);
  q << 3.0, -2.0, 1.3, -40.0, 7.5, -9.0;
  v << -12.0, 30.0, 200.0, 0.5, -0.25, -75.0;
  EXPECT_EQ(system.bias_forces(q, v), system.bias_forces(q0, v0));
  EXPECT_EQ(Eigen::MatrixXd(system.mass_matrix(q)), Eigen::MatrixXd(system.mass_matrix(q0)));
}

TEST(PlanarSystem, NamesFollowTheDesignOrder) {
  const System system({disk("ball", 0.2, 1.0), box("block", 0.4, 0.3, 1.0)}, {}, kG, {});
  EXPECT_EQ(system.position_names(),
            (std::vector<std::string>{"ball.x", "ball.y", "ball.theta", "block.x", "block.y",
                                      "block.theta"}));
  EXPECT_EQ(system.velocity_names(),
            (std::vector<std::string>{"ball.vx", "ball.vy", "ball.omega", "block.vx", "block.vy",
                                      "block.omega"}));
}

// Free flight under gravity by velocity Verlet (exact for constant acceleration up to rounding):
// the energy ½vᵀMv + Σ m g y must stay constant and the trajectory must be the parabola.
TEST(PlanarSystem, FreeFlightConservesEnergyAndFollowsTheParabola) {
  BodySpec ball = disk("ball", 0.2, 3.0);
  ball.velocity = {1.5, 4.0, 0.0};
  ball.angular_velocity = {0.0, 0.0, 7.0};
  BodySpec block = box("block", 0.4, 0.3, 2.0);
  block.position = {1.0, 2.0, 0.0};
  block.angle = 0.3;
  block.velocity = {-0.5, 1.0, 0.0};
  block.angular_velocity = {0.0, 0.0, -2.0};
  const System system({ball, block}, {}, kG, {});
  Eigen::VectorXd q = system.initial_positions();
  Eigen::VectorXd v = system.initial_velocities();
  const Eigen::VectorXd q0 = q;
  const Eigen::VectorXd v0 = v;
  const Eigen::SparseMatrix<double> m = system.mass_matrix(q);
  const Eigen::VectorXd inverse_mass = Eigen::MatrixXd(m).diagonal().cwiseInverse();
  const double e0 = system.energy(q, v);
  EXPECT_NEAR(e0,
              0.5 * 3.0 * (1.5 * 1.5 + 16.0) + 0.5 * 0.5 * 3.0 * 0.04 * 49.0 + 0.5 * 2.0 * 1.25 +
                  0.5 * 2.0 * 0.25 / 12.0 * 4.0 + 2.0 * kG * 2.0,
              1e-12);

  const double h = 1e-4;
  const int steps = 10000;
  double worst = 0.0;
  for (int k = 0; k < steps; ++k) {
    const Eigen::VectorXd a = -inverse_mass.cwiseProduct(system.bias_forces(q, v));
    v += 0.5 * h * a;
    q = system.integrate_position(q, system.position_rate(q, v), h);
    v += 0.5 * h * a;
    worst = std::max(worst, std::abs(system.energy(q, v) - e0));
  }
  EXPECT_LT(worst, 1e-10 * e0);
  const double t = h * steps;
  Eigen::VectorXd q_exact = q0 + t * v0;
  q_exact(1) -= 0.5 * kG * t * t;
  q_exact(4) -= 0.5 * kG * t * t;
  EXPECT_LT((q - q_exact).cwiseAbs().maxCoeff(), 1e-9);
}

void expect_rejected(const std::vector<BodySpec>& bodies,
                     const std::vector<StaticPlaneSpec>& planes, Material material,
                     const std::vector<ForceInputSpec>& inputs,
                     const std::string& expected_fragment) {
  try {
    System system(bodies, planes, kG, material, inputs);
    ADD_FAILURE() << "accepted, expected an error containing: " << expected_fragment;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(expected_fragment), std::string::npos)
        << "message: " << e.what() << "\nexpected: " << expected_fragment;
  }
}

TEST(PlanarSystem, RejectsInvalidSpecificationsNamingTheField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const BodySpec ok = disk("ok", 0.1, 1.0);
  expect_rejected({ok, disk("ball", 0.1, 0.0)}, {}, {}, {}, "body 'ball': mass must be");
  expect_rejected({disk("ball", 0.1, -2.5)}, {}, {}, {},
                  "body 'ball': mass must be finite and > 0, got -2.5");
  expect_rejected({disk("ball", 0.1, nan)}, {}, {}, {}, "body 'ball': mass must be");
  expect_rejected({disk("ball", 0.0, 1.0)}, {}, {}, {}, "body 'ball': radius must be");
  expect_rejected({disk("ball", -1e-7, 1.0)}, {}, {}, {},
                  "radius must be finite and > 0, got -1e-7");
  expect_rejected({box("block", 0.2, -0.1, 1.0)}, {}, {}, {},
                  "body 'block': size (width, height) must be finite and > 0, got (0.2, -0.1)");
  expect_rejected({box("block", nan, 0.1, 1.0)}, {}, {}, {}, "body 'block': size (width, height)");
  BodySpec sphere = disk("orb", 0.1, 1.0);
  sphere.shape = ShapeKind::kSphere;
  expect_rejected({sphere}, {}, {}, {}, "body 'orb': shape must be a disk or a box");
  BodySpec moving = disk("ball", 0.1, 1.0);
  moving.velocity.x() = nan;
  expect_rejected({moving}, {}, {}, {}, "body 'ball': initial position");
  expect_rejected({ok, ok}, {}, {}, {}, "body 'ok': duplicate name");
  StaticPlaneSpec flat;
  flat.name = "floor";
  flat.normal = Eigen::Vector3d::UnitZ();
  expect_rejected({ok}, {flat}, {}, {}, "plane 'floor': normal must be");
  expect_rejected({ok}, {}, {-0.1, 0.5}, {}, "friction must be finite and >= 0, got -0.1");
  expect_rejected({ok}, {}, {0.1, 1.5}, {}, "restitution must be in [0, 1], got 1.5");
  expect_rejected({ok}, {}, {}, {{"ghost", Eigen::Vector3d::UnitX()}}, "unknown body 'ghost'");
  expect_rejected({ok}, {}, {}, {{"ok", Eigen::Vector3d::UnitZ()}}, "input on body 'ok'");
}

TEST(PlanarSystem, RejectsWrongStateSizesAndNonFiniteStates) {
  const System system({disk("ball", 0.1, 1.0)}, {}, kG, {});
  std::vector<Contact<double>> contacts;
  const Eigen::VectorXd zero3 = Eigen::VectorXd::Zero(3);
  auto message_of = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v, double margin) {
    try {
      system.find_contacts(q, v, margin, contacts);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message_of(Eigen::VectorXd::Zero(2), zero3, 0.0).find("q has size 2, expected 3"),
            std::string::npos);
  EXPECT_NE(message_of(zero3, Eigen::VectorXd::Zero(4), 0.0).find("v has size 4, expected 3"),
            std::string::npos);
  EXPECT_NE(message_of(zero3, zero3, -1.25e-9)
                .find("contact margin must be finite and >= 0, got -1.25e-9"),
            std::string::npos);
  const Eigen::VectorXd q_nan = Eigen::Vector3d(0.0, std::numeric_limits<double>::quiet_NaN(), 0.0);
  EXPECT_NE(message_of(q_nan, zero3, 0.0).find("q of body 'ball' is not finite"),
            std::string::npos);
  EXPECT_THROW(system.energy(zero3, Eigen::VectorXd::Zero(4)), std::invalid_argument);
}

}  // namespace
}  // namespace impactbench::model::planar
