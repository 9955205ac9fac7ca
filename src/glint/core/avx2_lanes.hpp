// Arithmetic on the four double lanes of an AVX2 register, by short names, so that code written in lanes
// reads as its scalar namesake does: add(mul(a, b), c) for a * b + c. Only for functions compiled for
// AVX2 (target("avx2") or "avx2,fma"), which code reaches after asking cpu_has_avx2_and_fma. Named
// functions, not lambdas: GCC compiles a lambda inside such a function for the baseline CPU.
#pragma once

#include "glint/core/cpu.hpp"

#ifdef GLINT_HAVE_X86_SIMD
#include <immintrin.h>

namespace glint::avx2 {

// For lane functions of one's own: compiled for AVX2 and FMA, and always inlined into their callers
// (which are too).
#define GLINT_AVX2_INLINE __attribute__((target("avx2,fma"), always_inline)) inline
#define GLINT_AVX2_LANE_OP __attribute__((target("avx2"), always_inline)) inline

GLINT_AVX2_LANE_OP __m256d splat(double x) {
    return _mm256_set1_pd(x);
}
GLINT_AVX2_LANE_OP __m256d load(const double* p) {
    return _mm256_load_pd(p);
}
GLINT_AVX2_LANE_OP __m256d add(__m256d p, __m256d q) {
    return _mm256_add_pd(p, q);
}
GLINT_AVX2_LANE_OP __m256d sub(__m256d p, __m256d q) {
    return _mm256_sub_pd(p, q);
}
GLINT_AVX2_LANE_OP __m256d mul(__m256d p, __m256d q) {
    return _mm256_mul_pd(p, q);
}
// dot(p, q) = p.x q.x + p.y q.y + p.z q.z per lane, added left to right as vec.hpp does.
GLINT_AVX2_LANE_OP __m256d dot3(__m256d px, __m256d py, __m256d pz, __m256d qx, __m256d qy, __m256d qz) {
    return add(add(mul(px, qx), mul(py, qy)), mul(pz, qz));
}
// As _mm256_blendv_pd: p in the lanes where `mask` is clear, q where it is set.
GLINT_AVX2_LANE_OP __m256d blend(__m256d p, __m256d q, __m256d mask) {
    return _mm256_blendv_pd(p, q, mask);
}

#undef GLINT_AVX2_LANE_OP

}  // namespace glint::avx2

#endif
