// Four triangles side by side (structure of arrays), for the mesh's leaves: the watertight test of
// triangle.hpp run on four triangles at once with AVX2, or one after the other without it.
//
// The AVX2 path does exactly the scalar test's operations in the same order (no fused multiply-add),
// so it finds exactly the hits the scalar test finds; the hit found is then redone by the scalar test
// for its barycentric coordinates, which makes the two paths give identical results bit for bit.
#pragma once

#include <cstdint>
#include <limits>
#include <type_traits>

#include "glint/geometry/triangle.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace glint {

// Left uninitialised by its default constructor (a mesh allocates millions and fills them in parallel):
// every lane is written, by set() or set_empty(), before use.
struct alignas(32) TriangleBlock {
    static constexpr int kLanes = 4;
    static constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();
    double p[3][3][kLanes];         // [vertex][axis][lane]; an empty lane is all zero (degenerate: never hit)
    std::uint32_t element[kLanes];  // the triangle's index in the mesh, or kEmpty

    Vec3 vertex(int v, int lane) const { return {p[v][0][lane], p[v][1][lane], p[v][2][lane]}; }
    void set(int lane, std::uint32_t index, const Vec3& v0, const Vec3& v1, const Vec3& v2) {
        const Vec3* vs[3] = {&v0, &v1, &v2};
        for (int v = 0; v < 3; ++v) {
            for (int a = 0; a < 3; ++a) {
                p[v][a][lane] = (*vs[v])[a];
            }
        }
        element[lane] = index;
    }
    void set_empty(int lane) {
        for (auto& vertex : p) {
            for (auto& axis : vertex) {
                axis[lane] = 0;
            }
        }
        element[lane] = kEmpty;
    }
};
static_assert(std::is_trivially_default_constructible_v<TriangleBlock>);

// The nearest lane hit with t in (0, t_max), or −1; fills `out` for it.
inline int intersect_block_scalar(const WatertightRay& ray, const TriangleBlock& block, double t_max,
                                  TriangleHit& out) {
    int nearest = -1;
    for (int lane = 0; lane < TriangleBlock::kLanes; ++lane) {
        if (intersect_triangle(ray, block.vertex(0, lane), block.vertex(1, lane), block.vertex(2, lane),
                               t_max, out)) {
            t_max = out.t;
            nearest = lane;
        }
    }
    return nearest;
}

#if defined(__x86_64__) || defined(__i386__)
// The same answer as intersect_block_scalar, four lanes at a time.
__attribute__((target("avx2"), always_inline)) inline int intersect_block_avx2(const WatertightRay& ray,
                                                                               const TriangleBlock& block,
                                                                               double t_max,
                                                                               TriangleHit& out) {
    const __m256d ox = _mm256_set1_pd(ray.origin_x);
    const __m256d oy = _mm256_set1_pd(ray.origin_y);
    const __m256d oz = _mm256_set1_pd(ray.origin_z);
    const __m256d sx = _mm256_set1_pd(ray.shear_x);
    const __m256d sy = _mm256_set1_pd(ray.shear_y);
    const __m256d sz = _mm256_set1_pd(ray.shear_z);
    __m256d px[3], py[3], pz[3];  // sheared vertices, and their scaled z
    for (int v = 0; v < 3; ++v) {
        const __m256d dx = _mm256_sub_pd(_mm256_load_pd(block.p[v][ray.kx]), ox);
        const __m256d dy = _mm256_sub_pd(_mm256_load_pd(block.p[v][ray.ky]), oy);
        const __m256d dz = _mm256_sub_pd(_mm256_load_pd(block.p[v][ray.kz]), oz);
        px[v] = _mm256_sub_pd(dx, _mm256_mul_pd(sx, dz));
        py[v] = _mm256_sub_pd(dy, _mm256_mul_pd(sy, dz));
        pz[v] = _mm256_mul_pd(sz, dz);
    }
    // u = cx·by − cy·bx, v = ax·cy − ay·cx, w = bx·ay − by·ax (a, b, c: vertices 0, 1, 2).
    const __m256d u = _mm256_sub_pd(_mm256_mul_pd(px[2], py[1]), _mm256_mul_pd(py[2], px[1]));
    const __m256d v = _mm256_sub_pd(_mm256_mul_pd(px[0], py[2]), _mm256_mul_pd(py[0], px[2]));
    const __m256d w = _mm256_sub_pd(_mm256_mul_pd(px[1], py[0]), _mm256_mul_pd(py[1], px[0]));
    const __m256d zero = _mm256_setzero_pd();
    const __m256d negative =
        _mm256_or_pd(_mm256_or_pd(_mm256_cmp_pd(u, zero, _CMP_LT_OQ), _mm256_cmp_pd(v, zero, _CMP_LT_OQ)),
                     _mm256_cmp_pd(w, zero, _CMP_LT_OQ));
    const __m256d positive =
        _mm256_or_pd(_mm256_or_pd(_mm256_cmp_pd(u, zero, _CMP_GT_OQ), _mm256_cmp_pd(v, zero, _CMP_GT_OQ)),
                     _mm256_cmp_pd(w, zero, _CMP_GT_OQ));
    const __m256d det = _mm256_add_pd(_mm256_add_pd(u, v), w);
    const __m256d t_scaled = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(u, pz[0]), _mm256_mul_pd(v, pz[1])),
                                           _mm256_mul_pd(w, pz[2]));
    // Flip both by det's sign (the scalar test negates them when det < 0).
    const __m256d sign = _mm256_and_pd(det, _mm256_set1_pd(-0.0));
    const __m256d det_abs = _mm256_xor_pd(det, sign);
    const __m256d t_abs = _mm256_xor_pd(t_scaled, sign);
    const __m256d limit = _mm256_set1_pd(t_max);
    __m256d ok = _mm256_andnot_pd(_mm256_and_pd(negative, positive), _mm256_cmp_pd(det, zero, _CMP_NEQ_OQ));
    ok = _mm256_and_pd(ok, _mm256_cmp_pd(t_abs, zero, _CMP_GT_OQ));
    ok = _mm256_and_pd(ok, _mm256_cmp_pd(t_abs, _mm256_mul_pd(limit, det_abs), _CMP_LT_OQ));
    int mask = _mm256_movemask_pd(ok);
    if (mask == 0) {
        return -1;
    }
    const __m256d t = _mm256_mul_pd(t_abs, _mm256_div_pd(_mm256_set1_pd(1.0), det_abs));
    ok = _mm256_and_pd(
        ok, _mm256_and_pd(_mm256_cmp_pd(t, zero, _CMP_GT_OQ), _mm256_cmp_pd(t, limit, _CMP_LT_OQ)));
    mask = _mm256_movemask_pd(ok);
    if (mask == 0) {
        return -1;
    }
    alignas(32) double ts[4];
    _mm256_store_pd(ts, t);
    int nearest = -1;
    double nearest_t = t_max;
    for (int lane = 0; lane < 4; ++lane) {
        if ((mask >> lane & 1) != 0 && ts[lane] < nearest_t) {
            nearest_t = ts[lane];
            nearest = lane;
        }
    }
    // The scalar test gives the same t and the barycentric coordinates.
    if (!intersect_triangle(ray, block.vertex(0, nearest), block.vertex(1, nearest), block.vertex(2, nearest),
                            t_max, out)) {
        return -1;  // cannot happen: the same operations in the same order
    }
    return nearest;
}
#endif

}  // namespace glint
