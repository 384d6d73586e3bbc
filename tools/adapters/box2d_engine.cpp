#include "tools/adapters/box2d_engine.hpp"
#include "lib/engines/step_count.hpp"
#include "lib/output/message_text.hpp"

#include <box2d/box2d.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "tools/adapters/boundary_slab.hpp"

namespace impactbench::adapters {
namespace {

constexpr double kBoundaryHalfLength = 200.0;  // [m] static boundaries are long thin boxes

// Collects what each step's contacts report: impulses from PostSolve, begin/end as events.
class ContactRecorder : public b2ContactListener {
 public:
  explicit ContactRecorder(const std::vector<std::string>& body_names) : names_(body_names) {}

  void BeginContact(b2Contact* contact) override { begun_.push_back(contact); }
  void EndContact(b2Contact* contact) override { ended_.push_back(name_of(contact)); }
  void PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) override {
    Impulses& sum = impulses_[contact];
    for (int j = 0; j < impulse->count && j < 2; ++j) {
      sum.normal[j] += impulse->normalImpulses[j];
      sum.tangent[j] += impulse->tangentImpulses[j];
    }
  }

  std::string name_of(b2Contact* contact) const {
    b2Fixture* a = contact->GetFixtureA();
    b2Fixture* b = contact->GetFixtureB();
    return body_name(a->GetBody()) + "-" + body_name(b->GetBody());
  }

  struct Impulses {
    double normal[2] = {0, 0};
    double tangent[2] = {0, 0};
  };
  void clear() {
    begun_.clear();
    ended_.clear();
    impulses_.clear();
  }
  const std::vector<b2Contact*>& begun() const { return begun_; }
  const std::vector<std::string>& ended() const { return ended_; }
  Impulses impulses(b2Contact* c) const {
    const auto it = impulses_.find(c);
    return it == impulses_.end() ? Impulses{} : it->second;
  }

 private:
  // user data = 1 + index into the names (bodies, then static boundaries)
  std::string body_name(b2Body* body) const { return names_.at(body->GetUserData().pointer - 1); }
  const std::vector<std::string>& names_;
  std::vector<b2Contact*> begun_;
  std::vector<std::string> ended_;
  std::map<const b2Contact*, Impulses> impulses_;
};

double shape_area(const model::BodySpec& body) {
  if (body.shape == model::ShapeKind::kDisk) return std::numbers::pi * body.radius * body.radius;
  return body.size.x() * body.size.y();
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
    box.SetAsBox(static_cast<float>(body.size.x() / 2), static_cast<float>(body.size.y() / 2));
    fixture.shape = &box;
  } else {
    throw UnsupportedScene("Box2D is planar: body '" + body.name + "' is a spatial shape");
  }
  fixture.density = static_cast<float>(body.mass / shape_area(body));
  fixture.friction = static_cast<float>(material.friction);
  fixture.restitution = static_cast<float>(material.restitution);
  fixture.restitutionThreshold = static_cast<float>(restitution_threshold);
  b2body->CreateFixture(&fixture);
}

void add_boundary(b2World& world, const model::StaticPlaneSpec& plane, std::uintptr_t user_data,
                  const model::Material& material, double restitution_threshold) {
  const BoundarySlab slab = boundary_slab(plane, kBoundaryHalfLength);
  b2BodyDef def;  // static
  def.position.Set(static_cast<float>(slab.centre.x()), static_cast<float>(slab.centre.y()));
  def.angle = static_cast<float>(slab.planar_angle);
  def.userData.pointer = user_data;
  b2Body* body = world.CreateBody(&def);
  b2PolygonShape box;
  box.SetAsBox(static_cast<float>(slab.half_extents.x()),
               static_cast<float>(slab.half_extents.y()));
  b2FixtureDef fixture;
  fixture.shape = &box;
  fixture.friction = static_cast<float>(material.friction);
  fixture.restitution = static_cast<float>(material.restitution);
  fixture.restitutionThreshold = static_cast<float>(restitution_threshold);
  body->CreateFixture(&fixture);
}

