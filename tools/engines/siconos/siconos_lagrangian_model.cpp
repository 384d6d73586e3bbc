#include "tools/engines/siconos/siconos_lagrangian_model.hpp"

#include <siconos/kernel/BlockVector.hpp>
#include <siconos/kernel/Interaction.hpp>
#include <siconos/kernel/LagrangianDS.hpp>
#include <siconos/kernel/LagrangianScleronomousR.hpp>
#include <siconos/kernel/NewtonImpactFrictionNSL.hpp>
#include <siconos/kernel/NonSmoothDynamicalSystem.hpp>
#include <siconos/kernel/SiconosVector.hpp>
#include <siconos/kernel/SimpleMatrix.hpp>

#include "tools/engines/siconos/siconos_guard.hpp"
#include "tools/engines/siconos/siconos_moreau_jean_stepping.hpp"

namespace impactbench::adapters::siconos {
namespace {

Eigen::VectorXd eigen_vector(const SiconosVector& v) {
  Eigen::VectorXd x(v.size());
  for (unsigned i = 0; i < v.size(); ++i) x[i] = v(i);
  return x;
}

Eigen::VectorXd eigen_vector(const BlockVector& v) {
  Eigen::VectorXd x(v.size());
  for (unsigned i = 0; i < v.size(); ++i) x[i] = v(i);
  return x;
}

void copy_into(const Eigen::MatrixXd& from, SiconosMatrix& to) {
  for (unsigned r = 0; r < from.rows(); ++r)
    for (unsigned c = 0; c < from.cols(); ++c) to.setValue(r, c, from(r, c));
}

// The forces and their Jacobians from the callback, into the base class's _forces and force
// Jacobians (allocated here: MoreauJeanOSI computes the forces before the base class would).
// A zero _fInt tells Siconos the forces depend on q and v (never read: computeForces is
// replaced).
class CallbackDS : public LagrangianDS {
 public:
  explicit CallbackDS(const LagrangianProblem& problem)
      : LagrangianDS(siconos_vector(problem.q0), siconos_vector(problem.v0),
                     std::make_shared<SimpleMatrix>(static_cast<unsigned>(problem.mass.rows()),
                                                    static_cast<unsigned>(problem.mass.cols()))),
        forces_(problem.forces) {
    copy_into(problem.mass, *_mass);
    const auto n = static_cast<unsigned>(problem.q0.size());
    setFIntPtr(std::make_shared<SiconosVector>(n));
    _forces = std::make_shared<SiconosVector>(n);
    _jacobianqForces = std::make_shared<SimpleMatrix>(n, n);
    _jacobianqDotForces = std::make_shared<SimpleMatrix>(n, n);
  }

  void computeForces(double time, SP::SiconosVector q, SP::SiconosVector velocity) override {
    last_ = forces_(time, eigen_vector(*q), eigen_vector(*velocity));
    for (unsigned i = 0; i < _forces->size(); ++i) (*_forces)(i) = last_.f[i];
  }
  void computeJacobianqForces(double time) override {
    refresh(time);
    copy_into(last_.dq, *_jacobianqForces);
  }
  void computeJacobianvForces(double time) override {
    refresh(time);
    copy_into(last_.dv, *_jacobianqDotForces);
  }

 private:
  // The Jacobians at the current state (Siconos asks for them after computeForces of the same
  // state, but not always: recomputed from the current q and v to be sure).
  void refresh(double time) { last_ = forces_(time, eigen_vector(*_q[0]), eigen_vector(*_q[1])); }

  std::function<LagrangianForces(double, const Eigen::VectorXd&, const Eigen::VectorXd&)> forces_;
  LagrangianForces last_;
};

// y = (gap, 0, ...) and its Jacobian [w_nᵀ; W_tᵀ] from the callback. The tangential outputs are
// left at 0: only their velocities W_tᵀ v enter the velocity-level friction law.
class CallbackRelation : public LagrangianScleronomousR {
 public:
  CallbackRelation(int contact, int dofs, int rows,
                   std::function<ContactKinematics(int, const Eigen::VectorXd&)> kinematics,
                   std::shared_ptr<std::vector<Eigen::VectorXd>> jacobian_points)
      : contact_(contact),
        kinematics_(std::move(kinematics)),
        jacobian_points_(std::move(jacobian_points)) {
    _jachq =
        std::make_shared<SimpleMatrix>(static_cast<unsigned>(rows), static_cast<unsigned>(dofs));
  }

