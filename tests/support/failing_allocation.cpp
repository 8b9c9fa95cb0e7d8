// Test support, preloaded into the command line (LD_PRELOAD): posix_memalign, which the SIMD lanes'
// storage allocates through, fails every request above ROTORSWEEP_TEST_ALLOCATION_LIMIT bytes.
#include <cerrno>
#include <cstddef>

extern "C" {
char* getenv(const char* name) noexcept;
long long atoll(const char* text) noexcept;
void* __libc_memalign(std::size_t alignment, std::size_t size);

int posix_memalign(void** out, std::size_t alignment, std::size_t size) noexcept {
  static const long long limit = [] {
    const char* text = getenv("ROTORSWEEP_TEST_ALLOCATION_LIMIT");
    return text ? atoll(text) : 0;
  }();
  if (limit > 0 && size > std::size_t(limit)) return ENOMEM;
  void* p = __libc_memalign(alignment, size);
  if (!p) return ENOMEM;
  *out = p;
  return 0;
}
}