// Velocity of the material point of `body` at world point p.
b2Vec2 point_velocity(const b2Body* body, const b2Vec2& p) {
  return body->GetLinearVelocityFromWorldPoint(p);
}

engines::ContactSample sample_contact(b2Contact* contact, const ContactRecorder& recorder,
                                      int point, double friction) {
  b2WorldManifold manifold;
  contact->GetWorldManifold(&manifold);
  const b2Vec2 n = manifold.normal;  // from A to B
  const b2Vec2 t(n.y, -n.x);         // Box2D's tangent, b2Cross(n, 1)
  const b2Vec2 p = manifold.points[point];
  const b2Vec2 relative = point_velocity(contact->GetFixtureB()->GetBody(), p) -
                          point_velocity(contact->GetFixtureA()->GetBody(), p);
  const auto impulses = recorder.impulses(contact);
  engines::ContactSample s;
  s.name = recorder.name_of(contact) + "#" + std::to_string(point);
  s.gap = manifold.separations[point];
  s.impulse_n = impulses.normal[point];  // on B along n: pushes B away from A
  s.impulse_t.x() = impulses.tangent[point];
  s.velocity_n = b2Dot(relative, n);  // > 0 separating
  s.velocity_t.x() = b2Dot(relative, t);
  s.friction = friction;
  return s;
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
      // b2PolygonShape::ComputeMass asserts an area above FLT_EPSILON.
      if (!(shape_area(body) > std::numeric_limits<float>::epsilon()))
        throw UnsupportedScene("box2d: " + name + "area " + output::number_text(shape_area(body)) +
                               " m^2 is below the smallest polygon area Box2D accepts (1.2e-07)");
    }
    check_positive_float(name + "area", shape_area(body), "m^2");
    check_positive_float(name + "mass", body.mass, "kg");
    check_positive_float(name + "density", body.mass / shape_area(body), "kg/m^2");
    check_positive_float(name + "moment of inertia", body.mass * spread, "kg m^2");
  }
}

}  // namespace

