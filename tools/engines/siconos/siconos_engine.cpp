#include "tools/engines/siconos/siconos_engine.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "lib/engines/run_timer.hpp"
#include "lib/engines/step_count.hpp"
#include "lib/output/number_text.hpp"
#include "tools/engines/engine_names.hpp"
#include "tools/engines/fixed_step/scene_state.hpp"
#include "tools/engines/siconos/siconos_event_driven_model.hpp"

namespace impactbench::adapters {
namespace {

constexpr auto kBuiltIn = engines::SettingSource::kBuiltIn;
/// How far a box may turn before its linear contact relations no longer hold to round-off
/// (the gap error is about half the box's size times the square of the angle) [rad].
constexpr double kMaxBoxTurn = 1e-6;
/// Nonsmooth events between two samples past which an event-driven run is stopped: far more
/// than a Zeno sequence that ends (the bouncing ball's last 1 ms holds about 100 impacts).
constexpr long kMaxNonsmoothPerSample = 100000;

double planar_inertia(const model::BodySpec& body) {
  if (body.shape == model::ShapeKind::kDisk) return 0.5 * body.mass * body.radius * body.radius;
  return body.mass * (body.size.x() * body.size.x() + body.size.y() * body.size.y()) / 12.0;
}

// The points of a body that may touch a plane, relative to its centre in the world frame at
// the initial pose: a disk's point closest to the plane, a box's four corners.
std::vector<Eigen::Vector2d> contact_offsets(const model::BodySpec& body,
                                             const Eigen::Vector2d& normal) {
  if (body.shape == model::ShapeKind::kDisk) return {-body.radius * normal};
  const Eigen::Rotation2Dd turn(body.angle);
  const double a = body.size.x() / 2, b = body.size.y() / 2;
  return {turn * Eigen::Vector2d(a, b), turn * Eigen::Vector2d(-a, b),
          turn * Eigen::Vector2d(-a, -b), turn * Eigen::Vector2d(a, -b)};
}

// One Siconos interaction: a point of a body against a plane, y = H q + b with row 0 the gap
// along the normal n and row 1 the displacement along the tangent t = (n_y, −n_x), both linear
// in q = (x, y, θ) about the initial angle θ0: the point moves by ẑ × r per unit of θ.
struct PlaneContact {
  int body = 0;
  std::string pair;
  Eigen::Vector2d normal;
  Eigen::Vector2d tangent;
  Eigen::Vector2d offset;  // r at θ0
  Eigen::Matrix<double, 2, 3> h;
  Eigen::Vector2d b;
};

PlaneContact make_contact(int body, const model::BodySpec& spec,
                          const model::StaticPlaneSpec& plane, const Eigen::Vector2d& offset) {
  PlaneContact c;
  c.body = body;
  c.pair = spec.name + "-" + plane.name;
  c.normal = plane.normal.head<2>().normalized();
  c.tangent = Eigen::Vector2d(c.normal.y(), -c.normal.x());
  c.offset = offset;
  const Eigen::Vector2d turn_rate(-offset.y(), offset.x());  // ẑ × r
  c.h << c.normal.x(), c.normal.y(), c.normal.dot(turn_rate), c.tangent.x(), c.tangent.y(),
      c.tangent.dot(turn_rate);
  const Eigen::Vector2d p0 = plane.point.head<2>();
  c.b << c.normal.dot(offset - p0) - c.h(0, 2) * spec.angle, -c.h(1, 2) * spec.angle;
  return c;
}

BodyState body_state(const Eigen::Vector3d& q, const Eigen::Vector3d& v) {
  BodyState s;
  s.position = Eigen::Vector3d(q.x(), q.y(), 0.0);
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(q.z(), Eigen::Vector3d::UnitZ()));
  s.angle = q.z();
  s.velocity = Eigen::Vector3d(v.x(), v.y(), 0.0);
  s.angular_velocity = Eigen::Vector3d(0.0, 0.0, v.z());
  return s;
}

void check_supported(const ReferenceScene& scene) {
  if (!scene.planar)
    throw UnsupportedScene(
        "siconos: of spatial scenes only one sphere is stated, with scheme moreau_jean");
  if (!scene.hinges.empty()) throw UnsupportedScene("siconos: hinged bodies are not stated");
  if (scene.bodies.size() != 1)
    throw UnsupportedScene("siconos: one body against the planes only (no body-body contacts)");
  for (const auto& body : scene.bodies)
    if (body.shape != model::ShapeKind::kDisk && body.shape != model::ShapeKind::kBox)
      throw UnsupportedScene("siconos: body '" + body.name + "' is neither a disk nor a box");
}

std::vector<siconos::PlanarBody> planar_bodies(const ReferenceScene& scene) {
  std::vector<siconos::PlanarBody> bodies;
  for (const model::BodySpec& spec : scene.bodies) {
    siconos::PlanarBody body;
    body.q = Eigen::Vector3d(spec.position.x(), spec.position.y(), spec.angle);
    body.v = Eigen::Vector3d(spec.velocity.x(), spec.velocity.y(), spec.angular_velocity.z());
    body.mass_diagonal = Eigen::Vector3d(spec.mass, spec.mass, planar_inertia(spec));
    body.force = Eigen::Vector3d(0.0, -spec.mass * scene.gravity, 0.0);
    bodies.push_back(body);
  }
  return bodies;
}

std::vector<PlaneContact> plane_contacts(const ReferenceScene& scene) {
  std::vector<PlaneContact> contacts;
  for (int i = 0; i < static_cast<int>(scene.bodies.size()); ++i)
    for (const auto& plane : scene.planes) {
      const model::BodySpec& spec = scene.bodies[static_cast<std::size_t>(i)];
      for (const Eigen::Vector2d& r : contact_offsets(spec, plane.normal.head<2>().normalized()))
        contacts.push_back(make_contact(i, spec, plane, r));
    }
  return contacts;
}

// Stops the run once a box has turned past kMaxBoxTurn (its relations are linear about θ0).
void check_box_turn(const ReferenceScene& scene, const std::vector<Eigen::Vector3d>& q, double t) {
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    if (scene.bodies[i].shape == model::ShapeKind::kBox &&
        std::abs(q[i].z() - scene.bodies[i].angle) > kMaxBoxTurn)
      throw UnsupportedScene("siconos: box '" + scene.bodies[i].name + "' turned by more than " +
                             "1e-6 rad at t = " + output::number_text(t) +
                             " s; its contact relations are linear about its initial angle");
}

void check_event_driven(const ReferenceScene& scene) {
  if (scene.material.friction != 0.0)
    throw UnsupportedScene(
        "siconos: scheme event_driven states frictionless contacts only, and the scenario's "
        "friction is " +
        output::number_text(scene.material.friction) + " (use scheme moreau_jean)");
  if (!scene.inputs.empty())
    throw UnsupportedScene(
        "siconos: scheme event_driven applies no force inputs, and the "
        "scenario has " +
        std::to_string(scene.inputs.size()) + " (use scheme moreau_jean)");
}

// An event every h until samples · h, with the settings' tolerances.
siconos::EventDrivenScheme event_driven_scheme(const SiconosSettings& settings, double h,
                                               long samples) {
  siconos::EventDrivenScheme scheme;
  scheme.sample_dt = h;
  scheme.duration = static_cast<double>(samples) * h;
  scheme.rtol = settings.rtol;
  scheme.atol = settings.atol;
  scheme.event_tolerance = settings.event_tolerance;
  return scheme;
}

// What the event-driven run compiles in; the registry adds the settings in force.
engines::SettingList event_driven_settings() {
  return {{"precision", "double", kBuiltIn},
          {"integrator", "LsodarOSI + EventDriven (an event every dt)", kBuiltIn},
          {"contact problem", "LCP at impacts (Newton's law) and on persistent contacts, Lemke",
           kBuiltIn},
          {"contact relation",
           "LagrangianLinearTIR normal row per point and plane (linear about the initial angle)",
           kBuiltIn}};
}

// The impacts, touchdowns and lift-offs of the nonsmooth event at t (`persistent`: each
// contact's state before it, updated), and the deepest gap of its state.
void record_nonsmooth_event(const siconos::EventDrivenModel& model,
                            const std::vector<PlaneContact>& contacts,
                            const std::vector<Eigen::Vector3d>& q, double t,
                            std::vector<char>& persistent, engines::RunResult& result) {
  auto event = [&](const PlaneContact& c, const char* kind, bool before, bool after,
                   double impulse) {
    result.events.push_back(
        {t, c.pair, kind, before ? "slip" : "open", after ? "slip" : "open", impulse, 0.0});
  };
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const PlaneContact& c = contacts[i];
    const double impulse = model.impulse(static_cast<int>(i));
    const bool now = model.persistent(static_cast<int>(i));
    if (impulse > 0.0)
      event(c, "impact", persistent[i], now, impulse);
    else if (now && !persistent[i])
      event(c, "touchdown", false, true, 0.0);
    else if (!now && persistent[i])
      event(c, "liftoff", true, false, 0.0);
    persistent[i] = now;
    const double gap = c.h.row(0).dot(q[static_cast<std::size_t>(c.body)]) + c.b[0];
    result.max_penetration = std::max(result.max_penetration, -gap);
  }
}

