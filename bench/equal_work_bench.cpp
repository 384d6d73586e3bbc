// Engine CPU time per step at equal work on the piles, every engine in the same process, one
// after the other in each iteration (so machine load hits them alike): Moreau–Jean with 10
// sweeps, Box2D with 8 velocity + 3 position iterations, Bullet with 10 iterations, each run
// from the scenario's initial state for the same simulated time through the engines' own
// drivers as bare loops (timing-only runs: nothing of ours between the steps). The 1,000-body
// piles run five such rounds and the 10,000-disk pile one: this machine's speed drifts by tens
// of percent between runs seconds apart, and one round's ratio can land on either side of a
// target that a mean over rounds does not.
// A separate Moreau–Jean run without any observer counts heap allocations per step (malloc and
// its kin counted in this binary) after the first tenth of the steps, and the cost of a sweep
// per contact.
// Counters (per step, CPU, means over the rounds): moreau_ms, box2d_ms, bullet_ms,
// box2d_over_moreau = box2d_ms / moreau_ms (> 1: Moreau–Jean is faster), bullet_over_moreau,
// box2d_over_moreau_least and bullet_over_moreau_least (the least of the rounds' own ratios),
// rounds, moreau_allocs_per_step,
// moreau_allocating_step_share (the share of counted steps that allocated at all),
// moreau_steady_allocs_per_step (allocations per counted step that met no more candidate
// contacts than an earlier step, so needed no new contact storage), unchanged_active_share (the
// share of counted steps with as many active contacts as the step before),
// solve_wall_ns_per_contact_sweep (the solver's own wall-clock time, residuals included, over
// active contacts × sweeps), contacts (mean active per step of the Moreau–Jean run); on the disk
// piles also prox_gs_solve_wall_ns_per_contact_sweep, the same figure of a second such run with
// prox-gs in place of nsgs (10 sweeps as well).
// BM_WideGrowth measures Moreau–Jean's growth from 1,000 to 10,000 wide disks in one run: three
// rounds, each a bare loop of 1 s at 1,000 disks, one at 10,000 and one more at 1,000 (so that a
// drift of the machine's speed within the round hits both sizes alike). Counters (CPU per step,
// medians over the rounds): moreau_ms_1000, moreau_ms_10000, growth_exponent =
// log10(moreau_ms_10000 / moreau_ms_1000) (the step grows as N^growth_exponent), and
// growth_exponent_min/max, the extremes of the rounds' own exponents (each from its 10,000-disk
// step and the mean of the two 1,000-disk steps around it).
// BM_SettledAllocations runs Moreau–Jean alone on a pile for 3 s and counts over the last 0.5 s,
// when the pile has settled: moreau_allocs_per_step (and prox_gs_allocs_per_step, the same with
// prox-gs in place of nsgs), moreau_allocating_step_share,
// unchanged_active_share (the share of those steps with as many active contacts as the step
// before: the problem's size, on which its vectors' storage depends, did not change), contacts.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "common/registered_main.hpp"
#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "lib/engines/system_builder.hpp"
#include "lib/scenario/scenario.hpp"
#include "lib/validation/score_statistics.hpp"
#include "tests/support/heap/heap_allocations.hpp"
#include "tools/engines/engine_names.hpp"
#include "tools/engines/moreau/moreau_engine.hpp"
#include "tools/engines/registry/equal_work.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace {

namespace engines = impactbench::engines;
namespace mj = impactbench::engines::moreau_jean;
namespace scenario = impactbench::scenario;
namespace validation = impactbench::validation;
namespace engine_name = impactbench::engine_name;

constexpr double kDuration = 1.0;  // [s] simulated per engine and iteration (1,000 steps)
// Rounds of the 1,000-body piles (a few seconds each); the 10,000-disk pile runs one (Box2D's
// second alone takes about a minute there).
constexpr int kRoundsAt1000 = 5;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// The equal-work settings (tools/engines/registry/equal_work.hpp) for one run of 1 s.
engines::SettingsRequest equal_work(const std::string& engine) {
  engines::SettingsRequest request;
  request.duration = kDuration;
  request.options = engines::equal_work_settings(engine);
  return request;
}

// Engine CPU seconds per step of one bare loop through the engine's driver (a timing-only
// run: nothing of ours between the steps), as the suite's equal-work table measures it.
double seconds_per_step(const std::string& engine, const scenario::Scenario& s) {
  return engines::bare_loop_seconds_per_step(
      s, engines::resolve_run_options(engine, s, equal_work(engine)));
}

struct MoreauCounts {
  double allocations_per_step = 0.0;
  // Of the counted steps, the share that allocated at all, and the allocations per step of
  // those that met no more candidate contacts than some earlier step (contact storage grows
  // with the candidates: these steps need none).
  double allocating_step_share = 0.0;
  double steady_allocations_per_step = 0.0;
  double unchanged_active_share = 0.0;
  double sweep_ns_per_contact = 0.0;
  double mean_contacts = 0.0;
};