  void computeh(const BlockVector& q, BlockVector&, SiconosVector& y) override {
    y.zero();
    y(0) = kinematics_(contact_, eigen_vector(q)).gap;
  }
  void computeJachq(const BlockVector& q, BlockVector&) override {
    const Eigen::VectorXd at = eigen_vector(q);
    if (jacobian_points_->empty() || jacobian_points_->back() != at)
      jacobian_points_->push_back(at);
    copy_into(kinematics_(contact_, at).jacobian, *_jachq);
  }

 private:
  int contact_;
  std::function<ContactKinematics(int, const Eigen::VectorXd&)> kinematics_;
  std::shared_ptr<std::vector<Eigen::VectorXd>> jacobian_points_;  // the model's, this step
};

}  // namespace

struct LagrangianModel::Parts {
  std::shared_ptr<CallbackDS> ds;
  std::unique_ptr<MoreauJeanStepping> stepping;
  // Where the relations computed their Jacobians during the current step, in order.
  std::shared_ptr<std::vector<Eigen::VectorXd>> jacobian_points =
      std::make_shared<std::vector<Eigen::VectorXd>>();
};

LagrangianModel::LagrangianModel(const LagrangianProblem& problem, const Scheme& scheme,
                                 const NewtonLoop& newton)
    : parts_(std::make_unique<Parts>()) {
  guarded([&] {
    auto nsds = std::make_shared<NonSmoothDynamicalSystem>(0.0, scheme.duration);
    parts_->ds = std::make_shared<CallbackDS>(problem);
    nsds->insertDynamicalSystem(parts_->ds);
    std::vector<SP::Interaction> interactions;
    for (int c = 0; c < problem.contacts; ++c) {
      auto relation = std::make_shared<CallbackRelation>(
          c, static_cast<int>(problem.q0.size()), scheme.contact_dimension, problem.kinematics,
          parts_->jacobian_points);
      auto law = std::make_shared<NewtonImpactFrictionNSL>(
          problem.restitution.at(static_cast<std::size_t>(c)), 0.0,
          problem.friction.at(static_cast<std::size_t>(c)), scheme.contact_dimension);
      auto interaction = std::make_shared<Interaction>(law, relation);
      nsds->link(interaction, parts_->ds);
      interactions.push_back(interaction);
    }
    parts_->stepping = std::make_unique<MoreauJeanStepping>(nsds, interactions, scheme);
    TimeStepping& simulation = parts_->stepping->simulation();
    simulation.setNewtonOptions(SICONOS_TS_NONLINEAR);
    simulation.setNewtonTolerance(newton.tolerance);
    simulation.setNewtonMaxIteration(static_cast<unsigned>(newton.max_iterations));
    return 0;
  });
}

LagrangianModel::~LagrangianModel() = default;

void LagrangianModel::step() {
  guarded([&] {
    parts_->jacobian_points->clear();
    parts_->stepping->step();
    return 0;
  });
}

Eigen::VectorXd LagrangianModel::q() const {
  return eigen_vector(*parts_->ds->q());
}

Eigen::VectorXd LagrangianModel::v() const {
  return eigen_vector(*parts_->ds->velocity());
}

Eigen::VectorXd LagrangianModel::impulse(int contact) const {
  return parts_->stepping->impulse(contact);
}

int LagrangianModel::iterations() const {
  return parts_->stepping->iterations();
}

double LagrangianModel::residual() const {
  return parts_->stepping->residual();
}

Eigen::VectorXd LagrangianModel::law_frame_point() const {
  // Siconos evaluates the Jacobians at each Newton iterate before its contact problem and again
  // at the new state after the update: the last point before the final state is the one the
  // last contact problem used.
  const Eigen::VectorXd final_q = q();
  for (auto it = parts_->jacobian_points->rbegin(); it != parts_->jacobian_points->rend(); ++it)
    if (*it != final_q) return *it;
  return final_q;
}

int LagrangianModel::newton_iterations() const {
  return static_cast<int>(parts_->stepping->simulation().getNewtonNbIterations());
}

bool LagrangianModel::newton_converged() const {
  return parts_->stepping->simulation().isNewtonConverge();
}

}  // namespace impactbench::adapters::siconos
