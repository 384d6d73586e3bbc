#include "tools/engines/bullet/bullet_engine.hpp"

#include <BulletDynamics/MLCPSolvers/btDantzigSolver.h>
#include <BulletDynamics/MLCPSolvers/btMLCPSolver.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>

#include <Eigen/Geometry>

#include "lib/model/body_inertia.hpp"
#include "lib/output/number_text.hpp"
#include "tools/engines/engine_names.hpp"
#include "tools/engines/fixed_step/boundary_slab.hpp"
#include "tools/engines/fixed_step/contact_frame.hpp"
#include "tools/engines/fixed_step/fixed_step_driver.hpp"
#include "tools/engines/fixed_step/scene_state.hpp"

namespace impactbench::adapters {
namespace {

constexpr double kBoundaryHalfLength = 200.0;  // [m]

btVector3 to_bt(const Eigen::Vector3d& v) {
  return btVector3(v.x(), v.y(), v.z());
}
Eigen::Vector3d to_eigen(const btVector3& v) {
  return Eigen::Vector3d(v.x(), v.y(), v.z());
}

// Bullet's world objects, destroyed in reverse order of creation.
struct BulletWorld {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  std::unique_ptr<btDantzigSolver> dantzig;
  std::unique_ptr<btConstraintSolver> solver;
  std::unique_ptr<btDiscreteDynamicsWorld> world;
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btDefaultMotionState>> motion_states;
  std::vector<std::unique_ptr<btRigidBody>> bodies;  // dynamic first, then boundaries
  std::vector<std::unique_ptr<btTypedConstraint>> joints;

  ~BulletWorld() {
    for (auto& j : joints) world->removeConstraint(j.get());
    for (auto& b : bodies) world->removeRigidBody(b.get());
  }
};

// Bullet combines a pair's friction and restitution as the product of the two bodies' values:
// every body and boundary gets √μ and √e, so that every pair, body–body and body–boundary
// alike, gets the scenario's μ and e (giving bodies μ and boundaries 1 made body–body pairs
// μ² and e²).
void set_material(btRigidBody& body, const model::Material& material) {
  body.setFriction(std::sqrt(material.friction));
  body.setRestitution(std::sqrt(material.restitution));
}

std::unique_ptr<btCollisionShape> make_shape(const model::BodySpec& body, bool planar,
                                             double margin) {
  switch (body.shape) {
    case model::ShapeKind::kDisk:
    case model::ShapeKind::kSphere:
      return std::make_unique<btSphereShape>(body.radius);
    case model::ShapeKind::kBox: {
      const double depth = std::max(body.size.x(), body.size.y());
      auto box =
          std::make_unique<btBoxShape>(btVector3(body.size.x() / 2, body.size.y() / 2, depth / 2));
      box->setMargin(margin);
      return box;
    }
    case model::ShapeKind::kCuboid: {
      auto box = std::make_unique<btBoxShape>(to_bt(body.size / 2));
      box->setMargin(margin);
      return box;
    }
  }
  (void)planar;
  throw std::logic_error("unknown shape");
}

btVector3 local_inertia(const model::BodySpec& body, const btCollisionShape& shape) {
  btVector3 inertia;
  shape.calculateLocalInertia(body.mass, inertia);
  if (body.shape == model::ShapeKind::kDisk) {
    // A disk, not a ball: only the z inertia matters in the plane.
    const double izz = 0.5 * body.mass * body.radius * body.radius;
    inertia = btVector3(izz, izz, izz);
  }
  if (body.inertia) inertia = to_bt(model::principal_inertia(body));
  return inertia;
}

// Bullet reads its contact breaking threshold from the process global gContactBreakingThreshold,
// and not only where a contact manifold is made (btCollisionDispatcher::getNewManifold, which a
// dispatcher could override per world): btCollisionWorld::updateSingleAabb, which is not
// virtual, widens every object's bounding box by it, which decides the broadphase's pairs. So
// no per-world setting gives the same contacts; the run sets the global for its lifetime and
// puts the previous value back.
class ScopedContactBreakingThreshold {
 public:
  explicit ScopedContactBreakingThreshold(double threshold) : saved_(gContactBreakingThreshold) {
    gContactBreakingThreshold = threshold;
  }
  ~ScopedContactBreakingThreshold() { gContactBreakingThreshold = saved_; }
  ScopedContactBreakingThreshold(const ScopedContactBreakingThreshold&) = delete;
  ScopedContactBreakingThreshold& operator=(const ScopedContactBreakingThreshold&) = delete;

