// Arithmetic on the four double lanes of an AVX2 register, by short names, so that code written in lanes
// reads as its scalar namesake does: add(mul(a, b), c) for a * b + c. Only for functions compiled for
// AVX2 (target("avx2") or "avx2,fma"), which code reaches after asking cpu_has_avx2_and_fma. Named
// functions, not lambdas: GCC compiles a lambda inside such a function for the baseline CPU.
#pragma once

#include "glint/core/cpu.hpp"

#ifdef GLINT_HAVE_X86_SIMD
#include <immintrin.h>

namespace glint::avx2 {

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
// p in the lanes where `mask` is clear, q where it is set.
GLINT_AVX2_LANE_OP __m256d select(__m256d mask, __m256d p, __m256d q) {
    return _mm256_blendv_pd(p, q, mask);
}

#undef GLINT_AVX2_LANE_OP

}  // namespace glint::avx2

#endif
