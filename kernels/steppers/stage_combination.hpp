// Linear combinations of stage vectors whose weights a tableau gives at run time (the Rosenbrock
// steppers, Hairer & Wanner Eq. IV.7.25): out[k] = base(k) + Σ_t w_t s_t[k], terms in list order.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"

namespace rotorsweep::kernels {

/// Up to Max terms (w_t, s_t): a lane weight and a stage vector each.
template <class V, int Max>
struct StageTerms {
  static constexpr int max_terms = Max;
  int count = 0;
  V weight[Max];
  const V* vector[Max];
  ROTORSWEEP_HD void add(const V& w, const V* s) {
    weight[count] = w;
    vector[count] = s;
    ++count;
  }
};

/// combine_stages with exactly Count terms: each element's sum stays in a register while every term
/// is added, as an unrolled loop over compile-time coefficients would.
template <int Count, class V, int Max, class Base>
ROTORSWEEP_HD ROTORSWEEP_INLINE void combine_stages_of(const StageTerms<V, Max>& terms, Base&& base, V* out, std::size_t begin,
                                     std::size_t end) {
  V w[Count > 0 ? Count : 1];
  const V* s[Count > 0 ? Count : 1];
  for (int t = 0; t < Count; ++t) {
    w[t] = terms.weight[t];
    s[t] = terms.vector[t];
  }
  for (std::size_t k = begin; k < end; ++k) {
    V sum = base(k);
    for (int t = 0; t < Count; ++t) sum = sum + w[t] * s[t][k];
    out[k] = sum;
  }
}

/// out[k] = base(k) + Σ_t w_t s_t[k] for k in [begin, end), the terms added in order (the bits of
/// the same sum written out term by term).
template <class V, int Max, class Base>
ROTORSWEEP_HD ROTORSWEEP_INLINE void combine_stages(const StageTerms<V, Max>& terms, Base&& base, V* out, std::size_t begin,
                                  std::size_t end) {
  static_assert(Max >= 7 && Max <= 8, "combine_stages unrolls seven or eight terms");
  switch (terms.count) {
    case 0: return combine_stages_of<0>(terms, base, out, begin, end);
    case 1: return combine_stages_of<1>(terms, base, out, begin, end);
    case 2: return combine_stages_of<2>(terms, base, out, begin, end);
    case 3: return combine_stages_of<3>(terms, base, out, begin, end);
    case 4: return combine_stages_of<4>(terms, base, out, begin, end);
    case 5: return combine_stages_of<5>(terms, base, out, begin, end);
    case 6: return combine_stages_of<6>(terms, base, out, begin, end);
    case 7: return combine_stages_of<7>(terms, base, out, begin, end);
    default: return combine_stages_of<(Max < 8 ? Max : 8)>(terms, base, out, begin, end);
  }
}

}  // namespace rotorsweep::kernels
