#include "tools/engines/box2d/box2d_engine.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "lib/output/number_text.hpp"
#include "tools/engines/engine_names.hpp"
#include "tools/engines/fixed_step/boundary_slab.hpp"
#include "tools/engines/fixed_step/fixed_step_driver.hpp"
#include "tools/engines/fixed_step/scene_state.hpp"

namespace impactbench::adapters {
namespace {

constexpr auto kBuiltIn = engines::SettingSource::kBuiltIn;
constexpr double kBoundaryHalfLength = 200.0;  // [m] static boundaries are long thin boxes

// Keeps the impulses each contact reports in PostSolve (Box2D calls it from inside Step, once per
// solve and again for a time-of-impact sub-step); copying them is all the work done inside the
// step, sorting them out is recording.
class ImpulseListener : public b2ContactListener {
 public:
  struct Impulses {
    double normal[2] = {0, 0};
    double tangent[2] = {0, 0};
  };

  void PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) override {
    reported_.push_back({contact, *impulse});
  }
  void clear() { reported_.clear(); }
  /// The step's impulses per contact, summed over its reports.
  std::unordered_map<const b2Contact*, Impulses> per_contact() const {
    std::unordered_map<const b2Contact*, Impulses> sums;
    for (const auto& [contact, impulse] : reported_) {
      Impulses& sum = sums[contact];
      for (int j = 0; j < impulse.count && j < 2; ++j) {
        sum.normal[j] += impulse.normalImpulses[j];
        sum.tangent[j] += impulse.tangentImpulses[j];
      }
    }
    return sums;
  }

 private:
  std::vector<std::pair<const b2Contact*, b2ContactImpulse>> reported_;
};

// Body and contact names: user data = 1 + index into the names (bodies, then boundaries).
class ContactNames {
 public:
  explicit ContactNames(const std::vector<std::string>& names) : names_(names) {}
  std::string operator()(b2Contact* contact) const {
    return body_name(contact->GetFixtureA()->GetBody()) + "-" +
           body_name(contact->GetFixtureB()->GetBody());
  }