// Siconos' EventDriven with a time discretisation of scene.dt: a sample at every one of its
// events, impacts and contact changes from its nonsmooth events.
engines::RunResult simulate_event_driven(const ReferenceScene& scene,
                                         const SiconosSettings& settings,
                                         const engines::RecordingOptions& recording) {
  const double h = scene.dt;
  const long samples = engines::fixed_step_count(engine_name::kSiconos, scene.duration, h);
  const std::vector<PlaneContact> contacts = plane_contacts(scene);
  std::vector<siconos::NormalContact> normals;
  for (const PlaneContact& c : contacts)
    normals.push_back({c.body, c.h.row(0), c.b[0], scene.material.restitution});
  siconos::EventDrivenModel model(planar_bodies(scene), normals,
                                  event_driven_scheme(settings, h, samples));

  engines::RunResult result =
      scene_result(engine_name::kSiconos, scene, recording);  // exact shapes
  result.settings = event_driven_settings();
  result.unconverged_note = "event_driven: pivoting LCPs, no tolerance";

  const int nb = static_cast<int>(scene.bodies.size());
  std::vector<Eigen::Vector3d> q(scene.bodies.size());
  std::vector<BodyState> states(scene.bodies.size());
  auto read_states = [&] {
    for (int i = 0; i < nb; ++i) {
      q[i] = model.q(i);
      states[i] = body_state(q[i], model.v(i));
    }
  };
  std::vector<char> persistent(contacts.size(), 0);
  long persistent_samples = 0;
  auto record_state = [&](double t) {
    add_scene_sample(result, scene, states, t);
    for (const char p : persistent) persistent_samples += p;
  };

  engines::RunTimer timer;
  timer.start(engines::RunTimer::Phase::kRecord);
  read_states();
  record_state(0.0);
  long next_sample = 1;
  long nonsmooth_in_interval = 0;  // nonsmooth events since the last sample
  while (next_sample <= samples && model.has_next_event()) {
    timer.switch_to(engines::RunTimer::Phase::kEngine);
    const siconos::ProcessedEvent processed = model.advance();
    timer.switch_to(engines::RunTimer::Phase::kRecord);
    read_states();
    check_box_turn(scene, q, processed.t);
    if (processed.nonsmooth) {
      // Siconos may chain impacts without end where the gap after an impact stays below
      // event_tolerance but the contact does not close (Zeno at loose Lsodar tolerances).
      if (++nonsmooth_in_interval > kMaxNonsmoothPerSample)
        throw std::runtime_error(
            "siconos: event_driven: more than " + std::to_string(kMaxNonsmoothPerSample) +
            " nonsmooth events between two samples at t = " + output::number_text(processed.t) +
            " s (a Zeno sequence Siconos does not end: tighten rtol and atol)");
      record_nonsmooth_event(model, contacts, q, processed.t, persistent, result);
    }
    // Siconos drops a time-discretisation event that falls within 100 ticks (1e-14 s) of a
    // nonsmooth one: the state of the nonsmooth event then stands for the sample.
    const double t_sample = static_cast<double>(next_sample) * h;
    if (std::abs(processed.t - t_sample) <= 1e-12 * std::max(1.0, t_sample)) {
      record_state(t_sample);
      ++next_sample;
      nonsmooth_in_interval = 0;
    } else if (!processed.nonsmooth) {
      throw std::runtime_error(
          "siconos: a time-discretisation event at t = " + output::number_text(processed.t) +
          " s, expected " + output::number_text(t_sample) + " s");
    }
  }
  if (next_sample <= samples)
    throw std::runtime_error("siconos: the event-driven simulation ended at sample " +
                             std::to_string(next_sample - 1) + " of " + std::to_string(samples));
  result.finish_recording();
  result.step_count = model.integrator_steps();
  result.mean_contacts = static_cast<double>(persistent_samples) / static_cast<double>(samples + 1);
  timer.stop();
  result.set_timing(timer);
  return result;
}

}  // namespace

engines::RunResult run_siconos(const ReferenceScene& scene, const SiconosSettings& settings,
                               const engines::RecordingOptions& recording) {
  if (!(scene.dt > 0.0) || !(scene.duration > 0.0))
    throw std::invalid_argument("siconos: dt and duration must be positive");
  check_supported(scene);
  // Moreau–Jean runs the scenes Siconos states through our own model of them
  // (siconos_system_engine.hpp); what reaches here with it is not stated.
  if (settings.scheme != engines::SiconosScheme::kEventDriven)
    throw UnsupportedScene(
        "siconos: scheme moreau_jean states one planar body against planes "
        "and the plank-box only");
  check_event_driven(scene);
  return simulate_event_driven(scene, settings, recording);
}

}  // namespace impactbench::adapters
