#include "lib/sensitivity/nominal_trajectory.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace impactbench::sensitivity {

void NominalTrajectory::validate(int state_size, int num_contacts) const {
  if (!(std::isfinite(t_begin) && std::isfinite(t_end) && t_end > t_begin))
    throw std::invalid_argument("NominalTrajectory: need finite t_begin < t_end");
  if (x0.size() != state_size || !x0.allFinite())
    throw std::invalid_argument("NominalTrajectory: x0 must be finite with " +
                                std::to_string(state_size) + " entries");
  if (static_cast<int>(mode0.size()) != num_contacts)
    throw std::invalid_argument("NominalTrajectory: mode0 must have " +
                                std::to_string(num_contacts) + " phases");
  double previous = t_begin;
  for (std::size_t k = 0; k < events.size(); ++k) {
    const NominalEvent& e = events[k];
    if (!(e.time > previous && e.time < t_end))
      throw std::invalid_argument("NominalTrajectory: event " + std::to_string(k) +
                                  " at t = " + std::to_string(e.time) +
                                  " is not after the previous one and before t_end");
    if (e.micro_events.empty())
      throw std::invalid_argument("NominalTrajectory: event " + std::to_string(k) +
                                  " has no micro events");
    if (e.x_plus && (e.x_plus->size() != state_size || !e.x_plus->allFinite()))
      throw std::invalid_argument("NominalTrajectory: event " + std::to_string(k) +
                                  " has an invalid post-event state");
    previous = e.time;
  }
}

Eigen::VectorXd NominalTrajectory::input_at(double t, int input_size) const {
  if (!input) return Eigen::VectorXd::Zero(input_size);
  Eigen::VectorXd u = input(t);
  if (u.size() != input_size)
    throw std::invalid_argument("NominalTrajectory: input(t) has " + std::to_string(u.size()) +
                                " entries, expected " + std::to_string(input_size));
  return u;
}

Eigen::VectorXd NominalTrajectory::input_rate_at(double t, int input_size) const {
  if (!input_rate) return Eigen::VectorXd::Zero(input_size);
  Eigen::VectorXd r = input_rate(t);
  if (r.size() != input_size)
    throw std::invalid_argument("NominalTrajectory: input_rate(t) has " + std::to_string(r.size()) +
                                " entries, expected " + std::to_string(input_size));
  return r;
}

}  // namespace impactbench::sensitivity