 private:
  std::string body_name(b2Body* body) const { return names_.at(body->GetUserData().pointer - 1); }
  const std::vector<std::string>& names_;
};

double shape_area(const model::BodySpec& body) {
  if (body.shape == model::ShapeKind::kDisk) return std::numbers::pi * body.radius * body.radius;
  return body.size.x() * body.size.y();
}

// A box's skin: Box2D's b2_polygonRadius (1 cm), or a quarter of the thinner side for thinner
// boxes (the plank of the plank–box is 2 cm thick), so that the core keeps half of each side.
float box_skin(const model::BodySpec& body) {
  return std::min(b2_polygonRadius, static_cast<float>(body.size.head<2>().minCoeff() / 4));
}

void add_fixture(b2Body* b2body, const model::BodySpec& body, const model::Material& material,
                 double restitution_threshold) {
  b2FixtureDef fixture;
  b2CircleShape circle;
  b2PolygonShape box;
  if (body.shape == model::ShapeKind::kDisk) {
    circle.m_radius = static_cast<float>(body.radius);
    fixture.shape = &circle;
  } else if (body.shape == model::ShapeKind::kBox) {
    // Box2D rounds a polygon by its skin: the core shrunk by the skin puts the rounded outer
    // surface on the scenario's faces (corners rounded by the skin's radius).
    const float skin = box_skin(body);
    box.SetAsBox(static_cast<float>(body.size.x() / 2) - skin,
                 static_cast<float>(body.size.y() / 2) - skin);
    box.m_radius = skin;
    fixture.shape = &box;
  } else {
    throw UnsupportedScene("Box2D is planar: body '" + body.name + "' is a spatial shape");
  }
  fixture.density = static_cast<float>(body.mass / shape_area(body));
  fixture.friction = static_cast<float>(material.friction);
  fixture.restitution = static_cast<float>(material.restitution);
  fixture.restitutionThreshold = static_cast<float>(restitution_threshold);
  b2body->CreateFixture(&fixture);
  if (body.shape == model::ShapeKind::kBox) {
    // Box2D's mass from the shrunk core would be too small: the scenario's box's mass and
    // moment of inertia about its centre instead.
    b2MassData mass;
    mass.mass = static_cast<float>(body.mass);
    mass.center.SetZero();
    mass.I = static_cast<float>(body.mass * body.size.head<2>().squaredNorm() / 12);
    b2body->SetMassData(&mass);
  }
}

void add_boundary(b2World& world, const model::StaticPlaneSpec& plane, std::uintptr_t user_data,
                  const model::Material& material, double restitution_threshold) {
  const BoundarySlab slab = boundary_slab(plane, kBoundaryHalfLength);
  b2BodyDef def;  // static
  def.position.Set(static_cast<float>(slab.centre.x()), static_cast<float>(slab.centre.y()));
  def.angle = static_cast<float>(slab.planar_angle);
  def.userData.pointer = user_data;
  b2Body* body = world.CreateBody(&def);
  // The slab's core lies one skin below the plane (its local +y is the normal), so that its
  // skin's outer surface is the plane (see add_fixture).
  b2PolygonShape box;
  box.SetAsBox(static_cast<float>(slab.half_extents.x()), static_cast<float>(slab.half_extents.y()),
               b2Vec2(0.0f, -b2_polygonRadius), 0.0f);
  b2FixtureDef fixture;
  fixture.shape = &box;
  fixture.friction = static_cast<float>(material.friction);
  fixture.restitution = static_cast<float>(material.restitution);
  fixture.restitutionThreshold = static_cast<float>(restitution_threshold);
  body->CreateFixture(&fixture);
}

// Velocity of the material point of a body at world point p, from the body's velocities
// (v, ω) and its centre c: v + ω × (p − c).
b2Vec2 point_velocity(const b2Vec2& v, float omega, const b2Vec2& c, const b2Vec2& p) {
  return v + b2Cross(omega, p - c);
}
b2Vec2 point_velocity(const b2Body* body, const b2Vec2& p) {
  return point_velocity(body->GetLinearVelocity(), body->GetAngularVelocity(),
                        body->GetWorldCenter(), p);
}

// A body's velocities at the start of the step, for the approach speed of a closing contact.
struct BodyVelocity {
  b2Vec2 linear{0.0f, 0.0f};
  float angular = 0.0f;
};

// ζ_n of a contact's point at the start of the step, from the bodies' velocities before it.
double normal_velocity_before(b2Contact* contact, const b2WorldManifold& manifold, int point,
                              const std::vector<BodyVelocity>& before) {
  auto velocity = [&](b2Body* body, const b2Vec2& p) {
    const std::size_t i = body->GetUserData().pointer - 1;
    if (i >= before.size()) return b2Vec2(0.0f, 0.0f);  // a static boundary
    return point_velocity(before[i].linear, before[i].angular, body->GetWorldCenter(), p);
  };
  const b2Vec2 p = manifold.points[point];
  const b2Vec2 relative = velocity(contact->GetFixtureB()->GetBody(), p) -
                          velocity(contact->GetFixtureA()->GetBody(), p);
  return b2Dot(relative, manifold.normal);
}

engines::ContactSample sample_contact(b2Contact* contact, const std::string& name,
                                      const ImpulseListener::Impulses& impulses, int point,
                                      const std::vector<BodyVelocity>& before,
                                      const model::Material& material) {
  b2WorldManifold manifold;
  contact->GetWorldManifold(&manifold);
  const b2Vec2 n = manifold.normal;  // from A to B
  const b2Vec2 t(n.y, -n.x);         // Box2D's tangent, b2Cross(n, 1)
  const b2Vec2 p = manifold.points[point];
  const b2Vec2 relative = point_velocity(contact->GetFixtureB()->GetBody(), p) -
                          point_velocity(contact->GetFixtureA()->GetBody(), p);
  engines::ContactSample s;
  s.name = name + "#" + std::to_string(point);
  s.gap = manifold.separations[point];
  s.impulse_n = impulses.normal[point];  // on B along n: pushes B away from A
  s.impulse_t.x() = impulses.tangent[point];
  s.velocity_n = b2Dot(relative, n);  // > 0 separating
  s.velocity_n_before = normal_velocity_before(contact, manifold, point, before);
  s.velocity_t.x() = b2Dot(relative, t);
  s.friction = material.friction;
  s.restitution = material.restitution;
  return s;
}

// −ζ_n at the start of the step of the contact's points (the fastest).
double approach_speed(b2Contact* contact, const std::vector<BodyVelocity>& before) {
  b2WorldManifold manifold;
  contact->GetWorldManifold(&manifold);
  double speed = -std::numeric_limits<double>::infinity();
  for (int j = 0; j < contact->GetManifold()->pointCount; ++j)
    speed = std::max(speed, -normal_velocity_before(contact, manifold, j, before));
  return speed;
}

// Box2D computes in float and asserts (aborting the process) on values it cannot hold, so every
// quantity it will store or derive is checked here first, with the value and the limit named.
constexpr double kFloatMax = std::numeric_limits<float>::max();
constexpr double kFloatMin = std::numeric_limits<float>::min();  // smallest normal float

/// A coordinate, velocity or angle: any float, zero included.
void check_float(const std::string& what, double value, const char* unit) {
  if (!(std::abs(value) <= kFloatMax))
    throw UnsupportedScene("box2d computes in single precision: " + what + " = " +
                           output::number_text(value) + " " + unit +
                           " is outside its range (magnitude at most 3.4e+38)");
}

/// A size, mass or inertia that Box2D divides by: a positive normal float.
void check_positive_float(const std::string& what, double value, const char* unit) {
  if (!(value >= kFloatMin && value <= kFloatMax))
    throw UnsupportedScene("box2d computes in single precision: " + what + " = " +
                           output::number_text(value) + " " + unit +
                           " is outside its range for a positive quantity (1.2e-38 to 3.4e+38)");
}

void check_representable(const ReferenceScene& scene) {
  check_float("gravity", scene.gravity, "m/s^2");
  for (const auto& plane : scene.planes) {
    const BoundarySlab slab = boundary_slab(plane, kBoundaryHalfLength);
    for (int k = 0; k < 2; ++k)
      check_float("plane '" + plane.name + "' position", slab.centre(k), "m");
  }
  for (const auto& body : scene.bodies) {
    const std::string name = "body '" + body.name + "' ";
    for (int k = 0; k < 2; ++k) {
      check_float(name + "position", body.position(k), "m");
      check_float(name + "velocity", body.velocity(k), "m/s");
    }
    check_float(name + "angle", body.angle, "rad");
    check_float(name + "angular velocity", body.angular_velocity.z(), "rad/s");
    // Second moment of area per unit mass (I = mass · this) about the centre.
    double spread = 0.0;
    if (body.shape == model::ShapeKind::kDisk) {
      check_positive_float(name + "radius", body.radius, "m");
      spread = body.radius * body.radius / 2;
    } else {
      check_positive_float(name + "width", body.size.x(), "m");
      check_positive_float(name + "height", body.size.y(), "m");
      spread = (body.size.x() * body.size.x() + body.size.y() * body.size.y()) / 12;
      // b2PolygonShape::ComputeMass asserts an area above FLT_EPSILON (of the core, which
      // keeps at least half of each side: box_skin).
      if (!(shape_area(body) / 4 > std::numeric_limits<float>::epsilon()))
        throw UnsupportedScene("box2d: " + name + "area " + output::number_text(shape_area(body)) +
                               " m^2 is below the smallest box Box2D accepts (4.8e-07 m^2)");
    }
    check_positive_float(name + "area", shape_area(body), "m^2");
    check_positive_float(name + "mass", body.mass, "kg");
    check_positive_float(name + "density", body.mass / shape_area(body), "kg/m^2");
    check_positive_float(name + "moment of inertia", body.mass * spread, "kg m^2");
  }
}

// A Box2D world of the scene, stepped by the fixed-step loop. Boundaries are created before
// the bodies and the hinges after them (Box2D's order of bodies and contacts follows creation).
class Box2dWorld : public FixedStepWorld {
 public:
  Box2dWorld(const ReferenceScene& scene, const Box2dSettings& settings)
      : scene_(scene),
        settings_(settings),
        world_(b2Vec2(0.0f, static_cast<float>(-scene.gravity))) {
    for (const auto& spec : scene.bodies) names_.push_back(spec.name);
    for (const auto& plane : scene.planes) {
      names_.push_back(plane.name);
      add_boundary(world_, plane, names_.size(), scene.material, settings.restitution_threshold);
    }
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) add_body(i);
    for (const HingeSpec& hinge : scene.hinges) add_hinge(hinge);
    world_.SetContactListener(&listener_);
    velocity_before_.resize(bodies_.size());
    states_.resize(bodies_.size());
  }

