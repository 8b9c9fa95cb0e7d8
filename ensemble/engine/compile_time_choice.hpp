// Run-time choices turned into compile-time ones (one instantiation per value): a flag, for the
// choices that pay inside the hot loops (the lane type, the row model).
#pragma once

namespace rotorsweep::ensemble {

/// Calls f.template operator()<b>() with the run-time flag b as a compile-time constant.
template <class F>
decltype(auto) with_flag(bool b, F&& f) {
  return b ? f.template operator()<true>() : f.template operator()<false>();
}

}  // namespace rotorsweep::ensemble
