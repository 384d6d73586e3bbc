#include "tools/engines/mujoco/mujoco_engine.hpp"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "lib/model/body_inertia.hpp"
#include "lib/output/number_text.hpp"
#include "tools/engines/engine_names.hpp"
#include "tools/engines/fixed_step/fixed_step_driver.hpp"
#include "tools/engines/fixed_step/scene_state.hpp"
#include "tools/engines/fixed_step/step_contacts.hpp"
#include "tools/engines/mujoco/mujoco_sizes.hpp"

namespace impactbench::adapters {
namespace {

constexpr auto kBuiltIn = engines::SettingSource::kBuiltIn;
using output::number_text;

std::string vec_text(const Eigen::Vector3d& v) {
  return number_text(v.x()) + " " + number_text(v.y()) + " " + number_text(v.z());
}

// MuJoCo prints warnings to stdout by default; the adapter reads them from mjData instead.
void silence_warnings() {
  static std::once_flag once;
  std::call_once(once, [] { mju_user_warning = [](const char*) {}; });
}

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
struct VfsDeleter {
  void operator()(mjVFS* v) const {
    mj_deleteVFS(v);
    delete v;
  }
};

// The planar depth of a box and the inertia about the centre, as the other adapters use.
Eigen::Vector3d half_extents(const model::BodySpec& body) {
  if (body.shape == model::ShapeKind::kCuboid) return body.size / 2;
  const double depth = std::max(body.size.x(), body.size.y());
  return Eigen::Vector3d(body.size.x(), body.size.y(), depth) / 2;
}

Eigen::Vector3d body_inertia(const model::BodySpec& body) {
  const double m = body.mass;
  switch (body.shape) {
    case model::ShapeKind::kDisk:  // a disk, not a ball: only the z inertia matters in the plane
      return Eigen::Vector3d::Constant(0.5 * m * body.radius * body.radius);
    case model::ShapeKind::kSphere:
    case model::ShapeKind::kCuboid:
      return model::principal_inertia(body);
    case model::ShapeKind::kBox: {
      const Eigen::Vector3d s = 2 * half_extents(body);
      return m / 12 *
             Eigen::Vector3d(s.y() * s.y() + s.z() * s.z(), s.x() * s.x() + s.z() * s.z(),
                             s.x() * s.x() + s.y() * s.y());
    }
  }
  return Eigen::Vector3d::Zero();
}

std::string geom_text(const model::BodySpec& body, const Eigen::Vector3d& offset) {
  const bool round =
      body.shape == model::ShapeKind::kDisk || body.shape == model::ShapeKind::kSphere;
  return "<geom type=\"" + std::string(round ? "sphere" : "box") + "\" size=\"" +
         (round ? number_text(body.radius) : vec_text(half_extents(body))) + "\" pos=\"" +
         vec_text(offset) + "\"/>";
}

// The MJCF text of the scene. Planar bodies are placed unrotated at their initial centre (so
// the slide axes are the world's x and y) and turned by the hinge's initial position; a hinged
// body's frame sits at its anchor.
std::string mjcf(const ReferenceScene& scene, const MujocoSettings& settings) {
  const double mu = scene.material.friction;
  const double dampratio = settings.solref_dampratio.value_or(
      engines::restitution_damping_ratio(scene.material.restitution));
  // MuJoCo's direct form (−k, −b): a_ref = −b ζ_n − k h with k = 1/τ², b = 2ζ/τ, a spring of
  // natural frequency 1/τ and damping ratio ζ. (The positive form (τ, ζ) means k = 1/(τζ)²: a
  // small ζ for e near 1 would make the contact too stiff for the step.)
  const double tau = engines::solref_timeconst(settings);
  const auto nb = static_cast<int>(scene.bodies.size());
  const MujocoSizes sizes = mujoco_sizes(scene, settings.cone == engines::MujocoCone::kElliptic);
  std::ostringstream x;
  x << "<mujoco model=\"impactbench\">\n<compiler angle=\"radian\"/>\n"
    << "<size nconmax=\"" << sizes.nconmax << "\" njmax=\"" << sizes.njmax << "\"/>\n"
    << "<default><geom condim=\"3\" friction=\"" << number_text(mu) << " 0 0\" solref=\""
    << number_text(-1 / (tau * tau)) << " " << number_text(-2 * dampratio / tau) << "\" solimp=\""
    << number_text(settings.solimp_dmin) << " " << number_text(settings.solimp_dmax) << " "
    << number_text(settings.solimp_width) << "\"/></default>\n<worldbody>\n";
  for (const auto& plane : scene.planes)
    x << "<geom name=\"" << plane.name << "\" type=\"plane\" size=\"0 0 1\" pos=\""
      << vec_text(plane.point) << "\" zaxis=\"" << vec_text(plane.normal.normalized()) << "\"/>\n";
  for (int i = 0; i < nb; ++i) {
    const model::BodySpec& body = scene.bodies[i];
    const HingeSpec* hinge = hinge_of(scene, i);
    const Eigen::Vector3d inertia = body_inertia(body);
    if (!scene.planar) {
      const Eigen::Quaterniond& q = body.orientation;
      x << "<body name=\"" << body.name << "\" pos=\"" << vec_text(body.position) << "\" quat=\""
        << number_text(q.w()) << " " << vec_text(q.vec()) << "\">\n<freejoint/>\n";
      x << "<inertial pos=\"0 0 0\" mass=\"" << number_text(body.mass) << "\" diaginertia=\""
        << vec_text(inertia) << "\"/>\n"
        << geom_text(body, Eigen::Vector3d::Zero()) << "\n</body>\n";
      continue;
    }
    const Eigen::Vector3d origin = hinge ? hinge->anchor : body.position;
    // The centre relative to the frame at hinge angle 0.
    const Eigen::Vector3d offset =
        Eigen::AngleAxisd(-body.angle, Eigen::Vector3d::UnitZ()) * (body.position - origin);
    x << "<body name=\"" << body.name << "\" pos=\"" << vec_text(origin) << "\">\n";
    if (hinge) {
      x << "<joint type=\"hinge\" axis=\"0 0 1\" stiffness=\"" << number_text(hinge->stiffness)
        << "\" damping=\"" << number_text(hinge->damping) << "\"/>\n";
    } else {
      x << "<joint type=\"slide\" axis=\"1 0 0\"/>\n<joint type=\"slide\" axis=\"0 1 0\"/>\n"
        << "<joint type=\"hinge\" axis=\"0 0 1\"/>\n";
    }
    x << "<inertial pos=\"" << vec_text(offset) << "\" mass=\"" << number_text(body.mass)
      << "\" diaginertia=\"" << vec_text(inertia) << "\"/>\n"
      << geom_text(body, offset) << "\n</body>\n";
  }
  x << "</worldbody>\n</mujoco>\n";
  return x.str();
}

std::unique_ptr<mjModel, ModelDeleter> load_model(const std::string& text) {
  std::unique_ptr<mjVFS, VfsDeleter> vfs(new mjVFS);
  mj_defaultVFS(vfs.get());
  const char* file = "impactbench_scene.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), file, static_cast<int>(text.size())) != 0)
    throw std::runtime_error("mujoco: could not hold the model text in memory");
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), file)], text.data(), text.size());
  char error[1000] = "";
  std::unique_ptr<mjModel, ModelDeleter> model(mj_loadXML(file, vfs.get(), error, sizeof error));
  if (!model) throw std::runtime_error(std::string("mujoco: the generated model fails: ") + error);
  return model;
}