  void record_state(double t, engines::RunResult& result) override {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const b2Body* b = bodies_[i];
      BodyState& s = states_[i];
      s.position = Eigen::Vector3d(b->GetPosition().x, b->GetPosition().y, 0.0);
      s.angle = b->GetAngle();  // unwrapped
      s.orientation = Eigen::AngleAxisd(*s.angle, Eigen::Vector3d::UnitZ());
      s.velocity = Eigen::Vector3d(b->GetLinearVelocity().x, b->GetLinearVelocity().y, 0.0);
      s.angular_velocity = Eigen::Vector3d(0.0, 0.0, b->GetAngularVelocity());
      velocity_before_[i] = {b->GetLinearVelocity(), b->GetAngularVelocity()};
    }
    add_scene_sample(result, scene_, states_, t);
  }

  void before_step(double) override { listener_.clear(); }

  void step(double t) override {
    for (const auto& [body, force] : input_forces(scene_, t))
      bodies_[body]->ApplyForceToCenter(
          b2Vec2(static_cast<float>(force.x()), static_cast<float>(force.y())), true);
    for (const HingeSpec& hinge : scene_.hinges) {
      const b2Body* plank = bodies_[hinge.body];
      bodies_[hinge.body]->ApplyTorque(
          static_cast<float>(hinge_torque(hinge, plank->GetAngle(), plank->GetAngularVelocity())),
          true);
    }
    world_.Step(static_cast<float>(scene_.dt), settings_.velocity_iterations,
                settings_.position_iterations);
  }

  std::vector<engines::ClosedContact> read_step(double, engines::StepRecord& step,
                                                engines::RunResult& result) override {
    step.iterations = settings_.velocity_iterations;
    const auto impulses = listener_.per_contact();
    const ContactNames name_of(names_);
    std::vector<engines::ClosedContact> closed;
    for (b2Contact* c = world_.GetContactList(); c; c = c->GetNext()) {
      if (!c->IsTouching()) continue;
      const auto found = impulses.find(c);
      const ImpulseListener::Impulses imp =
          found == impulses.end() ? ImpulseListener::Impulses{} : found->second;
      const std::string name = name_of(c);
      for (int j = 0; j < c->GetManifold()->pointCount; ++j) {
        step.contacts.push_back(sample_contact(c, name, imp, j, velocity_before_, scene_.material));
        result.max_penetration = std::max(result.max_penetration, -step.contacts.back().gap);
      }
      closed.push_back({name, approach_speed(c, velocity_before_), imp.normal[0] + imp.normal[1],
                        imp.tangent[0] + imp.tangent[1]});
    }
    step.active_contacts = static_cast<int>(step.contacts.size());
    return closed;
  }

 private:
  void add_body(std::size_t i) {
    const model::BodySpec& spec = scene_.bodies[i];
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(static_cast<float>(spec.position.x()), static_cast<float>(spec.position.y()));
    def.angle = static_cast<float>(spec.angle);
    def.linearVelocity.Set(static_cast<float>(spec.velocity.x()),
                           static_cast<float>(spec.velocity.y()));
    def.angularVelocity = static_cast<float>(spec.angular_velocity.z());
    def.allowSleep = false;  // a sleeping body would freeze the trajectory we measure
    def.userData.pointer = i + 1;
    b2Body* body = world_.CreateBody(&def);
    add_fixture(body, spec, scene_.material, settings_.restitution_threshold);
    bodies_.push_back(body);
  }

  // A hinged body turns about its anchor on a revolute joint to a fixture-less static body;
  // its spring and damper are a torque applied before each step.
  void add_hinge(const HingeSpec& hinge) {
    b2BodyDef def;  // static
    b2Body* anchor = world_.CreateBody(&def);
    b2RevoluteJointDef joint;
    joint.Initialize(
        anchor, bodies_[hinge.body],
        b2Vec2(static_cast<float>(hinge.anchor.x()), static_cast<float>(hinge.anchor.y())));
    world_.CreateJoint(&joint);
  }

  const ReferenceScene& scene_;
  const Box2dSettings& settings_;
  ImpulseListener listener_;  // outlives the world that calls it
  b2World world_;
  std::vector<std::string> names_;  // bodies, then static boundaries (contact names)
  std::vector<b2Body*> bodies_;
  std::vector<BodyVelocity> velocity_before_;  // at the last state recorded
  std::vector<BodyState> states_;
};

}  // namespace

engines::RunResult run_box2d(const ReferenceScene& scene, const Box2dSettings& settings,
                             const engines::RecordingOptions& recording) {
  if (!scene.planar)
    throw UnsupportedScene("Box2D is a planar engine and cannot run a spatial scenario");
  check_representable(scene);
  Box2dWorld world(scene, settings);

  engines::RunResult result = scene_result(engine_name::kBox2d, scene, recording);
  // What Box2D compiles in; the registry adds the settings in force.
  result.settings = {{"linear_slop", output::number_text(b2_linearSlop), kBuiltIn},
                     {"polygon_radius", output::number_text(b2_polygonRadius), kBuiltIn},
                     {"precision", "float", kBuiltIn}};
  run_fixed_steps(world, {engine_name::kBox2d, scene.dt, scene.duration, settings.impact, false},
                  result);
  result.unconverged_note =
      "Box2D runs a fixed number of velocity iterations per step and has no tolerance to reach";
  return result;
}

}  // namespace impactbench::adapters
