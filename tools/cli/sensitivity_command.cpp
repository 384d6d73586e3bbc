// `impactbench sensitivity SCENARIO [--set k=v]... [--duration T] [--tol T] --out gains.csv
//  [--parameter-gains] [--prediction pred.csv [--epsilon E] [--seed N]]`
// First-order sensitivity of a scenario's event-driven trajectory (source C, D): runs the
// event-driven integrator, linearises along its run (lib/sensitivity) and writes the jump gains
// of every event (every order of simultaneous micro events) and the end-point matrix (state
// columns and one column per input channel for a constant input perturbation). With
// --prediction it also re-simulates one random perturbation of size ε and writes the nominal,
// perturbed and first-order predicted trajectories for tools/plot_sensitivity.py.
// Planar and spatial rigid-body scenarios and the plank–box. Spatial gains are written in tangent
// coordinates (orientation perturbations as world rotation vectors, sensitivity_csv.hpp). With
// --parameter-gains the friction coefficient μ and restitution e join the state (zero flow), so
// the gains and the end-point matrix get two more rows and columns: how the trajectory moves
// with μ and e.
#include "tools/cli/sensitivity_command.hpp"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <Eigen/LU>

#include "lib/sensitivity/sensitivity_csv.hpp"
#include "tools/cli/output_paths.hpp"
#include "tools/cli/overrides.hpp"
#include "tools/cli/sensitivity_study.hpp"
#include "tools/cli/setting_flags.hpp"
#include "tools/engines/engine_names.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::cli {
namespace {

class SensitivityCommand : public Command {
 public:
  explicit SensitivityCommand(CLI::App* app) : Command(app) {
    app->add_option("scenario", name_, "Scenario name (see `impactbench list`)")->required();
    app->add_option("--duration", duration_, "Simulated time [s] (default: the scenario's)")
        ->check(kPositiveFinite);
    app->add_option("--tol", tolerance_, "Event-driven tolerance (default 1e-12)")
        ->check(kPositiveFinite);
    app->add_option("--set", sets_, "Override a parameter: name=value (repeatable)");
    app->add_option("--out", out_, "Jump gains and end-point matrix CSV to write")->required();
    app->add_option("--prediction", prediction_,
                    "Also write nominal/perturbed/predicted trajectories of one random "
                    "perturbation to this CSV");
    app->add_option("--epsilon", epsilon_, "Size of that perturbation (default 1e-3)")
        ->check(kPositiveFinite);
    app->add_option("--seed", seed_, "Seed of its random direction (default 1)");
    app->add_flag("--parameter-gains", parameter_gains_,
                  "Append the friction coefficient and the restitution to the state (gains with "
                  "respect to mu and e)");
  }

  int run() override {
    auto s = scenario::load_scenario_by_name(name_, parse_overrides(sets_), duration_);
    if (s.supports_engine(engine_name::kEvent)) {  // else the study names the problem first
      check_output_path(out_, "--out");
      if (prediction_) {
        check_output_path(*prediction_, "--prediction");
        check_distinct_outputs({{"--out", out_}, {"--prediction", *prediction_}});
      }
    }
    const SensitivityStudy study(std::move(s), duration_, tolerance_, parameter_gains_);
    const sensitivity::TrajectorySensitivity& linearisation = study.linearisation();
    // Everything is computed before the first file is written, so a failed prediction run
    // leaves no gains file behind.
    std::optional<sensitivity::PredictionSeries> series;
    if (prediction_) series = predict(study);
    sensitivity::write_sensitivity_outputs(out_, linearisation, study.end_point(),
                                           prediction_ ? &*prediction_ : nullptr,
                                           series ? &*series : nullptr);
    std::cout << "sensitivity: " << linearisation.nominal().events.size()
              << " events linearised, gains in " << out_.string() << "\n";
    if (series) {
      std::cout << "sensitivity: prediction for eps = " << epsilon_ << " in "
                << prediction_->string() << "\n";
    }
    return 0;
  }

 private:
  /// Nominal, perturbed and first-order predicted states of one random perturbation.
  sensitivity::PredictionSeries predict(const SensitivityStudy& study) const {
    const sensitivity::MechanicalHybridModel& model = study.model();
    const engines::BuiltSystem& built = study.built();
    const sensitivity::TrajectorySensitivity& linearisation = study.linearisation();
    const sensitivity::InputFunction& input = study.input();
    const double duration = study.duration();
    const int n = model.state_size(), m = model.input_size();
    std::mt19937 rng(seed_);
    std::normal_distribution<double> normal;
    // A direction that keeps the initially closed contacts closed (null space of their rows).
    const Eigen::MatrixXd C =
        model.mode_constraint_rows(linearisation.nominal().mode0, linearisation.nominal().x0);
    const Eigen::MatrixXd basis =
        C.rows() > 0 ? Eigen::MatrixXd(Eigen::FullPivLU<Eigen::MatrixXd>(C).kernel())
                     : Eigen::MatrixXd(Eigen::MatrixXd::Identity(n, n));
    Eigen::VectorXd coefficients(basis.cols()), v(m);
    for (Eigen::Index i = 0; i < coefficients.size(); ++i) coefficients(i) = normal(rng);
    for (int j = 0; j < m; ++j) v(j) = normal(rng);
    Eigen::VectorXd z0 = basis * coefficients;
    // The re-simulation perturbs the state and the input; μ and e stay at their values.
    z0.tail(model.num_parameters()).setZero();
    const double norm = std::sqrt(z0.squaredNorm() + v.squaredNorm());
    z0 /= norm;
    v /= norm;
    const double eps = epsilon_;
    const auto perturbed_run = study.integrator().simulate(
        built.q0 + eps * z0.head(built.q0.size()),
        built.v0 + eps * z0.segment(built.q0.size(), built.v0.size()),
        [&](double t) { return Eigen::VectorXd(input(t) + eps * v); }, duration);
    if (!perturbed_run.succeeded())
      throw CliError("perturbed event-driven run failed: " + perturbed_run.message, kExitFailure);
    sensitivity::PredictionSeries series;
    for (const auto& name : built.system->position_names()) series.state_names.push_back(name);
    for (const auto& name : built.system->velocity_names()) series.state_names.push_back(name);
    if (model.num_parameters() > 0)
      for (const char* name : {"friction", "restitution"}) series.state_names.emplace_back(name);
    for (const auto& sample : perturbed_run.samples) {
      if (!series.times.empty() && sample.t <= series.times.back()) continue;
      series.times.push_back(sample.t);
      series.perturbed.push_back(model.state(sample.q, sample.v));
      series.nominal.push_back(linearisation.nominal_state(sample.t));
    }
    const sensitivity::InputFunction constant_v = [v](double) { return v; };
    const auto z = linearisation.perturbation(z0, constant_v, series.times);
    for (std::size_t i = 0; i < series.times.size(); ++i)
      series.predicted.push_back(series.nominal[i] + eps * z[i]);
    return series;
  }

  std::string name_;
  std::optional<double> duration_;
  std::optional<double> tolerance_;
  std::vector<std::string> sets_;
  std::filesystem::path out_;
  std::optional<std::filesystem::path> prediction_;
  double epsilon_ = 1e-3;
  unsigned seed_ = 1;
  bool parameter_gains_ = false;
};

}  // namespace

std::unique_ptr<Command> add_sensitivity_command(CLI::App& app) {
  return std::make_unique<SensitivityCommand>(app.add_subcommand(
      "sensitivity", "Jump gains and end-point sensitivity of a scenario's event-driven run"));
}

}  // namespace impactbench::cli