void apply_options(mjModel& m, const ReferenceScene& scene, const MujocoSettings& s) {
  m.opt.timestep = s.timestep;
  const Eigen::Vector3d up = scene.planar ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
  for (int a = 0; a < 3; ++a) m.opt.gravity[a] = -scene.gravity * up[a];
  m.opt.integrator = s.integrator == engines::MujocoIntegrator::kEuler ? mjINT_EULER
                     : s.integrator == engines::MujocoIntegrator::kRk4 ? mjINT_RK4
                                                                       : mjINT_IMPLICIT;
  m.opt.solver = s.solver == engines::MujocoSolver::kPgs  ? mjSOL_PGS
                 : s.solver == engines::MujocoSolver::kCg ? mjSOL_CG
                                                          : mjSOL_NEWTON;
  m.opt.iterations = s.iterations;
  m.opt.tolerance = s.tolerance;
  m.opt.cone = s.cone == engines::MujocoCone::kPyramidal ? mjCONE_PYRAMIDAL : mjCONE_ELLIPTIC;
  m.opt.impratio = s.impratio;
  m.opt.noslip_iterations = s.noslip_iterations;
}

// Fails the run when MuJoCo flagged the step from t (its state or its contact buffers).
void check_warnings(const mjModel& m, const mjData& d, double t) {
  const std::string at = "mujoco: the step at t = " + number_text(t) + " s failed (";
  if (d.warning[mjWARN_CONTACTFULL].number > 0 || d.warning[mjWARN_CNSTRFULL].number > 0)
    throw std::runtime_error(at + "too many contacts: more than nconmax = " +
                             std::to_string(m.nconmax) + " or njmax = " + std::to_string(m.njmax) +
                             ", the most MuJoCo 2.2.2's dense constraint arrays can address "
                             "for this scene; see docs/reference-engines.md)");
  for (int w : {mjWARN_BADQACC, mjWARN_BADQVEL, mjWARN_BADQPOS})
    if (d.warning[w].number > 0) throw std::runtime_error(at + "the state is not finite)");
}

