// Time per Moreau–Jean step on settled piles (planar disk_pile, spatial sphere_pile) of 100 to
// 10,000 bodies, per contact solver. Each pile is built and settled once (nsgs, 0.3 s) and
// cached; each benchmark then starts from the settled state,
// takes one untimed step (so the warm start is that of a running simulation) and times the
// following steps, each warm-started by the previous one as in a simulation.
// Counters: contacts (active per step), iterations, residual, converged (fraction of steps).
// Growth exponent: fit log(time) against log(bodies) over the sizes of one solver.
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include <benchmark/benchmark.h>

#include "common/registered_main.hpp"
#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "lib/model/planar/planar_scenes.hpp"
#include "lib/model/planar/planar_system.hpp"
#include "lib/model/spatial/spatial_scenes.hpp"
#include "lib/model/spatial/spatial_system.hpp"

namespace mj = impactbench::engines::moreau_jean;
namespace model = impactbench::model;

namespace {

constexpr double kStep = 1e-3;  // [s]
constexpr double kFriction = 0.3;
constexpr double kMargin = 0.01;  // [m], finds the neighbours a step can reach

enum class PileKind { kDisks, kSpheres };

struct SettledPile {
  std::unique_ptr<model::LagrangianSystem<double>> system;
  mj::MoreauJeanState state;
};

std::unique_ptr<model::LagrangianSystem<double>> build(PileKind kind, int bodies) {
  const model::Material material{kFriction, 0.0};
  if (kind == PileKind::kDisks) {
    const auto scene = model::planar::make_disk_pile(bodies, 1);
    return std::make_unique<model::planar::PlanarRigidBodySystemd>(scene.bodies, scene.planes, 9.81,
                                                                   material);
  }
  auto spec = model::spatial::make_sphere_pile(bodies, 1);
  spec.material = material;
  return std::make_unique<model::spatial::SpatialRigidBodySystem<double>>(std::move(spec));
}

Eigen::VectorXd initial_q(const model::LagrangianSystem<double>& s) {
  if (const auto* p = dynamic_cast<const model::planar::PlanarRigidBodySystemd*>(&s))
    return p->initial_positions();
  return dynamic_cast<const model::spatial::SpatialRigidBodySystem<double>&>(s).initial_positions();
}

mj::MoreauJeanOptions options_for(const std::string& solver) {
  mj::MoreauJeanOptions o;
  o.dt = kStep;
  o.solver = solver;
  o.tolerance = 1e-4;  // a typical game/robotics setting; convergence is reported per step
  o.max_iterations = solver == "lemke" ? 1000000 : 200;  // lemke: pivots, not sweeps
  o.on_failure = mj::OnFailure::kWarn;
  o.contact_margin = kMargin;
  o.record_impulses = false;
  return o;
}

// Long enough for every layer of the lattice-placed piles to land (about 0.1 s of fall plus
// the impacts dying out); the 10,000-body piles take about a minute to settle.
constexpr double kSettleTime = 0.3;  // [s]

const SettledPile& settled(PileKind kind, int bodies) {
  static std::map<std::pair<int, int>, SettledPile> cache;
  const auto key = std::make_pair(static_cast<int>(kind), bodies);
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  SettledPile pile;
  pile.system = build(kind, bodies);
  mj::MoreauJeanStepper stepper(*pile.system, options_for("nsgs"));
  const Eigen::VectorXd q0 = initial_q(*pile.system);
  const auto run =
      stepper.simulate(q0, Eigen::VectorXd::Zero(pile.system->num_velocities()), {}, kSettleTime);
  if (!run.succeeded()) throw std::runtime_error("settling failed: " + run.message);
  pile.state = run.final_state;
  return cache.emplace(key, std::move(pile)).first->second;
}

void BM_MoreauStep(benchmark::State& state, PileKind kind, std::string solver) {
  const int bodies = static_cast<int>(state.range(0));
  const SettledPile& pile = settled(kind, bodies);
  mj::MoreauJeanStepper stepper(*pile.system, options_for(solver));
  mj::MoreauJeanState s = pile.state;
  stepper.step(s, {});  // warm start from a step of this solver
  double contacts = 0, iterations = 0, residual = 0, converged = 0, steps = 0;
  for (auto _ : state) {
    const mj::StepReport report = stepper.step(s, {});
    if (!report.advanced) {
      state.SkipWithError(report.message().c_str());
      break;
    }
    benchmark::DoNotOptimize(s.v.data());
    contacts += report.statistics.active_contacts;
    iterations += report.statistics.solver_iterations;
    residual = std::max(residual, report.statistics.residual);
    converged += report.statistics.converged ? 1 : 0;
    steps += 1;
  }
  if (steps == 0) return;
  state.counters["bodies"] = bodies;
  state.counters["contacts"] = contacts / steps;
  state.counters["iterations"] = iterations / steps;
  state.counters["residual"] = residual;
  state.counters["converged"] = converged / steps;
  state.SetComplexityN(bodies);
}

// Fixed step counts keep the binary's run time bounded: the largest piles take seconds a step.
int timed_steps(int bodies) {
  return bodies <= 100 ? 20 : bodies <= 300 ? 10 : bodies <= 1000 ? 5 : 2;
}

struct SolverCase {
  const char* solver;
  int largest;  ///< pivoting (lemke) and Newton (nsn) methods are kept to smaller piles
};

void register_all() {
  const SolverCase cases[] = {{"nsgs", 10000}, {"prox-gs", 10000}, {"prox-jacobi", 10000},
                              {"nsn", 300},    {"pgs", 1000},      {"lemke", 100}};
  for (const auto& [kind, kind_name] :
       {std::pair{PileKind::kDisks, "disk_pile"}, std::pair{PileKind::kSpheres, "sphere_pile"}}) {
    for (const SolverCase& c : cases) {
      for (int n : {100, 300, 1000, 3000, 10000}) {
        if (n > c.largest) continue;
        const std::string name = std::string("BM_MoreauStep/") + kind_name + "/" + c.solver;
        benchmark::RegisterBenchmark(name.c_str(), BM_MoreauStep, kind, std::string(c.solver))
            ->Arg(n)
            ->Iterations(timed_steps(n))
            ->Unit(benchmark::kMillisecond);
      }
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  return impactbench::bench::run_registered_benchmarks(argc, argv, register_all);
}
