#include "tools/engines/ode/ode_engine.hpp"

#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "lib/model/body_inertia.hpp"
#include "lib/output/number_text.hpp"
#include "tools/engines/engine_names.hpp"
#include "tools/engines/fixed_step/contact_frame.hpp"
#include "tools/engines/fixed_step/fixed_step_driver.hpp"
#include "tools/engines/fixed_step/scene_state.hpp"
#include "tools/engines/fixed_step/step_contacts.hpp"

namespace impactbench::adapters {
namespace {

constexpr auto kBuiltIn = engines::SettingSource::kBuiltIn;

Eigen::Vector3d to_eigen(const dReal* v) {
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

// ODE reports internal errors (e.g. a quaternion that cannot be normalised once the state has
// overflowed) through handlers that abort by default: throw instead, so the run fails with one
// line and writes nothing.
[[noreturn]] void throw_ode_error(int number, const char* format, va_list arguments) {
  char text[512];
  std::vsnprintf(text, sizeof text, format, arguments);
  throw std::runtime_error("ode: internal error " + std::to_string(number) + ": " + text +
                           " (the state is probably no longer finite)");
}

// ODE's library state is set up once per process (dInitODE2 is not reentrant).
void init_ode() {
  static std::once_flag once;
  std::call_once(once, [] {
    dInitODE2(0);
    dSetErrorHandler(throw_ode_error);
    dSetDebugHandler(throw_ode_error);
    dSetMessageHandler([](int, const char*, va_list) {});  // warnings: the metrics tell
  });
}

// The world, its collision space (which owns the geometries) and the step's contact joints,
// destroyed in reverse order.
struct OdeWorld {
  dWorldID world = dWorldCreate();
  dSpaceID space = dHashSpaceCreate(nullptr);
  dJointGroupID contact_joints = dJointGroupCreate(0);
  ~OdeWorld() {
    dJointGroupDestroy(contact_joints);
    dSpaceDestroy(space);
    dWorldDestroy(world);
  }
  OdeWorld() = default;
  OdeWorld(const OdeWorld&) = delete;
  OdeWorld& operator=(const OdeWorld&) = delete;
};

// One contact point of the step, created by the collision callback with its joint's feedback.
struct StepContact {
  int body1 = 0;   // index into the scene's bodies (always a dynamic body)
  int body2 = -1;  // -1: a boundary
  std::string name;
  dContactGeom geom{};  // normal from body 2 to body 1: body 1's force is +λ n
  dJointFeedback* feedback = nullptr;
};

// What the collision callback needs; contacts and feedback live until the next step.
struct Collision {
  const ReferenceScene* scene = nullptr;
  const OdeSettings* settings = nullptr;
  OdeWorld* world = nullptr;
  std::vector<std::string> names;  // bodies, then boundaries (geom data = index + 1)
  std::vector<StepContact> contacts;
  std::deque<dJointFeedback> feedback;  // stable addresses
  std::vector<dContactGeom> buffer;
};

int geom_index(dGeomID g) {
  return static_cast<int>(reinterpret_cast<std::uintptr_t>(dGeomGetData(g))) - 1;
}

void near_callback(void* data, dGeomID o1, dGeomID o2) {
  auto& c = *static_cast<Collision*>(data);
  dBodyID b1 = dGeomGetBody(o1), b2 = dGeomGetBody(o2);
  if (!b1) {
    std::swap(o1, o2);
    std::swap(b1, b2);
  }
  if (!b1 || (b2 && dAreConnected(b1, b2))) return;  // two boundaries, or joined bodies
  const int n = dCollide(o1, o2, c.settings->max_contacts, c.buffer.data(), sizeof(dContactGeom));
  const int i1 = geom_index(o1), i2 = geom_index(o2);
  const int nb = static_cast<int>(c.scene->bodies.size());
  for (int k = 0; k < n; ++k) {
    dContact contact{};
    contact.geom = c.buffer[k];
    const Eigen::Vector3d normal = to_eigen(contact.geom.normal);
    dSurfaceParameters& s = contact.surface;
    s.mode = dContactBounce;
    const double mu = c.scene->material.friction;
    if (c.settings->friction == engines::OdeFriction::kPyramid) {
      s.mode |= dContactApprox1;
      s.mu = mu;
    } else {
      // The box: a constant limit per direction, the pair's weight share (see ode_settings.hpp).
      s.mu = mu * c.scene->bodies[i1].mass * c.scene->gravity / n;
    }
    // The first friction direction: planar scenes the in-plane tangent; spatial ones the
    // sliding direction when the contact slides, so that the pyramid's facets hold the
    // Coulomb force exactly opposite to the slip (otherwise ODE's arbitrary tangent).
    Eigen::Vector3d fdir = Eigen::Vector3d::Zero();
    if (c.scene->planar) {
      fdir = tangent_frame(normal, true).e1;
    } else {
      dVector3 v1{}, v2{};
      const dReal* p = contact.geom.pos;
      dBodyGetPointVel(b1, p[0], p[1], p[2], v1);
      if (b2) dBodyGetPointVel(b2, p[0], p[1], p[2], v2);
      const Eigen::Vector3d rel = to_eigen(v1) - to_eigen(v2);
      const Eigen::Vector3d slip = rel - rel.dot(normal) * normal;
      if (slip.norm() > 1e-12) fdir = slip.normalized();
    }
    if (fdir.squaredNorm() > 0.0) {
      s.mode |= dContactFDir1;
      for (int a = 0; a < 3; ++a) contact.fdir1[a] = fdir[a];
    }
    s.bounce = c.scene->material.restitution;
    s.bounce_vel = c.settings->bounce_velocity;
    dJointID joint = dJointCreateContact(c.world->world, c.world->contact_joints, &contact);
    dJointAttach(joint, b1, b2);
    c.feedback.emplace_back();
    dJointSetFeedback(joint, &c.feedback.back());
    StepContact record;
    record.body1 = i1;
    record.body2 = i2 < nb ? i2 : -1;
    record.name = c.names[i1] + "-" + c.names[i2];
    record.geom = contact.geom;
    record.feedback = &c.feedback.back();
    c.contacts.push_back(std::move(record));
  }
}

dGeomID make_geom(dSpaceID space, const model::BodySpec& body) {
  switch (body.shape) {
    case model::ShapeKind::kDisk:
    case model::ShapeKind::kSphere:
      return dCreateSphere(space, body.radius);
    case model::ShapeKind::kBox: {
      const double depth = std::max(body.size.x(), body.size.y());
      return dCreateBox(space, body.size.x(), body.size.y(), depth);
    }
    case model::ShapeKind::kCuboid:
      return dCreateBox(space, body.size.x(), body.size.y(), body.size.z());
  }
  throw std::logic_error("unknown shape");
}

dMass make_mass(const model::BodySpec& body) {
  dMass m;
  switch (body.shape) {
    case model::ShapeKind::kDisk: {
      // A disk, not a ball: only the z inertia matters in the plane.
      const double izz = 0.5 * body.mass * body.radius * body.radius;
      dMassSetParameters(&m, body.mass, 0, 0, 0, izz, izz, izz, 0, 0, 0);
      break;
    }
    case model::ShapeKind::kSphere:
      dMassSetSphereTotal(&m, body.mass, body.radius);
      break;
    case model::ShapeKind::kBox:
      dMassSetBoxTotal(&m, body.mass, body.size.x(), body.size.y(),
                       std::max(body.size.x(), body.size.y()));
      break;
    case model::ShapeKind::kCuboid:
      dMassSetBoxTotal(&m, body.mass, body.size.x(), body.size.y(), body.size.z());
      break;
  }
  if (body.inertia) {  // given principal moments replace the uniform solid's
    const Eigen::Vector3d i = model::principal_inertia(body);
    dMassSetParameters(&m, body.mass, 0, 0, 0, i.x(), i.y(), i.z(), 0, 0, 0);
  }
  return m;
}

BodyState body_state(dBodyID b) {
  BodyState s;
  s.position = to_eigen(dBodyGetPosition(b));
  const dReal* q = dBodyGetQuaternion(b);  // (w, x, y, z)
  s.orientation = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
  s.velocity = to_eigen(dBodyGetLinearVel(b));
  s.angular_velocity = to_eigen(dBodyGetAngularVel(b));
  return s;
}

// An ODE world of the scene, stepped by the fixed-step loop: each body with its geometry and
// its joint (a hinge, or a plane-2D joint keeping a planar body in the plane), then the
// boundaries as half-spaces.
class OdeScene : public FixedStepWorld {
 public:
  OdeScene(const ReferenceScene& scene, const OdeSettings& settings)
      : scene_(scene), settings_(settings) {
    const Eigen::Vector3d up = scene.planar ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d g = -scene.gravity * up;
    dWorldSetGravity(w_.world, g.x(), g.y(), g.z());
    dWorldSetERP(w_.world, settings.erp);
    dWorldSetCFM(w_.world, settings.cfm);
    dWorldSetQuickStepNumIterations(w_.world, settings.quick_iterations);
    dWorldSetAutoDisableFlag(w_.world, 0);  // sleeping would freeze the trajectory
    collision_.scene = &scene;
    collision_.settings = &settings;
    collision_.world = &w_;
    collision_.buffer.resize(static_cast<std::size_t>(settings.max_contacts));
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) add_body(static_cast<int>(i));
    for (const auto& plane : scene.planes) {
      const Eigen::Vector3d n = plane.normal.normalized();
      dGeomID geom = dCreatePlane(w_.space, n.x(), n.y(), n.z(), n.dot(plane.point));
      dGeomSetData(geom, reinterpret_cast<void*>(collision_.names.size() + 1));
      collision_.names.push_back(plane.name);
    }
    states_.resize(bodies_.size());
  }

  void record_state(double t, engines::RunResult& result) override {
    read_states();
    add_scene_sample(result, scene_, states_, t);
  }

  void before_step(double) override { before_ = states_; }

  void step(double t) override {
    dJointGroupEmpty(w_.contact_joints);
    collision_.contacts.clear();
    collision_.feedback.clear();
    for (const auto& [body, force] : input_forces(scene_, t))
      dBodyAddForce(bodies_[body], force.x(), force.y(), force.z());
    for (const HingeSpec& hinge : scene_.hinges)
      dBodyAddTorque(bodies_[hinge.body], 0, 0,
                     hinge_torque(hinge, planar_angle(before_[hinge.body].orientation),
                                  before_[hinge.body].angular_velocity.z()));
    dSpaceCollide(w_.space, &collision_, near_callback);
    if (settings_.stepper == engines::OdeStepper::kExact)
      dWorldStep(w_.world, scene_.dt);
    else
      dWorldQuickStep(w_.world, scene_.dt);
  }

  std::vector<engines::ClosedContact> read_step(double, engines::StepRecord& step,
                                                engines::RunResult& result) override {
    read_states();
    step.iterations =
        settings_.stepper == engines::OdeStepper::kQuick ? settings_.quick_iterations : 1;
    std::vector<PointContact> contacts;
    for (const StepContact& c : collision_.contacts)
      contacts.push_back({c.name, c.body1, c.body2, to_eigen(c.geom.pos), to_eigen(c.geom.normal),
                          c.geom.depth, to_eigen(c.feedback->f1) * scene_.dt});
    return record_step_contacts(scene_, contacts, before_, states_, step, result.max_penetration);
  }

 private:
  void read_states() {
    for (std::size_t i = 0; i < bodies_.size(); ++i) states_[i] = body_state(bodies_[i]);
  }

  void add_body(int i) {
    const model::BodySpec& spec = scene_.bodies[i];
    dBodyID b = dBodyCreate(w_.world);
    const dMass mass = make_mass(spec);
    dBodySetMass(b, &mass);
    dBodySetPosition(b, spec.position.x(), spec.position.y(), spec.position.z());
    Eigen::Quaterniond r =
        scene_.planar ? Eigen::Quaterniond(Eigen::AngleAxisd(spec.angle, Eigen::Vector3d::UnitZ()))
                      : spec.orientation;
    const dQuaternion q = {r.w(), r.x(), r.y(), r.z()};
    dBodySetQuaternion(b, q);
    dBodySetLinearVel(b, spec.velocity.x(), spec.velocity.y(), spec.velocity.z());
    dBodySetAngularVel(b, spec.angular_velocity.x(), spec.angular_velocity.y(),
                       spec.angular_velocity.z());
    dGeomID geom = make_geom(w_.space, spec);
    dGeomSetBody(geom, b);
    dGeomSetData(geom, reinterpret_cast<void*>(static_cast<std::uintptr_t>(i + 1)));
    if (const HingeSpec* hinge = hinge_of(scene_, i)) {
      dJointID j = dJointCreateHinge(w_.world, nullptr);
      dJointAttach(j, b, nullptr);
      dJointSetHingeAnchor(j, hinge->anchor.x(), hinge->anchor.y(), hinge->anchor.z());
      dJointSetHingeAxis(j, 0, 0, 1);
    } else if (scene_.planar) {
      dJointID j = dJointCreatePlane2D(w_.world, nullptr);
      dJointAttach(j, b, nullptr);
    }
    bodies_.push_back(b);
    collision_.names.push_back(spec.name);
  }

  const ReferenceScene& scene_;
  const OdeSettings& settings_;
  OdeWorld w_;
  Collision collision_;
  std::vector<dBodyID> bodies_;
  std::vector<BodyState> states_;  // after the last step
  std::vector<BodyState> before_;  // at the step's start (approach speeds, hinge torques)
};

}  // namespace

engines::RunResult run_ode(const ReferenceScene& scene, const OdeSettings& settings,
                           const engines::RecordingOptions& recording) {
  if (!scene.planar && !scene.hinges.empty())
    throw UnsupportedScene("ode: hinges are built for planar scenes only");
  init_ode();
  OdeScene world(scene, settings);
  engines::RunResult result =
      scene_result(engine_name::kOde, scene, recording);  // exact shapes, no skin
  result.settings = {{"precision", "double", kBuiltIn},
                     {"boundaries", "half-spaces (dCreatePlane)", kBuiltIn}};
  run_fixed_steps(world, {engine_name::kOde, scene.dt, scene.duration, settings.impact, false},
                  result);
  result.unconverged_note =
      settings.stepper == engines::OdeStepper::kExact
          ? "ODE's exact step solves each LCP by pivoting and reports no residual"
          : "ODE's quick step runs a fixed number of sweeps and has no tolerance to reach";
  return result;
}

}  // namespace impactbench::adapters