// A MuJoCo model and data of the scene, stepped by the fixed-step loop.
class MujocoScene : public FixedStepWorld {
 public:
  MujocoScene(const ReferenceScene& scene, const MujocoSettings& settings)
      : scene_(scene), settings_(settings), model_(load_model(mjcf(scene, settings))) {
    apply_options(*model_, scene, settings);
    data_.reset(mj_makeData(model_.get()));
    const mjModel& m = *model_;
    // Joint addresses per body, in body order (body 0 is the world).
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
      const int joint = m.body_jntadr[i + 1];
      qpos_at_.push_back(m.jnt_qposadr[joint]);
      qvel_at_.push_back(m.jnt_dofadr[joint]);
    }
    set_initial_state();
    for (int g = 0; g < m.ngeom; ++g) {  // per geom: its body's name, or the boundary's
      const int body = m.geom_bodyid[g];
      names_.push_back(body > 0 ? scene.bodies[body - 1].name
                                : scene.planes[static_cast<std::size_t>(g)].name);
    }
    states_ = body_states();
  }

  void record_state(double t, engines::RunResult& result) override {
    states_ = body_states();  // read here too: a timing-only run calls no read_step before it
    add_scene_sample(result, scene_, states_, t);
  }

  void before_step(double) override { before_ = std::move(states_); }

  void step(double t) override {
    mjData& d = *data_;
    mju_zero(d.xfrc_applied, 6 * model_->nbody);
    for (const auto& [body, force] : input_forces(scene_, t))
      for (int a = 0; a < 3; ++a) d.xfrc_applied[6 * (body + 1) + a] = force[a];
    mj_step(model_.get(), &d);
  }

  std::vector<engines::ClosedContact> read_step(double t, engines::StepRecord& step,
                                                engines::RunResult& result) override {
    const mjData& d = *data_;
    check_warnings(*model_, d, t);
    count_phantom_contacts();
    states_ = body_states();
    step.iterations = d.solver_iter;
    step.residual = d.solver_iter > 0 ? d.solver[d.solver_iter - 1].improvement : 0.0;
    // The main solver stops early when it reaches the tolerance; running out of iterations
    // means it did not.
    step.converged = d.solver_iter < settings_.iterations;
    return record_step_contacts(scene_, contacts(), before_, states_, step, result.max_penetration);
  }

  long phantom_contacts() const { return phantom_contacts_; }

 private:
  // Initial state: planar hinges take the initial angle, velocities the initial motion.
  void set_initial_state() {
    mjData& d = *data_;
    for (std::size_t i = 0; i < scene_.bodies.size(); ++i) {
      const model::BodySpec& body = scene_.bodies[i];
      mjtNum* qvel = d.qvel + qvel_at_[i];
      if (!scene_.planar) {
        const Eigen::Vector3d w_local = body.orientation.inverse() * body.angular_velocity;
        for (int a = 0; a < 3; ++a) {
          qvel[a] = body.velocity[a];
          qvel[3 + a] = w_local[a];  // a free joint's angular velocity is in the body frame
        }
      } else if (hinge_of(scene_, static_cast<int>(i))) {
        d.qpos[qpos_at_[i]] = body.angle;
        qvel[0] = body.angular_velocity.z();
      } else {
        d.qpos[qpos_at_[i] + 2] = body.angle;
        qvel[0] = body.velocity.x();
        qvel[1] = body.velocity.y();
        qvel[2] = body.angular_velocity.z();
      }
    }
  }

  std::vector<BodyState> body_states() const {
    std::vector<BodyState> states(scene_.bodies.size());
    for (std::size_t i = 0; i < states.size(); ++i) {
      const model::BodySpec& body = scene_.bodies[i];
      const mjtNum* q = data_->qpos + qpos_at_[i];
      const mjtNum* v = data_->qvel + qvel_at_[i];
      BodyState& s = states[i];
      if (!scene_.planar) {
        s.position = Eigen::Vector3d(q[0], q[1], q[2]);
        s.orientation = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized();
        s.velocity = Eigen::Vector3d(v[0], v[1], v[2]);
        s.angular_velocity = s.orientation * Eigen::Vector3d(v[3], v[4], v[5]);
      } else if (const HingeSpec* hinge = hinge_of(scene_, static_cast<int>(i))) {
        const Eigen::AngleAxisd turn(q[0] - body.angle, Eigen::Vector3d::UnitZ());
        s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(q[0], Eigen::Vector3d::UnitZ()));
        s.angle = q[0];
        s.position = hinge->anchor + turn * (body.position - hinge->anchor);
        s.angular_velocity = Eigen::Vector3d(0, 0, v[0]);
        s.velocity = s.angular_velocity.cross(s.position - hinge->anchor);
      } else {
        s.position = body.position + Eigen::Vector3d(q[0], q[1], 0.0);
        s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(q[2], Eigen::Vector3d::UnitZ()));
        s.angle = q[2];
        s.velocity = Eigen::Vector3d(v[0], v[1], 0.0);
        s.angular_velocity = Eigen::Vector3d(0, 0, v[2]);
      }
    }
    return states;
  }

  // Box–box contacts deeper than half the thinner box's half-size: no pose of boxes that the
  // soft contact holds apart overlaps so; MuJoCo 2.2.2's box–box collider reports such phantom
  // depths for boxes resting face to face (tests/engines/mujoco_box_collider_test.cpp).
  void count_phantom_contacts() {
    const mjModel& m = *model_;
    const mjData& d = *data_;
    const auto thinnest = [&m](int geom) {
      return std::min(
          {m.geom_size[3 * geom], m.geom_size[3 * geom + 1], m.geom_size[3 * geom + 2]});
    };
    for (int c = 0; c < d.ncon; ++c) {
      const mjContact& con = d.contact[c];
      if (m.geom_type[con.geom1] == mjGEOM_BOX && m.geom_type[con.geom2] == mjGEOM_BOX &&
          -con.dist > 0.5 * std::min(thinnest(con.geom1), thinnest(con.geom2)))
        ++phantom_contacts_;
    }
  }

  // The step's contacts that enter MuJoCo's problem.
  std::vector<PointContact> contacts() const {
    const mjModel& m = *model_;
    const mjData& d = *data_;
    std::vector<PointContact> out;
    for (int c = 0; c < d.ncon; ++c) {
      const mjContact& con = d.contact[c];
      if (con.efc_address < 0) continue;  // excluded by MuJoCo
      // The frame's normal points from geom 1 to geom 2 and the force acts on geom 2 along
      // it: geom 2's body is the reported body 1.
      mjtNum f[6];
      mj_contactForce(&m, &d, c, f);
      const Eigen::Vector3d n(con.frame[0], con.frame[1], con.frame[2]);
      const Eigen::Vector3d t1(con.frame[3], con.frame[4], con.frame[5]);
      const Eigen::Vector3d t2(con.frame[6], con.frame[7], con.frame[8]);
      const int b1 = m.geom_bodyid[con.geom2] - 1, b2 = m.geom_bodyid[con.geom1] - 1;
      out.push_back({names_[con.geom2] + "-" + names_[con.geom1], b1, b2,
                     Eigen::Vector3d(con.pos[0], con.pos[1], con.pos[2]), n,
                     std::max(0.0, -con.dist),
                     (f[0] * n + f[1] * t1 + f[2] * t2) * settings_.timestep});
    }
    return out;
  }

  const ReferenceScene& scene_;
  const MujocoSettings& settings_;
  std::unique_ptr<mjModel, ModelDeleter> model_;
  std::unique_ptr<mjData, DataDeleter> data_;
  std::vector<int> qpos_at_, qvel_at_;
  std::vector<std::string> names_;  // per geom: its body's name, or the boundary's
  std::vector<BodyState> states_;   // after the last step
  std::vector<BodyState> before_;   // at the step's start
  long phantom_contacts_ = 0;
};

}  // namespace

