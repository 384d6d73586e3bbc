#include "lib/model/plank_box/plank_box_parameters.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "lib/output/message_text.hpp"
namespace impactbench::model {
namespace {

void require_finite(double value, const char* field) {
  if (!std::isfinite(value))
    throw std::invalid_argument(std::string("PlankBoxParameters.") + field +
                                " must be finite, got " + output::number_text(value));
}

void require_positive(double value, const char* field) {
  require_finite(value, field);
  if (!(value > 0.0))
    throw std::invalid_argument(std::string("PlankBoxParameters.") + field + " must be > 0, got " +
                                output::number_text(value));
}

void require_non_negative(double value, const char* field) {
  require_finite(value, field);
  if (value < 0.0)
    throw std::invalid_argument(std::string("PlankBoxParameters.") + field + " must be >= 0, got " +
                                output::number_text(value));
}

}  // namespace

double PlankBoxParameters::box_inertia() const {
  return box_mass * (box_length * box_length + box_height * box_height) / 12.0;
}

double PlankBoxParameters::plank_centre_inertia() const {
  if (plank_inertia) return *plank_inertia;
  return plank_mass * (plank_length * plank_length + plank_thickness * plank_thickness) / 12.0;
}

double PlankBoxParameters::plank_hinge_inertia() const {
  return plank_mass * plank_length * plank_length / 4.0 + plank_centre_inertia();
}

void PlankBoxParameters::validate() const {
  require_positive(box_mass, "box_mass");
  require_positive(box_length, "box_length");
  require_positive(box_height, "box_height");
  require_positive(plank_mass, "plank_mass");
  require_positive(plank_length, "plank_length");
  require_positive(plank_thickness, "plank_thickness");
  if (plank_inertia) require_positive(*plank_inertia, "plank_inertia");
  require_non_negative(plank_stiffness, "plank_stiffness");
  require_non_negative(plank_damping, "plank_damping");
  require_non_negative(gravity, "gravity");
  require_non_negative(friction, "friction");
  require_non_negative(restitution, "restitution");
  if (restitution > 1.0)
    throw std::invalid_argument("PlankBoxParameters.restitution must be in [0, 1], got " +
                                output::number_text(restitution));
}

}  // namespace impactbench::model
