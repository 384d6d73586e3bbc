// Sensitivity of the plank–box (source appendix F) through a single corner impact (restitution
// e = 0.5) and through a simultaneous inelastic impact of both corners C_L and C_R, where the
// jump gain is conewise constant (source D.1–D.22). Frictionless contacts: no friction modes.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lib/model/plank_box/plank_box_system.hpp"
#include "lib/sensitivity/mechanical_hybrid_model.hpp"
#include "lib/sensitivity/sensitivity_csv.hpp"
#include "lib/sensitivity/trajectory_sensitivity.hpp"
#include "tests/support/lib/finite_difference.hpp"
#include "tests/support/lib/hybrid_reference_simulator.hpp"
#include "tests/support/lib/rk4.hpp"
#include "tests/support/lib/sensitivity_convergence.hpp"

namespace impactbench::sensitivity {
namespace {

using test_support::central_difference_jacobian;

using model::PlankBoxParameters;
using model::PlankBoxSystem;
constexpr int kLeft = 0, kRight = 1;

PlankBoxParameters frictionless(double restitution) {
  PlankBoxParameters p;
  p.friction = 0.0;
  p.restitution = restitution;
  return p;
}

/// Everything one plank–box scenario needs: systems, model, nominal run, sensitivity.
class PlankBoxCase {
 public:
  PlankBoxCase(double restitution, const Eigen::VectorXd& x0, double t_end)
      : system_(frictionless(restitution)),
        system_ad_(frictionless(restitution)),
        model_(system_, system_ad_) {
    setup_.model = &model_;
    setup_.mode0 = {ContactPhase::kOpen, ContactPhase::kOpen};
    setup_.x0 = x0;
    setup_.t_end = t_end;
    const ContactPhase after = restitution > 0 ? ContactPhase::kOpen : ContactPhase::kSlipPositive;
    setup_.options.impact_phase = {after, after};
    nominal_run_ = test_support::nominal_run_with_event_probes(setup_, 121);
  }

  NominalTrajectory nominal() const { return test_support::nominal_of(setup_, nominal_run_); }

  const MechanicalHybridModel& model() const { return model_; }
  const test_support::ConvergenceSetup& setup() const { return setup_; }
  const test_support::ReferenceRun& nominal_run() const { return nominal_run_; }
  const PlankBoxSystem<double>& system() const { return system_; }