engines::RunResult run_mujoco(const ReferenceScene& scene, const MujocoSettings& settings,
                              const engines::RecordingOptions& recording) {
  if (!scene.planar && !scene.hinges.empty())
    throw UnsupportedScene("mujoco: hinges are built for planar scenes only");
  silence_warnings();
  MujocoScene world(scene, settings);
  // Rest measured from the exact contact.
  engines::RunResult result = scene_result(engine_name::kMujoco, scene, recording);
  const double dampratio = settings.solref_dampratio.value_or(
      engines::restitution_damping_ratio(scene.material.restitution));
  result.settings = {
      {"precision", "double", kBuiltIn},
      {"solref_timeconst_in_force", number_text(engines::solref_timeconst(settings)), kBuiltIn},
      {"solref_dampratio_in_force", number_text(dampratio), kBuiltIn},
      {"friction_combine", "max (every geom has the scenario's mu)", kBuiltIn}};
  // The step is the settings' timestep, which the registry also gives the scene.
  run_fixed_steps(world,
                  {engine_name::kMujoco, settings.timestep, scene.duration, settings.impact, true},
                  result);
  if (world.phantom_contacts() > 0)
    result.defect_note = "MuJoCo 2.2.2's box-box collider reported " +
                         std::to_string(world.phantom_contacts()) +
                         " contacts deeper than half a box between boxes, a depth no pose of "
                         "these boxes has (upstream google-deepmind/mujoco issue 3476); the "
                         "boxes it ejects make this run's energy and penetration figures "
                         "(docs/reference-engines.md)";
  return result;
}

}  // namespace impactbench::adapters
