#include "lib/engines/moreau_jean/moreau_jean_options.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "lib/output/number_text.hpp"
#include "solvers/friction/friction_solvers.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("Moreau–Jean option " + what);
}

}  // namespace

void validate(const MoreauJeanOptions& o) {
  require(std::isfinite(o.dt) && o.dt > 0.0, "dt must be > 0, got " + output::number_text(o.dt));
  require(o.theta >= 0.5 && o.theta <= 1.0,
          "theta must be in [0.5, 1], got " + output::number_text(o.theta));
  require(std::isfinite(o.tolerance) && o.tolerance > 0.0,
          "tolerance must be > 0, got " + output::number_text(o.tolerance));
  require(o.max_iterations > 0,
          "max_iterations must be > 0, got " + std::to_string(o.max_iterations));
  require(std::isfinite(o.contact_margin) && o.contact_margin >= 0.0,
          "contact_margin must be >= 0, got " + output::number_text(o.contact_margin));
  if (o.activation_horizon)
    require(
        *o.activation_horizon >= 0.0 && *o.activation_horizon <= 1.0,
        "activation_horizon must be in [0, 1], got " + output::number_text(*o.activation_horizon));
  require(std::isfinite(o.activation_tolerance) && o.activation_tolerance >= 0.0,
          "activation_tolerance must be >= 0, got " + output::number_text(o.activation_tolerance));
  require(o.cone_facets >= 3, "cone_facets must be >= 3, got " + std::to_string(o.cone_facets));
  require(std::isfinite(o.jacobian_step) && o.jacobian_step > 0.0,
          "jacobian_step must be > 0, got " + output::number_text(o.jacobian_step));
  require(o.dense_delassus_max_rows >= 0, "dense_delassus_max_rows must be >= 0");
  const auto& known = solvers::friction_solvers();
  const bool found = std::any_of(known.begin(), known.end(),
                                 [&](const solvers::SolverInfo& s) { return s.name == o.solver; });
  if (!found) {
    std::string names;
    for (const auto& s : known) names += (names.empty() ? "" : ", ") + s.name;
    throw std::invalid_argument("Moreau–Jean option solver: unknown friction solver '" + o.solver +
                                "' (known: " + names + ")");
  }
}

double activation_horizon(const MoreauJeanOptions& o) {
  return o.activation_horizon.value_or(o.theta);
}

}  // namespace impactbench::engines::moreau_jean
