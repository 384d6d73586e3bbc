#pragma once
// The output samples of an event-driven run, stored flat: one array of times, one of energies,
// and one of values holding each sample's q and then its v. A sample made of two Eigen vectors
// cost two heap allocations, about a tenth of a bouncing ball's instructions per event at 100
// samples per second; the table grows geometrically and, reserved, not at all.
#include <cstddef>
#include <iterator>
#include <vector>

#include <Eigen/Core>

namespace impactbench::engines::event_driven {

/// One sample read in place: valid until its table is changed.
struct SampleView {
  double t;
  Eigen::Map<const Eigen::VectorXd> q;
  Eigen::Map<const Eigen::VectorXd> v;
  double energy;
};

class SampleTable {
 public:
  class const_iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = SampleView;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = SampleView;

    const_iterator(const SampleTable& table, std::size_t index) : table_(&table), index_(index) {}
    SampleView operator*() const { return (*table_)[index_]; }
    const_iterator& operator++() {
      ++index_;
      return *this;
    }
    bool operator==(const const_iterator& other) const { return index_ == other.index_; }
    bool operator!=(const const_iterator& other) const { return index_ != other.index_; }

   private:
    const SampleTable* table_;
    std::size_t index_;
  };

  /// Empties the table for samples of nq positions and nv velocities (≥ 0).
  void set_sizes(Eigen::Index nq, Eigen::Index nv);
  /// Room for `count` samples without another allocation.
  void reserve(std::size_t count);
  /// Empties the table; its sizes and storage stay.
  void clear();
  /// Appends a sample. Throws std::invalid_argument when q or v is not of the table's size.
  void push_back(double t, const Eigen::Ref<const Eigen::VectorXd>& q,
                 const Eigen::Ref<const Eigen::VectorXd>& v, double energy);

  std::size_t size() const { return times_.size(); }
  bool empty() const { return times_.empty(); }
  Eigen::Index position_size() const { return nq_; }
  Eigen::Index velocity_size() const { return nv_; }
  /// Sample k (< size()).
  SampleView operator[](std::size_t k) const;
  SampleView front() const { return (*this)[0]; }
  SampleView back() const { return (*this)[size() - 1]; }
  const_iterator begin() const { return {*this, 0}; }
  const_iterator end() const { return {*this, size()}; }

 private:
  Eigen::Index nq_ = 0;
  Eigen::Index nv_ = 0;
  std::vector<double> times_;
  std::vector<double> energies_;
  std::vector<double> values_;  // sample k: q at (nq + nv) k, then v
};

}  // namespace impactbench::engines::event_driven