 private:
  btScalar saved_;
};

// The solver and the world's solver information from the settings.
void set_up_solver(BulletWorld& w, const ReferenceScene& scene, const BulletSettings& settings) {
  if (settings.solver == BulletSolver::kMlcpDantzig) {
    w.dantzig = std::make_unique<btDantzigSolver>();
    w.solver = std::make_unique<btMLCPSolver>(w.dantzig.get());
  } else {
    w.solver = std::make_unique<btSequentialImpulseConstraintSolver>();
  }
  w.world = std::make_unique<btDiscreteDynamicsWorld>(&w.dispatcher, &w.broadphase, w.solver.get(),
                                                      &w.configuration);
  const Eigen::Vector3d up = scene.planar ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
  w.world->setGravity(to_bt(-scene.gravity * up));
  btContactSolverInfo& info = w.world->getSolverInfo();
  info.m_numIterations = settings.solver_iterations;
  info.m_splitImpulse = settings.split_impulse ? 1 : 0;
  // Bullet applies split impulse only to penetrations deeper than this (default −4 cm) and
  // Baumgarte (which adds energy) to shallower ones.
  info.m_splitImpulsePenetrationThreshold = -settings.split_impulse_depth;
  info.m_erp2 = settings.erp;
  info.m_restitutionVelocityThreshold = settings.restitution_threshold;
}

btRigidBody* add_body(BulletWorld& w, std::unique_ptr<btCollisionShape> shape, double mass,
                      const btVector3& inertia, const btTransform& pose) {
  w.motion_states.push_back(std::make_unique<btDefaultMotionState>(pose));
  btRigidBody::btRigidBodyConstructionInfo ci(mass, w.motion_states.back().get(), shape.get(),
                                              inertia);
  w.bodies.push_back(std::make_unique<btRigidBody>(ci));
  w.shapes.push_back(std::move(shape));
  btRigidBody* body = w.bodies.back().get();
  body->setActivationState(DISABLE_DEACTIVATION);  // sleeping would freeze the trajectory
  w.world->addRigidBody(body);
  return body;
}

void add_dynamic_body(BulletWorld& w, const model::BodySpec& spec, const ReferenceScene& scene,
                      const BulletSettings& settings, int index) {
  auto shape = make_shape(spec, scene.planar, settings.collision_margin);
  const btVector3 inertia = local_inertia(spec, *shape);
  btTransform pose;
  pose.setIdentity();
  pose.setOrigin(to_bt(spec.position));
  if (scene.planar) {
    pose.setRotation(btQuaternion(btVector3(0, 0, 1), spec.angle));
  } else {
    const auto& q = spec.orientation;
    pose.setRotation(btQuaternion(q.x(), q.y(), q.z(), q.w()));
  }
  btRigidBody* body = add_body(w, std::move(shape), spec.mass, inertia, pose);
  set_material(*body, scene.material);
  body->setLinearVelocity(to_bt(spec.velocity));
  body->setAngularVelocity(to_bt(spec.angular_velocity));
  if (scene.planar) {
    body->setLinearFactor(btVector3(1, 1, 0));
    body->setAngularFactor(btVector3(0, 0, 1));
  }
  body->setUserIndex(index);
}

// A hinged body turns about its anchor on a hinge about z to the world; its spring and damper
// are a torque applied before each step.
void add_hinge(BulletWorld& w, const HingeSpec& hinge) {
  btRigidBody* body = w.bodies[hinge.body].get();
  const btVector3 pivot =
      body->getCenterOfMassTransform().inverse() * to_bt(hinge.anchor);  // in the body frame
  const btVector3 axis =
      body->getCenterOfMassTransform().getBasis().transpose() * btVector3(0, 0, 1);
  w.joints.push_back(std::make_unique<btHingeConstraint>(*body, pivot, axis));
  w.world->addConstraint(w.joints.back().get(), /*disableCollisionsBetweenLinkedBodies=*/true);
}

void add_boundary(BulletWorld& w, const model::StaticPlaneSpec& plane,
                  const model::Material& material, int index) {
  const BoundarySlab slab = boundary_slab(plane, kBoundaryHalfLength);
  auto shape = std::make_unique<btBoxShape>(to_bt(slab.half_extents));
  const Eigen::Quaterniond rotation =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitY(), plane.normal.normalized());
  btTransform pose(btQuaternion(rotation.x(), rotation.y(), rotation.z(), rotation.w()),
                   to_bt(slab.centre));
  btRigidBody* body = add_body(w, std::move(shape), 0.0, btVector3(0, 0, 0), pose);
  set_material(*body, material);
  body->setUserIndex(index);
}

// A Bullet world of the scene, stepped by the fixed-step loop: the dynamic bodies first (user
// index = index into the names), their hinges, then the static boundaries.
class BulletScene : public FixedStepWorld {
 public:
  BulletScene(const ReferenceScene& scene, const BulletSettings& settings)
      : scene_(scene), settings_(settings), threshold_(settings.contact_breaking_threshold) {
    set_up_solver(w_, scene, settings);
    for (const auto& spec : scene.bodies) {
      add_dynamic_body(w_, spec, scene, settings, static_cast<int>(names_.size()));
      names_.push_back(spec.name);
    }
    for (const HingeSpec& hinge : scene.hinges) add_hinge(w_, hinge);
    for (const auto& plane : scene.planes) {
      add_boundary(w_, plane, scene.material, static_cast<int>(names_.size()));
      names_.push_back(plane.name);
    }
    states_.resize(scene.bodies.size());
  }

