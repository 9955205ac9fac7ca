// Thin lens {type: thin-lens, eye, look_at, up, fov | view_distance + zoom, near, near_shape,
//            lens_radius | f_stop + focal_length, focus_distance}.
#include "glint/camera/thin_lens.hpp"

#include <cassert>

#include "glint/core/avx2_lanes.hpp"
#include "glint/core/cpu.hpp"
#include "glint/params/params.hpp"
#include "glint/sampling/warps.hpp"

namespace glint {

// thin_lens_rays_avx2 (below) repeats it in AVX2 lanes, operation for operation: change both together.
Ray ThinLensCamera::generate_ray(Point2 film, Point2 lens) const {
    // The pinhole ray's direction has component d along −w, so scaling it by z_f/d reaches the focus
    // plane: every ray of this film point, whatever its lens point, passes there.
    const Vec3 to_focus = view_plane_direction(view_, film_, film) * (focus_distance_ / view_.view_distance);
    const Point2 disk = square_to_disk_concentric(lens);
    const Vec3 lens_offset = lens_radius_ * (disk.x * view_.basis.u + disk.y * view_.basis.v);
    // The lens offset lies across w, so the direction still advances focus_distance along the view.
    return ray_from_near_surface(view_, view_.eye + lens_offset, to_focus - lens_offset, focus_distance_);
}

#ifdef GLINT_HAVE_X86_SIMD
namespace {
// ---- four rays at a time, in the double lanes of AVX2 registers -----------------------------------------
// Each step is its scalar namesake's (generate_ray above, view_plane_direction, square_to_disk_concentric,
// sincos_quarter_pi, ray_from_near_surface) lane by lane: the same IEEE operations in the same order, no
// fused multiply–add (the build has -ffp-contract=off), so the same bits (test
// ThinLens.RaysTogetherAreOneByOnesRays).
using namespace avx2;

struct Vec3Lanes {
    __m256d x, y, z;
};
// s · a + t · b per lane, for constant vectors a and b: (s a.x + t b.x, …), as Vec3's operators round.
GLINT_AVX2_INLINE Vec3Lanes combination(__m256d s, const Vec3& a, __m256d t, const Vec3& b) {
    return {add(mul(s, splat(a.x)), mul(t, splat(b.x))), add(mul(s, splat(a.y)), mul(t, splat(b.y))),
            add(mul(s, splat(a.z)), mul(t, splat(b.z)))};
}

GLINT_AVX2_INLINE void sincos_quarter_pi_lanes(__m256d x, __m256d& sin, __m256d& cos) {
    const __m256d y = mul(x, x);
    const __m256d y2 = mul(y, y);
    const __m256d y4 = mul(y2, y2);
    const __m256d sin_high = add(add(splat(1.0 / 362880), mul(y, splat(-1.0 / 39916800))),
                                 mul(y2, add(splat(1.0 / 6227020800), mul(y, splat(-1.0 / 1307674368000)))));
    const __m256d sin_tail =
        add(mul(y, splat(-1.0 / 6)),
            add(mul(y2, add(splat(1.0 / 120), mul(y, splat(-1.0 / 5040)))), mul(y4, sin_high)));
    const __m256d cos_high = add(add(add(splat(1.0 / 40320), mul(y, splat(-1.0 / 3628800))),
                                     mul(y2, add(splat(1.0 / 479001600), mul(y, splat(-1.0 / 87178291200))))),
                                 mul(y4, splat(1.0 / 20922789888000)));
    const __m256d cos_tail =
        add(mul(y, splat(-1.0 / 2)),
            add(mul(y2, add(splat(1.0 / 24), mul(y, splat(-1.0 / 720)))), mul(y4, cos_high)));
    sin = mul(x, add(splat(1), sin_tail));
    cos = add(splat(1), cos_tail);
}

// square_to_disk_concentric: its two cases chosen per lane by blends, with one division (of the chosen
// operands), and its centre (a = b = 0, where the division gives NaN) set to 0 by a mask.
GLINT_AVX2_INLINE void disk_concentric_lanes(__m256d ux, __m256d uy, __m256d& x, __m256d& y) {
    const __m256d a = sub(mul(splat(2), ux), splat(1));
    const __m256d b = sub(mul(splat(2), uy), splat(1));
    const __m256d sign_bit = splat(-0.0);
    const __m256d a_wider =
        _mm256_cmp_pd(_mm256_andnot_pd(sign_bit, a), _mm256_andnot_pd(sign_bit, b), _CMP_GT_OQ);
    const __m256d scale = blend(b, a, a_wider);  // a where |a| > |b|, else b
    const __m256d ratio = _mm256_div_pd(blend(a, b, a_wider), scale);
    __m256d sin, cos;
    sincos_quarter_pi_lanes(mul(splat(kPi / 4), ratio), sin, cos);
    const __m256d centre = _mm256_and_pd(_mm256_cmp_pd(a, _mm256_setzero_pd(), _CMP_EQ_OQ),
                                         _mm256_cmp_pd(b, _mm256_setzero_pd(), _CMP_EQ_OQ));
    x = _mm256_andnot_pd(centre, mul(scale, blend(sin, cos, a_wider)));
    y = _mm256_andnot_pd(centre, mul(scale, blend(cos, sin, a_wider)));
}

// The rays of the largest multiple of four of the points; returns how many it made.
__attribute__((target("avx2,fma"))) std::size_t thin_lens_rays_avx2(const ViewParams& view, FilmSize size,
                                                                    double lens_radius, double focus_distance,
                                                                    std::span<const Point2> film,
                                                                    std::span<const Point2> lens,
                                                                    std::span<Ray> rays) {
    const CameraBasis& b = view.basis;
    const __m256d to_focus_scale = splat(focus_distance / view.view_distance);
    const Vec3 w_term = view.view_distance * b.w;
    const std::size_t end = rays.size() / 4 * 4;
    for (std::size_t i = 0; i < end; i += 4) {
        const __m256d film_x = _mm256_setr_pd(film[i].x, film[i + 1].x, film[i + 2].x, film[i + 3].x);
        const __m256d film_y = _mm256_setr_pd(film[i].y, film[i + 1].y, film[i + 2].y, film[i + 3].y);
        const __m256d lens_x = _mm256_setr_pd(lens[i].x, lens[i + 1].x, lens[i + 2].x, lens[i + 3].x);
        const __m256d lens_y = _mm256_setr_pd(lens[i].y, lens[i + 1].y, lens[i + 2].y, lens[i + 3].y);
        // view_plane_direction, then scaled to the focus plane.
        const __m256d x = mul(splat(view.pixel_size), sub(film_x, splat(0.5 * size.width)));
        const __m256d y = mul(splat(view.pixel_size), sub(splat(0.5 * size.height), film_y));
        const Vec3Lanes across = combination(x, b.u, y, b.v);
        const Vec3Lanes to_focus{mul(sub(across.x, splat(w_term.x)), to_focus_scale),
                                 mul(sub(across.y, splat(w_term.y)), to_focus_scale),
                                 mul(sub(across.z, splat(w_term.z)), to_focus_scale)};
        __m256d disk_x, disk_y;
        disk_concentric_lanes(lens_x, lens_y, disk_x, disk_y);
        const Vec3Lanes offset_direction = combination(disk_x, b.u, disk_y, b.v);
        const __m256d radius = splat(lens_radius);
        const Vec3Lanes offset{mul(offset_direction.x, radius), mul(offset_direction.y, radius),
                               mul(offset_direction.z, radius)};
        const Vec3Lanes origin{add(splat(view.eye.x), offset.x), add(splat(view.eye.y), offset.y),
                               add(splat(view.eye.z), offset.z)};
        const Vec3Lanes direction{sub(to_focus.x, offset.x), sub(to_focus.y, offset.y),
                                  sub(to_focus.z, offset.z)};
        // ray_from_near_surface: normalize (a reciprocal, then three multiplies), then the near surface.
        const __m256d length = _mm256_sqrt_pd(
            dot3(direction.x, direction.y, direction.z, direction.x, direction.y, direction.z));
        const __m256d inverse = _mm256_div_pd(splat(1.0), length);
        const Vec3Lanes unit{mul(direction.x, inverse), mul(direction.y, inverse), mul(direction.z, inverse)};
        Vec3Lanes start = origin;
        if (view.near != 0) {
            const bool sphere = view.near_shape == NearShape::Sphere;
            const __m256d step = splat(sphere ? view.near : view.near / focus_distance);
            const Vec3Lanes& along = sphere ? unit : direction;
            start = {add(origin.x, mul(along.x, step)), add(origin.y, mul(along.y, step)),
                     add(origin.z, mul(along.z, step))};
        }
        alignas(32) double out[6][4];
        _mm256_store_pd(out[0], start.x);
        _mm256_store_pd(out[1], start.y);
        _mm256_store_pd(out[2], start.z);
        _mm256_store_pd(out[3], unit.x);
        _mm256_store_pd(out[4], unit.y);
        _mm256_store_pd(out[5], unit.z);
        for (int lane = 0; lane < 4; ++lane) {
            rays[i + lane] = {{out[0][lane], out[1][lane], out[2][lane]},
                              {out[3][lane], out[4][lane], out[5][lane]}};
        }
    }
    return end;
}
}  // namespace
#endif

void ThinLensCamera::generate_rays(std::span<const Point2> film, std::span<const Point2> lens,
                                   std::span<Ray> rays) const {
    assert(film.size() == rays.size() && lens.size() == rays.size());
    std::size_t done = 0;
#ifdef GLINT_HAVE_X86_SIMD
    if (cpu_has_avx2_and_fma()) {
        done = thin_lens_rays_avx2(view_, film_, lens_radius_, focus_distance_, film, lens, rays);
    }
#endif
    for (; done < rays.size(); ++done) {
        rays[done] = generate_ray(film[done], lens[done]);
    }
}

std::unique_ptr<Camera> ThinLensCamera::create(Params& params, const BuildContext&, FilmSize film) {
    const ViewParams view = read_view_params(params, film);
    const bool has_radius = params.has("lens_radius");
    const bool has_f_stop = params.has("f_stop");
    const bool has_focal_length = params.has("focal_length");
    double lens_radius = 0;
    if (has_radius) {
        if (has_f_stop || has_focal_length) {
            params.fail(has_f_stop ? "f_stop" : "focal_length",
                        "thin-lens takes lens_radius, or f_stop with focal_length, not both");
        }
        lens_radius = params.non_negative("lens_radius", 0);
    } else if (has_f_stop || has_focal_length) {
        if (!has_f_stop || !has_focal_length) {
            params.fail(
                has_f_stop ? "f_stop" : "focal_length",
                "thin-lens f_stop and focal_length go together (lens_radius = focal_length / (2 f_stop))");
        }
        lens_radius = lens_radius_from_f_stop(params.positive("focal_length"), params.positive("f_stop"));
    } else {
        params.fail("thin-lens needs an aperture: lens_radius, or f_stop with focal_length");
    }
    const double focus_distance = params.positive("focus_distance", length(view.look_at - view.eye));
    if (has_focal_length && !(focus_distance > params.positive("focal_length"))) {
        params.fail(params.has("focus_distance") ? "focus_distance" : "focal_length",
                    "thin-lens focus_distance must exceed focal_length: a lens cannot focus nearer than f");
    }
    return std::make_unique<ThinLensCamera>(view, film, lens_radius, focus_distance);
}

}  // namespace glint