 private:
  PlankBoxSystem<double> system_;
  PlankBoxSystem<AutoDiff> system_ad_;
  MechanicalHybridModel model_;
  test_support::ConvergenceSetup setup_;
  test_support::ReferenceRun nominal_run_;
};

/// Box tilted by 0.15 rad, lowest corner (C_L) 5 cm above the horizontal plank, all at rest.
Eigen::VectorXd tilted_drop() {
  const PlankBoxParameters p = frictionless(0.5);
  const double tilt = 0.15;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(8);
  x << 0.5,
      0.5 * p.plank_thickness + 0.05 + 0.5 * p.box_length * std::sin(tilt) +
          0.5 * p.box_height * std::cos(tilt),
      tilt, 0.0, 0.0, 0.0, 0.0, 0.0;
  return x;
}

/// A state whose two corners touch the plank at once (box parallel to the plank, resting on
/// it, both corners approaching), integrated backwards by `before` seconds in free flight.
Eigen::VectorXd simultaneous_landing(double before, const MechanicalHybridModel& model) {
  const PlankBoxParameters p = frictionless(0.0);
  const double phi = -0.03, s = 0.55;
  const Eigen::Vector2d e1(std::cos(phi), std::sin(phi)), e2(-std::sin(phi), std::cos(phi));
  const Eigen::Vector2d centre = s * e1 + 0.5 * (p.plank_thickness + p.box_height) * e2;
  Eigen::VectorXd x(8);
  x << centre.x(), centre.y(), phi, phi, 0.2, -1.2, 0.9, 0.5;
  const HybridMode open{ContactPhase::kOpen, ContactPhase::kOpen};
  const test_support::StateDerivative backwards = [&](double, const Eigen::VectorXd& xs) {
    return Eigen::VectorXd(-model.flow(open, xs, Eigen::VectorXd::Zero(3)));
  };
  return test_support::integrate_rk4(backwards, 0.0, x, before, 2000);
}

class PlankBoxSingleImpact : public ::testing::Test {
 protected:
  PlankBoxSingleImpact() : case_(0.5, tilted_drop(), 0.15) {}
  PlankBoxCase case_;
};

TEST_F(PlankBoxSingleImpact, NominalHasOneImpactOfTheLowerCorner) {
  ASSERT_EQ(case_.nominal_run().events.size(), 1u);
  EXPECT_EQ(case_.nominal_run().events[0].event.contact, kLeft);
  EXPECT_EQ(case_.nominal_run().events[0].event.kind, GuardKind::kImpact);
}

// Ξ = R + (f⁺ − R f⁻) n_γᵀ / (n_γᵀ f⁻), every ingredient by central differences of the model's
// plain (double) functions: independent of the AD linearisation and of compute_jump_gain.
TEST_F(PlankBoxSingleImpact, JumpGainIsTheClassicalSaltationMatrix) {
  const TrajectorySensitivity sensitivity(case_.model(), case_.nominal());
  ASSERT_EQ(sensitivity.events().size(), 1u);
  const ConewiseJumpGain& event = sensitivity.events()[0];
  const MicroEvent impact = event.events()[0];
  const HybridMode open = event.mode_before();
  const Eigen::VectorXd x_minus = event.x_minus();
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(3);
  const MechanicalHybridModel& model = case_.model();
  const Eigen::MatrixXd R = central_difference_jacobian(
      [&](const Eigen::VectorXd& x) { return model.reset(open, impact, x); }, x_minus, 1e-6);
  const Eigen::RowVectorXd n = central_difference_jacobian(
      [&](const Eigen::VectorXd& x) {
        return Eigen::VectorXd::Constant(1, model.guard_value(open, impact, x, u));
      },
      x_minus, 1e-6);
  const Eigen::VectorXd f_minus = model.flow(open, x_minus, u);
  const Eigen::VectorXd f_plus = model.flow(open, model.reset(open, impact, x_minus), u);
  const Eigen::MatrixXd saltation = R + (f_plus - R * f_minus) * n / n.dot(f_minus);
  const ComposedGain gain = event.gain_of_order({0});
  EXPECT_LT((gain.Gz - saltation).lpNorm<Eigen::Infinity>(),
            1e-6 * saltation.lpNorm<Eigen::Infinity>())
      << "G_z\n"
      << gain.Gz << "\nsaltation\n"
      << saltation;
  EXPECT_EQ(gain.Gv.norm(), 0.0);
  // Sanity of the impact law itself: ζ_n⁺ = −e ζ_n⁻ at the impacting corner.
  const Eigen::MatrixXd zeta_minus = model.relative_velocities(x_minus);
  const Eigen::MatrixXd zeta_plus = model.relative_velocities(event.x_plus());
  EXPECT_NEAR(zeta_plus(kLeft, 0), -0.5 * zeta_minus(kLeft, 0), 1e-12);
}

TEST_F(PlankBoxSingleImpact, PredictionErrorShrinksLikeEpsilonSquared) {
  const TrajectorySensitivity sensitivity(case_.model(), case_.nominal());
  std::mt19937 rng(11);
  std::vector<test_support::PerturbationDirection> directions;
  for (int k = 0; k < 20; ++k)
    directions.push_back(test_support::random_direction(case_.setup(), rng));
  test_support::expect_second_order(case_.setup(), case_.nominal_run(), sensitivity, directions,
                                    "plank_box single impact");
}

class PlankBoxSimultaneousImpact : public ::testing::Test {
 protected:
  PlankBoxSimultaneousImpact()
      : system_(frictionless(0.0)),
        system_ad_(frictionless(0.0)),
        model_(system_, system_ad_),
        case_(0.0, simultaneous_landing(0.1, model_), 0.3) {}

