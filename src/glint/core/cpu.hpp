// What the CPU the program runs on can do. Code compiled both for AVX2 and FMA and for the baseline
// (the BVH's traversal, sobol's camera points a pixel's samples at a time) chooses its path by this,
// so one binary runs on any x86-64 and uses the wider instructions where they exist.
#pragma once

#if defined(__x86_64__) || defined(__i386__)
#define GLINT_HAVE_X86_SIMD 1
#endif

namespace glint {

// Whether the CPU has AVX2 and FMA; asked of the CPU once, on the first call. Always false off x86.
bool cpu_has_avx2_and_fma();

}  // namespace glint