// Steps Moreau–Jean directly (no observer, no records kept) for `duration` seconds and counts
// from `counted_from` on; `solver` in place of the equal-work settings' when given.
MoreauCounts count_moreau(const scenario::Scenario& s, double duration, double counted_from,
                          const std::string& solver = {}) {
  engines::SettingsRequest request = equal_work(engine_name::kMoreau);
  request.duration = duration;
  if (!solver.empty())
    for (auto& [key, value] : request.options)
      if (key == "solver") value = solver;
  const auto options = engines::resolve_run_options(engine_name::kMoreau, s, request);
  mj::MoreauJeanOptions o = mj::options_from(options);
  const engines::BuiltSystem built = engines::build_system(s);
  mj::MoreauJeanStepper stepper(*built.system, o);
  mj::MoreauJeanState state{0.0, built.q0, built.v0};
  const long steps = std::lround(duration / o.dt);
  const long warmup = std::lround(counted_from / o.dt);
  MoreauCounts counts;
  double solve_seconds = 0.0;
  double contact_sweeps = 0.0;
  long counted_allocations = 0;
  long allocating_steps = 0;
  long steady_steps = 0;
  long steady_allocations = 0;
  long unchanged_active_steps = 0;
  int most_candidates = 0;
  int previous_active = -1;
  for (long k = 0; k < steps; ++k) {
    const long before = impactbench::heap::allocations();
    const mj::StepReport report = stepper.step(state, {});
    const long allocated = impactbench::heap::allocations() - before;
    const auto& stats = report.statistics;
    const bool steady = k > 0 && stats.candidate_contacts <= most_candidates;
    most_candidates = std::max(most_candidates, stats.candidate_contacts);
    const bool unchanged_active = stats.active_contacts == previous_active;
    previous_active = stats.active_contacts;
    if (k < warmup) continue;
    unchanged_active_steps += unchanged_active ? 1 : 0;
    counted_allocations += allocated;
    allocating_steps += allocated > 0 ? 1 : 0;
    if (steady) ++steady_steps, steady_allocations += allocated;
    solve_seconds += stats.solve_seconds;
    contact_sweeps += static_cast<double>(stats.active_contacts) * stats.solver_iterations;
    counts.mean_contacts += stats.active_contacts;
  }
  const auto counted = static_cast<double>(steps - warmup);
  counts.allocations_per_step = static_cast<double>(counted_allocations) / counted;
  counts.allocating_step_share = static_cast<double>(allocating_steps) / counted;
  counts.unchanged_active_share = static_cast<double>(unchanged_active_steps) / counted;
  counts.steady_allocations_per_step =
      steady_steps > 0 ? static_cast<double>(steady_allocations) / steady_steps : kNaN;
  counts.sweep_ns_per_contact = contact_sweeps > 0 ? 1e9 * solve_seconds / contact_sweeps : kNaN;
  counts.mean_contacts /= counted;
  return counts;
}

// The pile `scene` of `count` bodies for `duration`; `wide`: the box widened with the count
// (width = count/100 m: one layer of about ten disks per metre, the pile's height independent
// of N), the scaling case.
scenario::Scenario pile_scenario(const std::string& scene, int count, bool wide, double duration) {
  scenario::ParameterOverrides overrides{{"count", count}};
  if (wide) overrides["width"] = count / 100.0;
  return scenario::load_scenario_by_name(scene, overrides, duration);
}

// Every engine at equal work on the pile (see the header); `wide` as in pile_scenario.
void BM_EqualWork(benchmark::State& state, const std::string& scene, bool planar, bool wide) {
  const int count = static_cast<int>(state.range(0));
  const scenario::Scenario s = pile_scenario(scene, count, wide, kDuration);
  double moreau = 0.0;
  double box2d = 0.0;
  double bullet = 0.0;
  long rounds = 0;
  // Each round's own ratios: the least of them is the margin the worst round left.
  double least_box2d_ratio = kNaN;
  double least_bullet_ratio = kNaN;
  for (auto _ : state) {  // interleaved: every engine once per iteration
    const double moreau_round = seconds_per_step(engine_name::kMoreau, s);
    const double box2d_round = planar ? seconds_per_step(engine_name::kBox2d, s) : kNaN;
    const double bullet_round = seconds_per_step(engine_name::kBullet, s);
    moreau += moreau_round;
    box2d += planar ? box2d_round : 0.0;
    bullet += bullet_round;
    least_box2d_ratio = std::fmin(least_box2d_ratio, box2d_round / moreau_round);
    least_bullet_ratio = std::fmin(least_bullet_ratio, bullet_round / moreau_round);
    ++rounds;
  }
  const MoreauCounts counts = count_moreau(s, kDuration, kDuration / 10);
  const auto per_round = [&](double total) { return 1e3 * total / static_cast<double>(rounds); };
  state.counters["bodies"] = count;
  state.counters["moreau_ms"] = per_round(moreau);
  state.counters["box2d_ms"] = planar ? per_round(box2d) : kNaN;
  state.counters["bullet_ms"] = per_round(bullet);
  state.counters["box2d_over_moreau"] = planar ? box2d / moreau : kNaN;
  state.counters["bullet_over_moreau"] = bullet / moreau;
  state.counters["box2d_over_moreau_least"] = least_box2d_ratio;
  state.counters["bullet_over_moreau_least"] = least_bullet_ratio;
  state.counters["rounds"] = static_cast<double>(rounds);
  state.counters["moreau_allocs_per_step"] = counts.allocations_per_step;
  state.counters["moreau_allocating_step_share"] = counts.allocating_step_share;
  state.counters["moreau_steady_allocs_per_step"] = counts.steady_allocations_per_step;
  state.counters["unchanged_active_share"] = counts.unchanged_active_share;
  state.counters["solve_wall_ns_per_contact_sweep"] = counts.sweep_ns_per_contact;
  state.counters["prox_gs_solve_wall_ns_per_contact_sweep"] =
      planar ? count_moreau(s, kDuration, kDuration / 10, "prox-gs").sweep_ns_per_contact : kNaN;
  state.counters["contacts"] = counts.mean_contacts;
}

