// Counter-based random numbers (docs/model.md §2, §7): the k-th draw of a stream is a pure function
// of (seed, stream index, k), so results never depend on threads, lane width, scheduling or device.
#pragma once

#include <cstdint>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_math.hpp"

namespace rotorsweep::kernels {

/// SplitMix64 finaliser (Steele, Lea, Flood, "Fast splittable pseudorandom number
/// generators", OOPSLA 2014): a bijective mix with full avalanche.
ROTORSWEEP_HD constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// The draws of one member: draw(k) is uniform on [0, 1) with 53 random bits.
class RandomStream {
 public:
  ROTORSWEEP_HD constexpr RandomStream(std::uint64_t seed, std::uint64_t member)
      : key_(mix64(mix64(seed ^ 0x9e3779b97f4a7c15ULL) + member)) {}

  /// The stream with a given key (a device lane keeps only the key of its member's stream).
  ROTORSWEEP_HD static constexpr RandomStream from_key(std::uint64_t key) {
    RandomStream stream(0, 0);
    stream.key_ = key;
    return stream;
  }
  ROTORSWEEP_HD constexpr std::uint64_t key() const { return key_; }

  ROTORSWEEP_HD constexpr double draw(std::uint64_t k) const {
    return double(mix64(key_ + 0x9e3779b97f4a7c15ULL * (k + 1)) >> 11) * 0x1.0p-53;
  }

  /// A standard normal number from draws 2k and 2k + 1 (Box–Muller, cosine branch), computed with
  /// the portable lane functions so that every lane type and device gives the same bits.
  ROTORSWEEP_HD double normal(std::uint64_t k) const {
    const double u1 = draw(2 * k), u2 = draw(2 * k + 1);
    double s = 0, c = 0;
    lane_sincos(6.283185307179586 * u2, s, c);
    return lane_sqrt(-2.0 * lane_log(1.0 - u1)) * c;
  }

 private:
  std::uint64_t key_;
};

}  // namespace rotorsweep::kernels