  void record_state(double t, engines::RunResult& result) override {
    for (std::size_t i = 0; i < states_.size(); ++i) {
      const btRigidBody& b = *w_.bodies[i];
      const btTransform& pose = b.getWorldTransform();
      const btQuaternion r = pose.getRotation();
      BodyState& s = states_[i];
      s.position = to_eigen(pose.getOrigin());
      s.orientation = Eigen::Quaterniond(r.w(), r.x(), r.y(), r.z());
      s.velocity = to_eigen(b.getLinearVelocity());
      s.angular_velocity = to_eigen(b.getAngularVelocity());
    }
    add_scene_sample(result, scene_, states_, t);
  }

  // The bodies' velocities at the start of the step: a closing pair's approach speed.
  void before_step(double) override {
    velocity_before_.clear();
    for (std::size_t i = 0; i < states_.size(); ++i)
      velocity_before_.emplace_back(w_.bodies[i]->getLinearVelocity(),
                                    w_.bodies[i]->getAngularVelocity());
  }

  void step(double t) override {
    for (const auto& [body, force] : input_forces(scene_, t))
      w_.bodies[body]->applyCentralForce(to_bt(force));
    for (const HingeSpec& hinge : scene_.hinges)
      w_.bodies[hinge.body]->applyTorque(
          btVector3(0, 0,
                    hinge_torque(hinge, planar_angle(states_[hinge.body].orientation),
                                 states_[hinge.body].angular_velocity.z())));
    w_.world->stepSimulation(scene_.dt, 0);
  }

  std::vector<engines::ClosedContact> read_step(double, engines::StepRecord& step,
                                                engines::RunResult& result) override {
    step.iterations = settings_.solver_iterations;
    std::vector<engines::ClosedContact> closed;
    const int manifolds = w_.dispatcher.getNumManifolds();
    for (int m = 0; m < manifolds; ++m) {
      engines::ClosedContact pair =
          read_manifold(*w_.dispatcher.getManifoldByIndexInternal(m), step, result);
      if (pair.approach_speed == -std::numeric_limits<double>::infinity()) continue;
      closed.push_back(std::move(pair));
    }
    step.active_contacts = static_cast<int>(step.contacts.size());
    return closed;
  }

 private:
  // Velocity of body's material point at p before the step (boundaries do not move).
  btVector3 velocity_before(const btRigidBody* body, const btVector3& p) const {
    const auto i = static_cast<std::size_t>(body->getUserIndex());
    if (i >= velocity_before_.size()) return btVector3(0, 0, 0);
    return velocity_before_[i].first +
           velocity_before_[i].second.cross(p - body->getCenterOfMassPosition());
  }

