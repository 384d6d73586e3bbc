#include "lib/engines/event_driven/sample_table.hpp"

#include <stdexcept>
#include <string>

namespace impactbench::engines::event_driven {

void SampleTable::set_sizes(Eigen::Index nq, Eigen::Index nv) {
  if (nq < 0 || nv < 0) throw std::invalid_argument("sample table: negative state size");
  nq_ = nq;
  nv_ = nv;
  clear();
}

void SampleTable::reserve(std::size_t count) {
  times_.reserve(count);
  energies_.reserve(count);
  values_.reserve(count * static_cast<std::size_t>(nq_ + nv_));
}

void SampleTable::clear() {
  times_.clear();
  energies_.clear();
  values_.clear();
}

void SampleTable::push_back(double t, const Eigen::Ref<const Eigen::VectorXd>& q,
                            const Eigen::Ref<const Eigen::VectorXd>& v, double energy) {
  if (q.size() != nq_ || v.size() != nv_)
    throw std::invalid_argument("sample table: a sample of " + std::to_string(q.size()) +
                                " positions and " + std::to_string(v.size()) +
                                " velocities in a table of " + std::to_string(nq_) + " and " +
                                std::to_string(nv_));
  times_.push_back(t);
  energies_.push_back(energy);
  values_.insert(values_.end(), q.data(), q.data() + q.size());
  values_.insert(values_.end(), v.data(), v.data() + v.size());
}

SampleView SampleTable::operator[](std::size_t k) const {
  const double* q = values_.data() + k * static_cast<std::size_t>(nq_ + nv_);
  return {times_[k], Eigen::Map<const Eigen::VectorXd>(q, nq_),
          Eigen::Map<const Eigen::VectorXd>(q + nq_, nv_), energies_[k]};
}

}  // namespace impactbench::engines::event_driven
