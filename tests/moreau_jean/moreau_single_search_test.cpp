// The time stepper's one candidate search (find_reachable_contacts, where the system bounds its
// contacts' motion) against its two-search fallback (the contacts within the margin at the
// predicted state, then a search at q wide enough to hold them all): both hold every contact the
// activation rule admits, in the same order, so the two runs must agree bit for bit. A pile of
// 200 disks dropped for 0.15 s (impacts, sliding, a pile forming), a pyramid of 36 boxes dropped
// onto each other, and a pile of 60 spheres. The one search leaves its contacts unnamed and the
// stepper names those it reports through the system (write_contact_name): the names must be the
// ones the fallback's searches give.
#include <gtest/gtest.h>

#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "lib/model/planar/planar_scenes.hpp"
#include "lib/model/planar/planar_system.hpp"
#include "lib/model/spatial/spatial_scenes.hpp"
#include "lib/model/spatial/spatial_system.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

using System = model::LagrangianSystem<double>;

// Long enough for impacts and a forming pile; under the sanitizers (10–15× slower) the disk
// pile runs its first 60 ms, where it already has its contacts (the box pyramid runs 80 ms and
// the spheres, which start apart, 0.3 s everywhere).
#if defined(__SANITIZE_ADDRESS__)
constexpr double kDuration = 0.06;  // [s]
#else
constexpr double kDuration = 0.15;  // [s]
#endif

// Everything of the wrapped system except find_reachable_contacts (so the stepper falls back).
class WithoutReach final : public System {
 public:
  explicit WithoutReach(const System& inner) : inner_(inner) {}
  int num_positions() const override { return inner_.num_positions(); }
  int num_velocities() const override { return inner_.num_velocities(); }
  int num_inputs() const override { return inner_.num_inputs(); }
  int tangent_dim() const override { return inner_.tangent_dim(); }
  SparseMatrix mass_matrix(const Vector& q) const override { return inner_.mass_matrix(q); }
  Vector bias_forces(const Vector& q, const Vector& v) const override {
    return inner_.bias_forces(q, v);
  }
  bool has_damping_matrix() const override { return inner_.has_damping_matrix(); }
  SparseMatrix damping_matrix(const Vector& q, const Vector& v) const override {
    return inner_.damping_matrix(q, v);
  }
  Matrix input_matrix(const Vector& q) const override { return inner_.input_matrix(q); }
  Vector position_rate(const Vector& q, const Vector& v) const override {
    return inner_.position_rate(q, v);
  }
  Vector integrate_position(const Vector& q, const Vector& v, const double& h) const override {
    return inner_.integrate_position(q, v, h);
  }
  void find_contacts(const Vector& q, const Vector& v, double margin,
                     std::vector<model::Contact<double>>& out) const override {
    inner_.find_contacts(q, v, margin, out);
  }
  double energy(const Vector& q, const Vector& v) const override { return inner_.energy(q, v); }
  std::vector<std::string> position_names() const override { return inner_.position_names(); }
  std::vector<std::string> velocity_names() const override { return inner_.velocity_names(); }

 private:
  const System& inner_;
};

void expect_same_runs(const System& system, const Eigen::VectorXd& q0, double duration) {
  MoreauJeanOptions options;
  options.dt = 1e-3;
  options.tolerance = 1e-6;
  options.on_failure = OnFailure::kWarn;
  options.record_impulses = true;
  options.record_steps = true;
  MoreauJeanStepper one_search(system, options);
  const WithoutReach fallback_system(system);
  MoreauJeanStepper two_searches(fallback_system, options);
  const Eigen::VectorXd v0 = Eigen::VectorXd::Zero(system.num_velocities());
  const auto a = one_search.simulate(q0, v0, {}, duration);
  const auto b = two_searches.simulate(q0, v0, {}, duration);
  ASSERT_TRUE(a.succeeded()) << a.message;
  ASSERT_TRUE(b.succeeded()) << b.message;
  ASSERT_EQ(a.steps.size(), b.steps.size());
  int contacts = 0;
  for (std::size_t k = 0; k < a.steps.size(); ++k) {
    ASSERT_EQ(a.steps[k].active_contacts, b.steps[k].active_contacts) << "step " << k;
    contacts = std::max(contacts, a.steps[k].active_contacts);
  }
  EXPECT_GT(contacts, 50);                      // the pile must actually form
  EXPECT_EQ(a.final_state.q, b.final_state.q);  // bit for bit
  EXPECT_EQ(a.final_state.v, b.final_state.v);
  EXPECT_EQ(a.summary.late_contacts, b.summary.late_contacts);
  ASSERT_EQ(a.impulses.size(), b.impulses.size());
  std::size_t named = 0;
  for (std::size_t k = 0; k < a.impulses.size(); ++k) {
    ASSERT_EQ(a.impulses[k].size(), b.impulses[k].size()) << "step " << k;
    for (std::size_t i = 0; i < a.impulses[k].size(); ++i) {
      ASSERT_FALSE(b.impulses[k][i].name.empty()) << "step " << k;
      ASSERT_EQ(a.impulses[k][i].name, b.impulses[k][i].name) << "step " << k;
      ++named;
    }
  }
  EXPECT_GT(named, 1000u);
}

TEST(MoreauSingleSearch, DiskPileAgreesBitForBitWithTwoSearches) {
  const auto scene = model::planar::make_disk_pile(200, 4);
  const model::planar::PlanarRigidBodySystemd system(scene.bodies, scene.planes, 9.81, {0.3, 0.1});
  expect_same_runs(system, system.initial_positions(), kDuration);
}

TEST(MoreauSingleSearch, BoxPyramidAgreesBitForBitWithTwoSearches) {
  const auto scene = model::planar::make_box_pyramid(8);
  const model::planar::PlanarRigidBodySystemd system(scene.bodies, scene.planes, 9.81, {0.5, 0.0});
  Eigen::VectorXd q0 = system.initial_positions();
  for (int i = 0; i < system.num_bodies(); ++i) q0(3 * i + 1) += 0.01 * (i % 3);  // drops
  expect_same_runs(system, q0, 0.08);  // the 2 cm drops land at 64 ms
}

TEST(MoreauSingleSearch, SpherePileAgreesBitForBitWithTwoSearches) {
  const model::spatial::SpatialRigidBodySystem<double> system(
      model::spatial::make_sphere_pile(60, 4));
  expect_same_runs(system, system.initial_positions(), 0.3);  // ~11 s under the sanitizers
}

}  // namespace
}  // namespace impactbench::engines::moreau_jean
