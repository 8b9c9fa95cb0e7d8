// Counter-based random numbers (model.md §2): the k-th draw of a member is a pure function of
// (seed, member index, k), so results never depend on threads, lane width or scheduling.
#pragma once

#include <cstdint>

namespace rotorsweep::ensemble {

/// SplitMix64 finaliser (Steele, Lea, Flood, "Fast splittable pseudorandom number
/// generators", OOPSLA 2014): a bijective mix with full avalanche.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// The draws of one member: draw(k) is uniform on [0, 1) with 53 random bits.
class RandomStream {
 public:
  constexpr RandomStream(std::uint64_t seed, std::uint64_t member)
      : key_(mix64(mix64(seed ^ 0x9e3779b97f4a7c15ULL) + member)) {}

  constexpr double draw(std::uint64_t k) const {
    return double(mix64(key_ + 0x9e3779b97f4a7c15ULL * (k + 1)) >> 11) * 0x1.0p-53;
  }

 private:
  std::uint64_t key_;
};

}  // namespace rotorsweep::ensemble
