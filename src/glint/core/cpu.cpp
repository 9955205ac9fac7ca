#include "glint/core/cpu.hpp"

namespace glint {

bool cpu_has_avx2_and_fma() {
#ifdef GLINT_HAVE_X86_SIMD
    static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    return avx2;
#else
    return false;
#endif
}

}  // namespace glint