  // A manifold's points that touch or carry an impulse into step.contacts (Bullet keeps
  // separated points up to the breaking threshold), and the pair; its approach speed stays
  // −∞ when none does (the pair is not closed).
  engines::ClosedContact read_manifold(const btPersistentManifold& manifold,
                                       engines::StepRecord& step, engines::RunResult& result) {
    const auto* a = static_cast<const btRigidBody*>(manifold.getBody0());
    const auto* b = static_cast<const btRigidBody*>(manifold.getBody1());
    engines::ClosedContact pair{names_[a->getUserIndex()] + "-" + names_[b->getUserIndex()],
                                -std::numeric_limits<double>::infinity(), 0.0, 0.0};
    Eigen::Vector2d pair_friction = Eigen::Vector2d::Zero();
    for (int j = 0; j < manifold.getNumContacts(); ++j) {
      const btManifoldPoint& p = manifold.getContactPoint(j);
      if (p.getDistance() > 0.0 && p.getAppliedImpulse() == 0.0) continue;
      const btVector3 n = p.m_normalWorldOnB;  // points from B to A
      engines::ContactSample s = contact_sample(*a, *b, p, pair.name + "#" + std::to_string(j));
      const btVector3 before =
          velocity_before(a, p.getPositionWorldOnA()) - velocity_before(b, p.getPositionWorldOnB());
      s.velocity_n_before = before.dot(n);
      pair.approach_speed = std::max(pair.approach_speed, -s.velocity_n_before);
      pair.impulse_n += s.impulse_n;
      pair_friction += s.impulse_t;
      result.max_penetration = std::max(result.max_penetration, -s.gap);
      step.contacts.push_back(std::move(s));
    }
    pair.impulse_t = scene_.planar ? pair_friction.x() : pair_friction.norm();
    return pair;
  }

  engines::ContactSample contact_sample(const btRigidBody& a, const btRigidBody& b,
                                        const btManifoldPoint& p, std::string name) const {
    const btVector3 n = p.m_normalWorldOnB;  // points from B to A
    // Relative velocity of A with respect to B at the contact point.
    const btVector3 va =
        a.getVelocityInLocalPoint(p.getPositionWorldOnA() - a.getCenterOfMassPosition());
    const btVector3 vb =
        b.getVelocityInLocalPoint(p.getPositionWorldOnB() - b.getCenterOfMassPosition());
    const btVector3 rel = va - vb;
    const btVector3 vt = rel - rel.dot(n) * n;
    engines::ContactSample s;
    s.name = std::move(name);
    s.gap = p.getDistance();
    s.impulse_n = p.getAppliedImpulse();  // on A along n
    s.velocity_n = rel.dot(n);
    s.friction = scene_.material.friction;
    s.restitution = scene_.material.restitution;
    // Friction impulse on A, in a fixed tangent frame (planar: the in-plane tangent first) so
    // that impulse and sliding velocity are compared in the same components.
    const btVector3 friction_impulse = p.m_appliedImpulseLateral1 * p.m_lateralFrictionDir1 +
                                       p.m_appliedImpulseLateral2 * p.m_lateralFrictionDir2;
    const TangentFrame frame = tangent_frame(to_eigen(n), scene_.planar);
    s.impulse_t = frame.components(to_eigen(friction_impulse));
    s.velocity_t = frame.components(to_eigen(vt));
    return s;
  }

  const ReferenceScene& scene_;
  const BulletSettings& settings_;
  ScopedContactBreakingThreshold threshold_;  // set before the world is made, reset after it
  BulletWorld w_;
  std::vector<std::string> names_;
  std::vector<BodyState> states_;  // at the last state recorded
  std::vector<std::pair<btVector3, btVector3>> velocity_before_;
};

}  // namespace

engines::RunResult run_bullet(const ReferenceScene& scene, const BulletSettings& settings,
                              const engines::RecordingOptions& recording) {
  BulletScene world(scene, settings);
  // Rest measured from the exact contact: the margins lie inside the shapes.
  engines::RunResult result = scene_result(engine_name::kBullet, scene, recording);
  // The registry adds the settings in force.
  result.settings = {{"collision_margin", output::number_text(settings.collision_margin),
                      engines::SettingSource::kBuiltIn},
                     {"precision", "double", engines::SettingSource::kBuiltIn}};
  run_fixed_steps(world, {engine_name::kBullet, scene.dt, scene.duration, settings.impact, false},
                  result);
  result.unconverged_note =
      "Bullet runs a fixed number of solver iterations per step and has no tolerance to reach";
  return result;
}

}  // namespace impactbench::adapters