engines::RunResult run_box2d(const ReferenceScene& scene, const Box2dSettings& settings) {
  if (!scene.planar)
    throw UnsupportedScene("Box2D is a planar engine and cannot run a spatial scenario");
  if (settings.velocity_iterations < 1 || settings.position_iterations < 0 ||
      !(settings.restitution_threshold >= 0.0))
    throw std::invalid_argument("box2d: iterations must be positive and the threshold >= 0");
  if (!(scene.dt > 0.0) || !(scene.duration > 0.0))
    throw std::invalid_argument("box2d: dt and duration must be positive");
  check_representable(scene);

  b2World world(b2Vec2(0.0f, static_cast<float>(-scene.gravity)));
  std::vector<std::string> names;  // bodies, then static boundaries (contact names)
  std::vector<b2Body*> bodies;
  for (const auto& spec : scene.bodies) names.push_back(spec.name);
  for (const auto& plane : scene.planes) {
    names.push_back(plane.name);
    add_boundary(world, plane, names.size(), scene.material, settings.restitution_threshold);
  }
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const model::BodySpec& spec = scene.bodies[i];
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(static_cast<float>(spec.position.x()), static_cast<float>(spec.position.y()));
    def.angle = static_cast<float>(spec.angle);
    def.linearVelocity.Set(static_cast<float>(spec.velocity.x()),
                           static_cast<float>(spec.velocity.y()));
    def.angularVelocity = static_cast<float>(spec.angular_velocity.z());
    def.allowSleep = false;  // a sleeping body would freeze the trajectory we measure
    def.userData.pointer = i + 1;
    b2Body* body = world.CreateBody(&def);
    add_fixture(body, spec, scene.material, settings.restitution_threshold);
    bodies.push_back(body);
  }

  engines::RunResult result;
  result.engine = "box2d";
  // Box2D keeps touching shapes at a separation of −b2_linearSlop between their skins: a disk
  // (no skin) on a boundary (skin b2_polygonRadius) rests polygonRadius − slop above the exact
  // height, a box (skin on both) 2 polygonRadius − slop.
  for (const auto& spec : scene.bodies)
    result.rest_offsets.push_back(spec.shape == model::ShapeKind::kDisk
                                      ? b2_polygonRadius - b2_linearSlop
                                      : 2 * b2_polygonRadius - b2_linearSlop);

  ContactRecorder recorder(names);
  world.SetContactListener(&recorder);

  for (const auto& spec : scene.bodies)
    for (const char* c : {".x", ".y", ".theta"})
      result.trajectory.position_names.push_back(spec.name + c);
  for (const auto& spec : scene.bodies)
    for (const char* c : {".vx", ".vy", ".omega"})
      result.trajectory.velocity_names.push_back(spec.name + c);
  result.settings = {{"velocity_iterations", std::to_string(settings.velocity_iterations)},
                     {"position_iterations", std::to_string(settings.position_iterations)},
                     {"restitution_threshold", std::to_string(settings.restitution_threshold)},
                     {"linear_slop", std::to_string(b2_linearSlop)},
                     {"polygon_radius", std::to_string(b2_polygonRadius)},
                     {"precision", "float"}};

  const auto nb = static_cast<int>(bodies.size());
  auto record_state = [&](double t) {
    Eigen::VectorXd q(3 * nb), v(3 * nb);
    for (int i = 0; i < nb; ++i) {
      const b2Body* b = bodies[i];
      q.segment<3>(3 * i) << b->GetPosition().x, b->GetPosition().y, b->GetAngle();
      v.segment<3>(3 * i) << b->GetLinearVelocity().x, b->GetLinearVelocity().y,
          b->GetAngularVelocity();
    }
    const double e = scene.energy ? scene.energy(q, v) : std::nan("");
    result.add_sample(t, std::move(q), std::move(v), e);
  };

  engines::checked_step_count("box2d", scene.duration, scene.dt);  // refuses what cannot fit
  const auto steps = static_cast<long>(std::llround(scene.duration / scene.dt));
  const auto start = std::chrono::steady_clock::now();
  record_state(0.0);
  for (long k = 0; k < steps; ++k) {
    const double t = k * scene.dt;
    for (const auto& [body, force] : input_forces(scene, t))
      bodies[body]->ApplyForceToCenter(
          b2Vec2(static_cast<float>(force.x()), static_cast<float>(force.y())), true);
    recorder.clear();
    world.Step(static_cast<float>(scene.dt), settings.velocity_iterations,
               settings.position_iterations);
    const double t_end = (k + 1) * scene.dt;

    engines::StepRecord step;
    step.t = t_end;
    step.iterations = settings.velocity_iterations;
    for (b2Contact* c = world.GetContactList(); c; c = c->GetNext()) {
      if (!c->IsTouching()) continue;
      for (int j = 0; j < c->GetManifold()->pointCount; ++j)
        step.contacts.push_back(sample_contact(c, recorder, j, scene.material.friction));
    }
    step.active_contacts = static_cast<int>(step.contacts.size());
    for (b2Contact* c : recorder.begun()) {
      const auto imp = recorder.impulses(c);
      result.events.push_back({t_end, recorder.name_of(c), "impact", "open", "closed",
                               imp.normal[0] + imp.normal[1], imp.tangent[0] + imp.tangent[1]});
    }
    for (const auto& name : recorder.ended())
      result.events.push_back({t_end, name, "liftoff", "closed", "open", 0.0, 0.0});
    result.steps.push_back(std::move(step));
    record_state(t_end);
  }
  result.cpu_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace impactbench::adapters