  /// The first micro event's order indicator s(d) = Δ_L − Δ_R, linear in the direction
  /// d = (z0, v0, v1): s < 0 selects C_L first.
  double order_indicator(const TrajectorySensitivity& sensitivity,
                         const test_support::PerturbationDirection& d) const {
    const double tau = sensitivity.nominal().events[0].time;
    const Eigen::VectorXd z = sensitivity.perturbation(d.z0, d.input(), {tau})[0];
    const Eigen::VectorXd v = d.input()(tau);
    const JumpGain& left = sensitivity.events()[0].micro_event({kLeft}).gain;
    const JumpGain& right = sensitivity.events()[0].micro_event({kRight}).gain;
    return (left.a - right.a).dot(z) + (left.b - right.b).dot(v);
  }

  PlankBoxSystem<double> system_;
  PlankBoxSystem<AutoDiff> system_ad_;
  MechanicalHybridModel model_;
  PlankBoxCase case_;
};

TEST_F(PlankBoxSimultaneousImpact, BothCornersLandAtOnceAndTheOrderDoesNotChangeTheNominal) {
  ASSERT_EQ(case_.nominal_run().events.size(), 2u);
  EXPECT_NEAR(case_.nominal_run().events[0].time, 0.1, 1e-10);
  EXPECT_NEAR(case_.nominal_run().events[1].time, 0.1, 1e-10);
  const TrajectorySensitivity sensitivity(case_.model(), case_.nominal());
  ASSERT_EQ(sensitivity.events().size(), 1u);
  const ConewiseJumpGain& event = sensitivity.events()[0];
  ASSERT_EQ(event.events().size(), 2u);
  // Inelastic impacts are nested projections: g_R ∘ g_L = g_L ∘ g_R.
  EXPECT_LT(event.order_dependence(), 1e-12);
  // …but the gains of the two orders differ: the jump gain is only conewise constant.
  const ComposedGain lr = event.gain_of_order({kLeft, kRight});
  const ComposedGain rl = event.gain_of_order({kRight, kLeft});
  EXPECT_GT((lr.Gz - rl.Gz).lpNorm<Eigen::Infinity>(), 1e-2 * lr.Gz.lpNorm<Eigen::Infinity>())
      << "C_L first\n"
      << lr.Gz << "\nC_R first\n"
      << rl.Gz;
}

TEST_F(PlankBoxSimultaneousImpact, EachConesGainPredictsToSecondOrder) {
  const TrajectorySensitivity sensitivity(case_.model(), case_.nominal());
  std::mt19937 rng(5);
  // The order indicator is linear in d; mirror each random direction across its zero set so
  // that both cones get the same number of directions.
  const int dims = 8 + 3 + 3;
  Eigen::VectorXd w(dims);
  const auto unpack = [](const Eigen::VectorXd& flat) {
    test_support::PerturbationDirection d;
    d.z0 = flat.head(8);
    d.v0 = flat.segment(8, 3);
    d.v1 = flat.tail(3);
    return d;
  };
  for (int i = 0; i < dims; ++i)
    w(i) = order_indicator(sensitivity, unpack(Eigen::VectorXd::Unit(dims, i)));
  std::vector<test_support::PerturbationDirection> left_first, right_first;
  for (int k = 0; k < 10; ++k) {
    const auto d = test_support::random_direction(case_.setup(), rng);
    Eigen::VectorXd flat(dims);
    flat << d.z0, d.v0, d.v1;
    const Eigen::VectorXd mirror = flat - 2 * w.dot(flat) / w.squaredNorm() * w;
    for (const Eigen::VectorXd& candidate : {flat, mirror}) {
      const auto direction = unpack(candidate);
      const double tau = sensitivity.nominal().events[0].time;
      const Eigen::VectorXd z = sensitivity.perturbation(direction.z0, direction.input(), {tau})[0];
      const std::vector<int> order = sensitivity.events()[0].order_for(z, direction.input()(tau));
      EXPECT_EQ(order[0] == kLeft, order_indicator(sensitivity, direction) < 0);
      (order[0] == kLeft ? left_first : right_first).push_back(direction);
    }
  }
  ASSERT_EQ(left_first.size(), 10u);
  ASSERT_EQ(right_first.size(), 10u);
  test_support::expect_second_order(case_.setup(), case_.nominal_run(), sensitivity, left_first,
                                    "plank_box simultaneous, C_L first");
  test_support::expect_second_order(case_.setup(), case_.nominal_run(), sensitivity, right_first,
                                    "plank_box simultaneous, C_R first");
}

TEST_F(PlankBoxSimultaneousImpact, TheWrongConesGainIsOnlyFirstOrderAccurate) {
  // Control experiment: predicting a C_L-first perturbation with the C_R-first gain leaves an
  // O(ε) error (ratio ≈ 2), so the ε² test above discriminates between the cones.
  const TrajectorySensitivity sensitivity(case_.model(), case_.nominal());
  std::mt19937 rng(3);
  const auto d = test_support::random_direction(case_.setup(), rng);
  const double tau = sensitivity.nominal().events[0].time;
  const Eigen::VectorXd z_tau = sensitivity.perturbation(d.z0, d.input(), {tau})[0];
  const std::vector<int> chosen = sensitivity.events()[0].order_for(z_tau, d.input()(tau));
  const ComposedGain wrong = sensitivity.events()[0].gain_of_order({chosen[1], chosen[0]});
  const ComposedGain right = sensitivity.events()[0].gain_of_order(chosen);
  const Eigen::VectorXd v_tau = d.input()(tau);
  const Eigen::VectorXd z_right = right.Gz * z_tau + right.Gv * v_tau;
  const Eigen::VectorXd z_wrong = wrong.Gz * z_tau + wrong.Gv * v_tau;
  EXPECT_GT((z_right - z_wrong).norm(), 1e-2 * z_right.norm());
  // The end-point matrix of the chosen cone reproduces the trajectory's end value.
  const InputBasis basis = [](double t) {
    Eigen::MatrixXd V(3, 6);
    V << Eigen::Matrix3d::Identity(), t * Eigen::Matrix3d::Identity();
    return V;
  };
  Eigen::VectorXd p(6);
  p << d.v0, d.v1;
  const EndPointSensitivity end = sensitivity.end_point_sensitivity(basis, d.z0, p);
  const Eigen::VectorXd z_end =
      sensitivity.perturbation(d.z0, d.input(), {sensitivity.nominal().t_end})[0];
  EXPECT_LT((end.state * d.z0 + end.input * p - z_end).norm(), 1e-9 * z_end.norm());
  EXPECT_EQ(end.orders[0], chosen);
}

TEST_F(PlankBoxSimultaneousImpact, ConewiseGainIsPositivelyHomogeneous) {
  const TrajectorySensitivity sensitivity(case_.model(), case_.nominal());
  const ConewiseJumpGain& event = sensitivity.events()[0];
  std::mt19937 rng(9);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int k = 0; k < 20; ++k) {
    Eigen::VectorXd z(8), v(3);
    for (int i = 0; i < 8; ++i) z(i) = normal(rng);
    for (int i = 0; i < 3; ++i) v(i) = normal(rng);
    const Eigen::VectorXd h = event.apply(z, v);
    for (const double a : {1e-6, 0.37, 1.0, 25.0, 1e4}) {
      const Eigen::VectorXd ha = event.apply(a * z, a * v);
      EXPECT_LT((ha - a * h).norm(), 1e-12 * a * h.norm()) << "a = " << a;
    }
  }
}

// The CSV writers: every gain of every order and the end-point matrices, read back at full
// precision; the prediction series for tools/plot_sensitivity.py. Set
// IMPACTBENCH_SENSITIVITY_OUT=DIR to keep the files (e.g. to plot them).
TEST_F(PlankBoxSimultaneousImpact, WritesGainsAndPredictionCsv) {
  const TrajectorySensitivity sensitivity(case_.model(), case_.nominal());
  const char* keep = std::getenv("IMPACTBENCH_SENSITIVITY_OUT");
  const std::filesystem::path dir =
      keep != nullptr ? std::filesystem::path(keep)
                      : std::filesystem::temp_directory_path() / "impactbench_sensitivity_test";
  std::filesystem::create_directories(dir);
  const InputBasis constant = [](double) { return Eigen::MatrixXd(Eigen::Matrix3d::Identity()); };
  const EndPointSensitivity end = sensitivity.end_point_sensitivity(constant);
  write_sensitivity_csv_file(dir / "plank_box_gains.csv", sensitivity, end);

  std::ifstream in(dir / "plank_box_gains.csv");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "kind,event,t,order,micro_events,matrix,row,col,value");
  int jump_rows = 0, end_rows = 0;
  bool found = false;
  const ComposedGain rl = sensitivity.events()[0].gain_of_order({kRight, kLeft});
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream row(line);
    for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
    ASSERT_EQ(fields.size(), 9u) << line;
    (fields[0] == "jump_gain" ? jump_rows : end_rows) += 1;
    if (fields[0] == "jump_gain" && fields[3] == "1 0" && fields[5] == "Gz" && fields[6] == "2" &&
        fields[7] == "7") {
      found = true;
      EXPECT_EQ(std::stod(fields[8]), rl.Gz(2, 7));
      EXPECT_EQ(fields[4], "1:impact->slip+ 0:impact->slip+");
    }
  }
  EXPECT_TRUE(found);
  EXPECT_EQ(jump_rows, 2 * (8 * 8 + 8 * 3));  // two orders, Gz and Gv each
  EXPECT_EQ(end_rows, 8 * 8 + 8 * 3);

  // A visible perturbation (ε = 0.02) for the plot.
  std::mt19937 rng(1);
  const auto d = test_support::random_direction(case_.setup(), rng);
  const double eps = 0.02;
  PredictionSeries series;
  for (const auto& name : case_.system().position_names()) series.state_names.push_back(name);
  for (const auto& name : case_.system().velocity_names()) series.state_names.push_back(name);
  for (int i = 0; i <= 300; ++i) series.times.push_back(case_.setup().t_end * i / 300);
  const auto perturbed = test_support::simulate_reference(
      case_.model(), case_.setup().mode0, case_.setup().x0 + eps * d.z0,
      [&](double t) { return Eigen::VectorXd(eps * d.input()(t)); }, 0.0, case_.setup().t_end,
      series.times, case_.setup().options);
  const auto z = sensitivity.perturbation(d.z0, d.input(), series.times);
  for (std::size_t i = 0; i < series.times.size(); ++i) {
    series.nominal.push_back(sensitivity.nominal_state(series.times[i]));
    series.perturbed.push_back(perturbed.states[i]);
    series.predicted.push_back(series.nominal.back() + eps * z[i]);
  }
  write_prediction_csv_file(dir / "plank_box_prediction.csv", series);
  std::ifstream prediction(dir / "plank_box_prediction.csv");
  int lines = 0;
  for (std::string l; std::getline(prediction, l);) ++lines;
  EXPECT_EQ(lines, 302);
  // Away from the event the prediction is within O(ε²) of the perturbed run.
  EXPECT_LT((series.predicted[30] - series.perturbed[30]).lpNorm<Eigen::Infinity>(), 1e-2);
  // The module's own nominal (RK4 + Hermite) agrees with the reference run.
  for (std::size_t k = 0; k < case_.nominal_run().times.size(); k += 10)
    EXPECT_LT(
        (sensitivity.nominal_state(case_.nominal_run().times[k]) - case_.nominal_run().states[k])
            .lpNorm<Eigen::Infinity>(),
        1e-9);
  if (keep == nullptr) std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace impactbench::sensitivity