// Heap allocations per step of a settled pile (see the header): a pile in steady state.
void BM_SettledAllocations(benchmark::State& state, const std::string& scene, bool wide) {
  constexpr double kSettledDuration = 3.0;  // [s]: the piles are at rest by 2.5 s
  constexpr double kCountedFrom = 2.5;      // [s]
  const int count = static_cast<int>(state.range(0));
  const scenario::Scenario s = pile_scenario(scene, count, wide, kSettledDuration);
  MoreauCounts counts;
  for (auto _ : state) counts = count_moreau(s, kSettledDuration, kCountedFrom);
  state.counters["bodies"] = count;
  state.counters["moreau_allocs_per_step"] = counts.allocations_per_step;
  state.counters["moreau_allocating_step_share"] = counts.allocating_step_share;
  state.counters["unchanged_active_share"] = counts.unchanged_active_share;
  state.counters["contacts"] = counts.mean_contacts;
  // prox-gs, the targets' other sweep, on the same pile.
  state.counters["prox_gs_allocs_per_step"] =
      count_moreau(s, kSettledDuration, kCountedFrom, "prox-gs").allocations_per_step;
}

// Moreau–Jean's growth from 1,000 to 10,000 wide disks (see the header), both sizes in one run.
void BM_WideGrowth(benchmark::State& state) {
  constexpr int kRounds = 3;
  const scenario::Scenario small = pile_scenario("disk_pile", 1000, true, kDuration);
  const scenario::Scenario large = pile_scenario("disk_pile", 10000, true, kDuration);
  std::vector<double> small_ms, large_ms, exponents;
  for (auto _ : state) {
    for (int round = 0; round < kRounds; ++round) {
      const double before = seconds_per_step(engine_name::kMoreau, small);
      const double big = seconds_per_step(engine_name::kMoreau, large);
      const double after = seconds_per_step(engine_name::kMoreau, small);
      small_ms.insert(small_ms.end(), {1e3 * before, 1e3 * after});
      large_ms.push_back(1e3 * big);
      exponents.push_back(std::log10(big / (0.5 * (before + after))));  // 10× the bodies
    }
  }
  const double small_median = validation::percentile(small_ms, 0.5);
  const double large_median = validation::percentile(large_ms, 0.5);
  state.counters["moreau_ms_1000"] = small_median;
  state.counters["moreau_ms_10000"] = large_median;
  state.counters["growth_exponent"] = std::log10(large_median / small_median);
  state.counters["growth_exponent_min"] = *std::min_element(exponents.begin(), exponents.end());
  state.counters["growth_exponent_max"] = *std::max_element(exponents.begin(), exponents.end());
}

BENCHMARK_CAPTURE(BM_EqualWork, disk_pile, "disk_pile", true, false)
    ->Arg(1000)
    ->Iterations(kRoundsAt1000)
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_EqualWork, wide_disk_pile, "disk_pile", true, true)
    ->Arg(1000)
    ->Iterations(kRoundsAt1000)
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_EqualWork, wide_disk_pile, "disk_pile", true, true)
    ->Arg(10000)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_EqualWork, sphere_pile, "sphere_pile", false, false)
    ->Arg(1000)
    ->Iterations(kRoundsAt1000)
    ->Unit(benchmark::kSecond);
BENCHMARK(BM_WideGrowth)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_SettledAllocations, disk_pile, "disk_pile", false)
    ->Arg(1000)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_SettledAllocations, wide_disk_pile, "disk_pile", true)
    ->Arg(1000)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_SettledAllocations, sphere_pile, "sphere_pile", false)
    ->Arg(1000)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

}  // namespace

int main(int argc, char** argv) {
  return impactbench::bench::run_registered_benchmarks(argc, argv, [] {});
}
