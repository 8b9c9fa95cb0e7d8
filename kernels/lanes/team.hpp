// A team of threads that integrates one member together (docs/architecture.md "Teams"): its rows in
// contiguous blocks, one per rank, algorithms in phases separated by barriers, and sums over the team.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "kernels/lanes/host_device.hpp"

namespace rotorsweep::kernels {

/// The rows [begin, end) of rank `rank` in a team of `size` over n rows: contiguous blocks whose
/// lengths differ by at most one, the longer ones first.
struct TeamRows {
  std::size_t begin = 0, end = 0;
  ROTORSWEEP_HD std::size_t size() const { return end - begin; }
};
ROTORSWEEP_HD inline TeamRows team_rows(std::size_t n, std::size_t size, std::size_t rank) {
  const std::size_t base = n / size, longer = n % size;
  const std::size_t begin = rank * base + (rank < longer ? rank : longer);
  return {begin, begin + base + (rank < longer ? 1 : 0)};
}

/// A team on the host: each phase runs every rank's part in rank order, which is what a barrier
/// after the phase guarantees on a device. A team's sums add the ranks' values in the order of a
/// butterfly over a power-of-two team (v_i + v_{i+o} for o = size/2, size/4, …, 1), the order in
/// which a warp's shuffle reduction adds them, so that the host reproduces a device team's bits.
class HostTeam {
 public:
  explicit HostTeam(std::size_t size) : size_(size), values_(size) {}

  std::size_t size() const { return size_; }

  /// One phase: part(rank) for every rank; the next phase sees all of their writes.
  template <class Part>
  void each(Part&& part) const {
    for (std::size_t rank = 0; rank < size_; ++rank) part(rank);
  }

  /// A barrier: every rank's writes so far are seen by all (the host runs ranks in turn: nothing to do).
  void sync() const {}

  /// One rank's phase: part() on rank 0, which every rank then sees.
  template <class Part>
  void one(Part&& part) const {
    part();
  }

  /// Σ over ranks of value(rank), in butterfly order (a size that is not a power of two adds the
  /// ranks beyond the largest power of two first, rank by rank).
  template <class Value>
  double sum(Value&& value) {
    for (std::size_t rank = 0; rank < size_; ++rank) values_[rank] = value(rank);
    std::size_t width = 1;
    while (2 * width <= size_) width *= 2;
    for (std::size_t rank = width; rank < size_; ++rank) values_[rank - width] += values_[rank];
    for (std::size_t offset = width / 2; offset >= 1; offset /= 2)
      for (std::size_t rank = 0; rank < offset; ++rank) values_[rank] += values_[rank + offset];
    return values_[0];
  }

  /// max over ranks of value(rank).
  template <class Value>
  double max(Value&& value) const {
    double m = value(0);
    for (std::size_t rank = 1; rank < size_; ++rank) {
      const double v = value(rank);
      m = v > m ? v : m;
    }
    return m;
  }

  /// Whether every rank's test(rank) holds.
  template <class Test>
  bool all(Test&& test) const {
    bool all = true;
    for (std::size_t rank = 0; rank < size_; ++rank) all = all && test(rank);
    return all;
  }

 private:
  std::size_t size_;
  std::vector<double> values_;  ///< one value per rank while a sum reduces them
};

#if defined(__CUDACC__)
/// A team of `size` threads of one warp (a power of two up to 32; threads size·k … size·k + size − 1
/// of the warp), the device's counterpart of HostTeam: each thread runs its own rank's part of a
/// phase, phases end with __syncwarp over the team, votes are warp votes and sums a butterfly of
/// shuffles in HostTeam's order. Objects a team shares are built by every rank over the team's
/// shared storage, then sync().
class WarpTeam {
 public:
  __device__ explicit WarpTeam(unsigned size)
      : size_(size),
        rank_(threadIdx.x % size),
        mask_(size == 32 ? 0xffffffffu : ((1u << size) - 1u) << (threadIdx.x % 32u / size * size)) {}

  __device__ std::size_t size() const { return size_; }
  __device__ std::size_t rank() const { return rank_; }
  __device__ void sync() const { __syncwarp(mask_); }

  template <class Part>
  __device__ void each(Part&& part) const {
    part(std::size_t(rank_));
    __syncwarp(mask_);
  }
  template <class Part>
  __device__ void one(Part&& part) const {
    if (rank_ == 0) part();
    __syncwarp(mask_);
  }
  /// value() on rank 0, handed to every rank (a shuffle from the team's first thread).
  template <class Value>
  __device__ unsigned long long first(Value&& value) const {
    unsigned long long v = 0;
    if (rank_ == 0) v = value();
    return __shfl_sync(mask_, v, 0, size_);
  }
  template <class Value>
  __device__ double sum(Value&& value) const {
    double v = value(std::size_t(rank_));
    for (unsigned offset = size_ / 2; offset >= 1; offset /= 2) v += __shfl_xor_sync(mask_, v, offset, size_);
    return v;
  }
  template <class Value>
  __device__ double max(Value&& value) const {
    double v = value(std::size_t(rank_));
    for (unsigned offset = size_ / 2; offset >= 1; offset /= 2) {
      const double other = __shfl_xor_sync(mask_, v, offset, size_);
      v = other > v ? other : v;
    }
    return v;
  }
  template <class Test>
  __device__ bool all(Test&& test) const {
    return __all_sync(mask_, test(std::size_t(rank_)) ? 1 : 0) != 0;
  }

 private:
  unsigned size_, rank_, mask_;
};
#endif

}  // namespace rotorsweep::kernels
