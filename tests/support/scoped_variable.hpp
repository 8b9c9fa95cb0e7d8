// Test support: an environment variable set for the scope of an object (the GPU's launch:
// ROTORSWEEP_GPU_TEAM and the like, read at each run).
#pragma once

#include <cstdlib>
#include <string>

namespace rotorsweep::testing {

/// Sets an environment variable for the scope of the object.
class ScopedVariable {
 public:
  ScopedVariable(const char* name, const std::string& value) : name_(name) {
    ::setenv(name, value.c_str(), 1);
  }
  ScopedVariable(const ScopedVariable&) = delete;
  ScopedVariable& operator=(const ScopedVariable&) = delete;
  ~ScopedVariable() { ::unsetenv(name_); }

 private:
  const char* name_;
};

}  // namespace rotorsweep::testing
