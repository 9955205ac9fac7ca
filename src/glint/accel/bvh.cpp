#include "glint/accel/bvh.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cstring>
#include <limits>
#include <type_traits>

#include "glint/core/avx2_lanes.hpp"
#include "glint/geometry/mesh.hpp"
#include "glint/geometry/rectangle.hpp"
#include "glint/geometry/sphere.hpp"

namespace glint {

void BvhAccelerator::ShapeList::add(const Shape* shape, std::uint32_t index) {
    const auto* sphere = dynamic_cast<const Sphere*>(shape);
    // Before the padding, which stays at the end.
    spheres.insert(spheres.end() - kSpherePadding,
                   sphere != nullptr ? LeafSphere{sphere->center(), sphere->radius()} : LeafSphere{});
    sphere_count += sphere != nullptr ? 1 : 0;
    if (with_rectangles) {
        const std::size_t i = shapes.size();
        if (i % 4 == 0) {
            rectangles.emplace_back();
        }
        if (spheres[i].radius > 0) {
            rectangles.back().spheres |= 1u << (i % 4);
        }
        if (const auto* rectangle = dynamic_cast<const Rectangle*>(shape)) {
            RectangleBlock& block = rectangles.back();
            const int lane = static_cast<int>(i % 4);
            for (int axis = 0; axis < 3; ++axis) {
                block.corner[axis][lane] = rectangle->corner()[axis];
                block.normal[axis][lane] = rectangle->normal()[axis];
                block.dual1[axis][lane] = rectangle->dual1()[axis];
                block.dual2[axis][lane] = rectangle->dual2()[axis];
            }
            block.rectangles |= 1u << lane;
            ++rectangle_count;
        }
    }
    if (with_rectangles) {
        // Padded by a relative 1e-9 of its size and place, far beyond the rounding of any shape's own
        // test, so that the box test never rejects a ray the shape would hit.
        Bounds3 box = shape->bounds();
        if (box.is_finite()) {
            const Vec3 pad = 1e-9 * (box.extent() + abs(box.lo) + abs(box.hi)) + Vec3{1e-300, 1e-300, 1e-300};
            box = {box.lo - pad, box.hi + pad};
        } else {
            box = Bounds3::infinite();
        }
        culling_boxes.push_back(box);
        RectangleBlock& block = rectangles.back();
        const int lane = static_cast<int>(shapes.size() % 4);
        for (int axis = 0; axis < 3; ++axis) {
            block.box_lo[axis][lane] = box.lo[axis];
            block.box_hi[axis][lane] = box.hi[axis];
        }
    }
    shapes.push_back(shape);
    scene_index.push_back(index);
}

namespace {

// Whether the ray (with reciprocal direction inv) can meet `box` for t in [0, t_max]: the slab test,
// with the far t's widened by 1 + 2γ₃ for their rounding (pbrt-v4's Bounds3::IntersectP). A slab the
// ray runs along gives ±∞, or NaN on its plane, which the comparisons leave without effect.
// Without branches (the three axes' answers are combined at the end): a ray's box tests are as
// unpredictable as its direction.
inline bool ray_may_meet(const Bounds3& box, const Ray& ray, const Vec3& inv, double t_max) {
    constexpr double kWiden = 1 + 6 * std::numeric_limits<double>::epsilon();
    double t0 = 0, t1 = t_max;
    for (int axis = 0; axis < 3; ++axis) {
        const double a = (box.lo[axis] - ray.origin[axis]) * inv[axis];
        const double b = (box.hi[axis] - ray.origin[axis]) * inv[axis];
        // Ordered as `if (a > b) swap`: a NaN (0 · ∞, the ray on a slab's plane and along it) stays
        // where it was and then compares false, so it narrows neither end.
        const double near = a > b ? b : a;
        const double far = (a > b ? a : b) * kWiden;
        t0 = near > t0 ? near : t0;
        t1 = far < t1 ? far : t1;
    }
    return t0 <= t1;
}

// Four at a time pays for the flat list only, and only from three spheres and rectangles. Measured
// (user time, medians of 5): smallpt's nine spheres render 11–13 % faster, the Cornell box of RTIOW
// book 2 (six rectangles, two instanced boxes) 5 %; in tree leaves (at most 4 shapes, often 1 or 2)
// it gained nothing (RTIOW's final scene: +6 % time from one entry, +1 % from two, +0.4 % from three;
// the accelerator benchmark's 100 k spheres within ±3 %; leaves laid out as blocks of four, field by
// field, without the transpose: +6 % time when every leaf went four at a time, ±0 from three entries),
// so leaves stay one at a time. A list of other shapes gains nothing from it either: the Cornell box's
// quads and boxes spent 8 % of the render's instructions on sphere lanes that held no sphere.
constexpr std::uint32_t kFewestSpheresForFour = 3;

#ifdef GLINT_BVH_HAVE_AVX2_PATH
// What test_group finds for a group of four entries of a list against one ray (sphere and rectangle
// lanes tested at once, the other shapes left to their own tests).
struct SphereLanes {
    alignas(32) double t[4];
    // A rectangle lane's hit point and (a, b), as Rectangle::solve finds them: read only for rectangle
    // lanes that are hit, so that the nearest one's Hit is filled without solving again.
    alignas(32) double point[3][4];
    alignas(32) double ab[2][4];
    unsigned hit;    // sphere (and rectangle) lanes hit with t in (0, t_limit)
    unsigned other;  // lanes of other shapes whose culling box the ray may meet
};

using namespace avx2;  // the lane arithmetic of the sphere tests below

// Four sphere–ray pairs at once, one in each lane: the ray origin's offset from the centre (oc), the
// direction d with a = |d|² and 1/a, and the radius. sphere_hit_t (geometry/sphere.hpp) in each lane,
// operation for operation in the same order, for lanes that are `active` (all bits set): no FMA (the
// build has -ffp-contract=off and no FMA intrinsic is used outside the wide BVH's node test), and sqrt
// and division are correctly rounded in both, so each lane's t is the very double the scalar function
// computes. Returns the lanes hit with t in (0, t_limit) and their t in `t` (the other lanes' t are not
// to be read). Both tests below call it: four spheres against one ray (the flat list) and one sphere
// against four rays (a packet's leaves).
struct SphereRayLanes {
    __m256d ocx, ocy, ocz, dx, dy, dz, a, inverse_a, radius;
};
__attribute__((target("avx2"), always_inline)) inline __m256d sphere_hit_lanes(const SphereRayLanes& in,
                                                                               __m256d active,
                                                                               __m256d t_limit, __m256d& t) {
    // sphere_roots, line for line.
    const __m256d h = dot3(in.dx, in.dy, in.dz, in.ocx, in.ocy, in.ocz);
    const __m256d radius2 = mul(in.radius, in.radius);
    const __m256d c = sub(dot3(in.ocx, in.ocy, in.ocz, in.ocx, in.ocy, in.ocz), radius2);
    const __m256d h_over_a = mul(h, in.inverse_a);
    const __m256d lx = sub(in.ocx, mul(in.dx, h_over_a));
    const __m256d ly = sub(in.ocy, mul(in.dy, h_over_a));
    const __m256d lz = sub(in.ocz, mul(in.dz, h_over_a));
    const __m256d discriminant = mul(in.a, sub(radius2, dot3(lx, ly, lz, lx, ly, lz)));
    const __m256d zero = _mm256_setzero_pd();
    const __m256d not_missed = _mm256_cmp_pd(discriminant, zero, _CMP_NLT_UQ);  // !(Δ < 0)
    // Most groups miss every sphere, or leave it behind from outside (h > 0, c ≥ 0: both roots negative):
    // skip the square root and the divisions then, as the scalar code returns early.
    const __m256d left_behind =
        _mm256_and_pd(_mm256_cmp_pd(h, zero, _CMP_GT_OQ), _mm256_cmp_pd(c, zero, _CMP_GE_OQ));
    const __m256d candidate = _mm256_andnot_pd(left_behind, _mm256_and_pd(not_missed, active));
    if (_mm256_movemask_pd(candidate) == 0) {
        t = zero;
        return zero;
    }
    const __m256d sign_bit = _mm256_set1_pd(-0.0);
    // copysign(sqrt(Δ), h), then q = −(h + that): sign flips are exact, as in the scalar code.
    const __m256d root =
        _mm256_or_pd(_mm256_andnot_pd(sign_bit, _mm256_sqrt_pd(discriminant)), _mm256_and_pd(sign_bit, h));
    const __m256d q = _mm256_xor_pd(add(h, root), sign_bit);
    const __m256d near_root = mul(q, in.inverse_a);
    const __m256d far_root = _mm256_div_pd(c, q);
    const __m256d swapped = _mm256_cmp_pd(near_root, far_root, _CMP_GT_OQ);  // if (t0 > t1) swap
    const __m256d t0 = _mm256_blendv_pd(near_root, far_root, swapped);
    const __m256d t1 = _mm256_blendv_pd(far_root, near_root, swapped);
    // sphere_hit_t: t = t0 > 0 ? t0 : t1, hit when t > 0 && t < t_max. (A lane left behind has both
    // roots ≤ 0, so leaving it out of `candidate` changes no answer.)
    t = _mm256_blendv_pd(t1, t0, _mm256_cmp_pd(t0, zero, _CMP_GT_OQ));
    __m256d hit = _mm256_and_pd(candidate, _mm256_cmp_pd(q, zero, _CMP_NEQ_UQ));  // !(q == 0)
    hit = _mm256_and_pd(hit, _mm256_cmp_pd(t, zero, _CMP_GT_OQ));
    return _mm256_and_pd(hit, _mm256_cmp_pd(t, t_limit, _CMP_LT_OQ));
}

// Four consecutive sphere records (cx, cy, cz, r in rows) against a ray, laid out for sphere_hit_lanes
// (transposed into one register per field); `is_sphere` gets the lanes whose record is a sphere.
__attribute__((target("avx2"), always_inline)) inline SphereRayLanes sphere_records_against_ray(
    const double* records, const Ray& ray, double inverse_a, __m256d& is_sphere) {
    const __m256d r0 = _mm256_loadu_pd(records);
    const __m256d r1 = _mm256_loadu_pd(records + 4);
    const __m256d r2 = _mm256_loadu_pd(records + 8);
    const __m256d r3 = _mm256_loadu_pd(records + 12);
    const __m256d x0z0x1z1 = _mm256_unpacklo_pd(r0, r1);
    const __m256d y0r0y1r1 = _mm256_unpackhi_pd(r0, r1);
    const __m256d x2z2x3z3 = _mm256_unpacklo_pd(r2, r3);
    const __m256d y2r2y3r3 = _mm256_unpackhi_pd(r2, r3);
    const __m256d cx = _mm256_permute2f128_pd(x0z0x1z1, x2z2x3z3, 0x20);
    const __m256d cz = _mm256_permute2f128_pd(x0z0x1z1, x2z2x3z3, 0x31);
    const __m256d cy = _mm256_permute2f128_pd(y0r0y1r1, y2r2y3r3, 0x20);
    const __m256d radius = _mm256_permute2f128_pd(y0r0y1r1, y2r2y3r3, 0x31);
    is_sphere = _mm256_cmp_pd(radius, _mm256_setzero_pd(), _CMP_GT_OQ);
    return {sub(_mm256_set1_pd(ray.origin.x), cx),
            sub(_mm256_set1_pd(ray.origin.y), cy),
            sub(_mm256_set1_pd(ray.origin.z), cz),
            _mm256_set1_pd(ray.direction.x),
            _mm256_set1_pd(ray.direction.y),
            _mm256_set1_pd(ray.direction.z),
            _mm256_set1_pd(dot(ray.direction, ray.direction)),
            _mm256_set1_pd(inverse_a),
            radius};
}

// Four consecutive sphere records tested against a ray at once, for test_group. Fills `lanes`' hit and
// t in place: returned by value, the 224-byte record was copied twice a group (2.5 % of smallpt's
// instructions).
__attribute__((target("avx2"))) inline void test_sphere_lanes(const double* records, const Ray& ray,
                                                              double inverse_a, double t_limit,
                                                              SphereLanes& lanes) {
    __m256d is_sphere;
    const SphereRayLanes in = sphere_records_against_ray(records, ray, inverse_a, is_sphere);
    __m256d t;
    lanes.hit = static_cast<unsigned>(
        _mm256_movemask_pd(sphere_hit_lanes(in, is_sphere, _mm256_set1_pd(t_limit), t)));
    _mm256_store_pd(lanes.t, t);
}

// The lanes (all bits set) of a group of four entries from i that lie before `end`.
__attribute__((target("avx2"), always_inline)) inline __m256d lanes_before(std::uint32_t i,
                                                                           std::uint32_t end) {
    const auto left = static_cast<std::int64_t>(end - i);
    return _mm256_castsi256_pd(_mm256_cmpgt_epi64(_mm256_set1_epi64x(left), _mm256_setr_epi64x(0, 1, 2, 3)));
}

// A list of spheres alone (smallpt's room), entries [first, end): the nearest hit with t in
// (0, t_limit), the first in list order among equal t's, as the one-at-a-time loop finds it. Every
// group is tested before any answer is looked at, each lane keeping its nearest: the groups' square
// roots and divisions then overlap, where the walk of each group's lanes against the t_limit of the
// moment (test_range) made every group wait for the last one's branches, mispredicted as often as a
// ray's hits are unpredictable. A lane keeps the earlier of equal t's (a later group replaces it only
// when nearer), and the lanes' ties go to the lowest entry. Returns whether any sphere is hit, with its
// entry in `nearest` and its t in `nearest_t`.
__attribute__((target("avx2"))) inline bool nearest_sphere_of_list(const double* records, std::uint32_t first,
                                                                   std::uint32_t end, const Ray& ray,
                                                                   double inverse_a, double t_limit,
                                                                   std::uint32_t& nearest,
                                                                   double& nearest_t) {
    const __m256d limit = _mm256_set1_pd(t_limit);
    __m256d lane_t = limit;  // each lane's nearest t so far (t_limit: none)
    __m256i lane_entry = _mm256_setzero_si256();
    for (std::uint32_t i = first; i < end; i += 4) {
        __m256d is_sphere;
        const SphereRayLanes in = sphere_records_against_ray(records + 4 * i, ray, inverse_a, is_sphere);
        __m256d t;
        const __m256d hit = sphere_hit_lanes(in, _mm256_and_pd(is_sphere, lanes_before(i, end)), limit, t);
        const __m256d nearer = _mm256_and_pd(hit, _mm256_cmp_pd(t, lane_t, _CMP_LT_OQ));
        lane_t = _mm256_blendv_pd(lane_t, t, nearer);
        lane_entry = _mm256_castpd_si256(_mm256_blendv_pd(
            _mm256_castsi256_pd(lane_entry),
            _mm256_castsi256_pd(_mm256_add_epi64(_mm256_set1_epi64x(i), _mm256_setr_epi64x(0, 1, 2, 3))),
            nearer));
    }
    // The lanes' minimum (no lane holds a NaN: only hits' t's, which compared less, were taken).
    const __m256d halves = _mm256_min_pd(lane_t, _mm256_permute2f128_pd(lane_t, lane_t, 0x01));
    const __m256d smallest = _mm256_min_pd(halves, _mm256_permute_pd(halves, 0b0101));
    const auto at_smallest = static_cast<unsigned>(_mm256_movemask_pd(_mm256_and_pd(
        _mm256_cmp_pd(lane_t, smallest, _CMP_EQ_OQ), _mm256_cmp_pd(lane_t, limit, _CMP_LT_OQ))));
    if (at_smallest == 0) {
        return false;
    }
    alignas(32) std::int64_t entries[4];
    _mm256_store_si256(reinterpret_cast<__m256i*>(entries), lane_entry);
    auto lane = static_cast<unsigned>(__builtin_ctz(at_smallest));
    for (unsigned tied = at_smallest & (at_smallest - 1); tied != 0; tied &= tied - 1) {
        const auto other = static_cast<unsigned>(__builtin_ctz(tied));
        lane = entries[other] < entries[lane] ? other : lane;
    }
    nearest = static_cast<std::uint32_t>(entries[lane]);
    nearest_t = _mm256_cvtsd_f64(smallest);
    return true;
}

// Whether any sphere of entries [first, end) of a list of spheres alone is hit with t in (0, t_limit):
// every group tested before the answer is looked at, as nearest_sphere_of_list does.
__attribute__((target("avx2"))) inline bool any_sphere_of_list(const double* records, std::uint32_t first,
                                                               std::uint32_t end, const Ray& ray,
                                                               double inverse_a, double t_limit) {
    const __m256d limit = _mm256_set1_pd(t_limit);
    __m256d any_hit = _mm256_setzero_pd();
    for (std::uint32_t i = first; i < end; i += 4) {
        __m256d is_sphere;
        const SphereRayLanes in = sphere_records_against_ray(records + 4 * i, ray, inverse_a, is_sphere);
        __m256d t;
        any_hit = _mm256_or_pd(
            any_hit, sphere_hit_lanes(in, _mm256_and_pd(is_sphere, lanes_before(i, end)), limit, t));
    }
    return _mm256_movemask_pd(any_hit) != 0;
}

// A packet's four rays (field by field, lane k ray k) against one sphere at once, with t_max = ∞ in
// each lane: each lane's t is the very double the scalar function computes. Returns the lanes among
// `active` that are hit (all bits set), and their t in `t`.
struct PacketRayLanes {
    __m256d ox, oy, oz, dx, dy, dz, a, inverse_a;
};
__attribute__((target("avx2"))) inline __m256d test_sphere_rays(const double* record,
                                                                const PacketRayLanes& rays, __m256d active,
                                                                __m256d& t) {
    // The record: centre x, y, z and radius.
    const SphereRayLanes in{sub(rays.ox, _mm256_set1_pd(record[0])),
                            sub(rays.oy, _mm256_set1_pd(record[1])),
                            sub(rays.oz, _mm256_set1_pd(record[2])),
                            rays.dx,
                            rays.dy,
                            rays.dz,
                            rays.a,
                            rays.inverse_a,
                            _mm256_set1_pd(record[3])};
    return sphere_hit_lanes(in, active, _mm256_set1_pd(kInf), t);
}

// A packet's rays field by field, four to a register (lanes beyond the packet's rays hold zeros and are
// never read), with each ray's nearest hit so far.
struct alignas(32) PacketRays {
    static constexpr int kMax = WideBvh::kMaxPacket;
    double ox[kMax], oy[kMax], oz[kMax], dx[kMax], dy[kMax], dz[kMax], a[kMax], inverse_a[kMax];
    double nearest_t[kMax];      // each ray's t_max, lowered to its nearest hit
    std::int64_t nearest[kMax];  // the position of its nearest sphere in the list
};

// Spheres first … first + count − 1 of a list (`records`: its sphere records, 4 doubles each) tested
// against rays k … k + 3 of the packet, of which those in `group` (bit i for ray k + i) entered their
// leaf: each ray's nearest hit lowered as a one-at-a-time loop over the spheres would lower it. Returns
// the rays (bit i) whose nearest hit it lowered, and sets in `tied` those that met a sphere at their
// nearest t of the moment.
__attribute__((target("avx2"))) inline unsigned test_leaf_against_group(const double* records,
                                                                        std::uint32_t first,
                                                                        std::uint32_t count, PacketRays& p,
                                                                        int k, unsigned group,
                                                                        unsigned& tied) {
    const PacketRayLanes lanes{load(p.ox + k), load(p.oy + k), load(p.oz + k), load(p.dx + k),
                               load(p.dy + k), load(p.dz + k), load(p.a + k),  load(p.inverse_a + k)};
    const __m256d in_leaf = _mm256_castsi256_pd(_mm256_cmpgt_epi64(
        _mm256_and_si256(_mm256_set1_epi64x(group), _mm256_setr_epi64x(1, 2, 4, 8)), _mm256_setzero_si256()));
    __m256d nearest_t = load(p.nearest_t + k);
    __m256i nearest = _mm256_load_si256(reinterpret_cast<const __m256i*>(p.nearest + k));
    unsigned closer_lanes = 0;
    for (std::uint32_t i = 0; i < count; ++i) {
        __m256d t;
        const __m256d hit = test_sphere_rays(records + 4 * (first + i), lanes, in_leaf, t);
        if (_mm256_movemask_pd(hit) == 0) {
            continue;
        }
        const __m256d closer = _mm256_and_pd(hit, _mm256_cmp_pd(t, nearest_t, _CMP_LT_OQ));
        const __m256d same = _mm256_and_pd(hit, _mm256_cmp_pd(t, nearest_t, _CMP_EQ_OQ));
        nearest_t = _mm256_blendv_pd(nearest_t, t, closer);
        nearest = _mm256_castpd_si256(_mm256_blendv_pd(
            _mm256_castsi256_pd(nearest), _mm256_castsi256_pd(_mm256_set1_epi64x(first + i)), closer));
        closer_lanes |= static_cast<unsigned>(_mm256_movemask_pd(closer));
        tied |= static_cast<unsigned>(_mm256_movemask_pd(same));
    }
    _mm256_store_pd(p.nearest_t + k, nearest_t);
    _mm256_store_si256(reinterpret_cast<__m256i*>(p.nearest + k), nearest);
    return closer_lanes;
}

// Four rectangles of a block tested against a ray at once: Rectangle::solve in each lane, operation for
// operation in the same order (no FMA, as above), so each lane's t, point and (a, b) are the scalar
// function's. Returns the lanes hit with t in (0, t_limit); their t's replace those lanes of `t_lanes`,
// the others are kept. `point` and `ab` get every lane's values when any lane is hit.
// (Blended and stored whole: a masked store, whose result the lane walk then reads back, stalled
// the loads on AMD's Zen and made the Cornell box 4 % slower.)
template <class Block>
__attribute__((target("avx2"))) inline unsigned test_rectangle_lanes(const Block& block, const Ray& ray,
                                                                     double t_limit, double* t_lanes,
                                                                     double (&point)[3][4],
                                                                     double (&ab)[2][4]) {
    const __m256d nx = load(block.normal[0]), ny = load(block.normal[1]), nz = load(block.normal[2]);
    const __m256d cx = load(block.corner[0]), cy = load(block.corner[1]), cz = load(block.corner[2]);
    const __m256d ox = _mm256_set1_pd(ray.origin.x);
    const __m256d oy = _mm256_set1_pd(ray.origin.y);
    const __m256d oz = _mm256_set1_pd(ray.origin.z);
    const __m256d dx = _mm256_set1_pd(ray.direction.x);
    const __m256d dy = _mm256_set1_pd(ray.direction.y);
    const __m256d dz = _mm256_set1_pd(ray.direction.z);
    const __m256d zero = _mm256_setzero_pd();
    // plane_hit_t: a ray parallel to the plane (denominator 0) misses.
    const __m256d denominator = dot3(dx, dy, dz, nx, ny, nz);
    const __m256d t = _mm256_div_pd(dot3(sub(cx, ox), sub(cy, oy), sub(cz, oz), nx, ny, nz), denominator);
    // Hit when !(denominator == 0), t > 0 and !(t >= t_limit).
    __m256d hit = _mm256_cmp_pd(denominator, zero, _CMP_NEQ_UQ);
    hit = _mm256_and_pd(hit, _mm256_cmp_pd(t, zero, _CMP_GT_OQ));
    hit = _mm256_and_pd(hit, _mm256_cmp_pd(t, _mm256_set1_pd(t_limit), _CMP_NGE_UQ));
    if (_mm256_movemask_pd(hit) == 0) {
        return 0;
    }
    // point_on_plane: p = O + t D, moved along n onto the plane.
    __m256d px = add(ox, mul(t, dx));
    __m256d py = add(oy, mul(t, dy));
    __m256d pz = add(oz, mul(t, dz));
    const __m256d offset = dot3(sub(px, cx), sub(py, cy), sub(pz, cz), nx, ny, nz);
    px = sub(px, mul(nx, offset));
    py = sub(py, mul(ny, offset));
    pz = sub(pz, mul(nz, offset));
    const __m256d qx = sub(px, cx), qy = sub(py, cy), qz = sub(pz, cz);
    const __m256d a = dot3(qx, qy, qz, load(block.dual1[0]), load(block.dual1[1]), load(block.dual1[2]));
    const __m256d b = dot3(qx, qy, qz, load(block.dual2[0]), load(block.dual2[1]), load(block.dual2[2]));
    // Inside unless a < 0, a > 1, b < 0 or b > 1.
    const __m256d one = _mm256_set1_pd(1.0);
    hit = _mm256_and_pd(hit, _mm256_cmp_pd(a, zero, _CMP_NLT_UQ));
    hit = _mm256_and_pd(hit, _mm256_cmp_pd(a, one, _CMP_NGT_UQ));
    hit = _mm256_and_pd(hit, _mm256_cmp_pd(b, zero, _CMP_NLT_UQ));
    hit = _mm256_and_pd(hit, _mm256_cmp_pd(b, one, _CMP_NGT_UQ));
    _mm256_store_pd(t_lanes, _mm256_blendv_pd(_mm256_load_pd(t_lanes), t, hit));
    _mm256_store_pd(point[0], px);
    _mm256_store_pd(point[1], py);
    _mm256_store_pd(point[2], pz);
    _mm256_store_pd(ab[0], a);
    _mm256_store_pd(ab[1], b);
    return static_cast<unsigned>(_mm256_movemask_pd(hit));
}

// ray_may_meet for the four culling boxes of a block at once, operation for operation in the same
// order, so each lane's answer is the scalar function's. Returns the lanes whose box the ray may meet.
// (The Cornell box's two instanced boxes made two scalar box tests a ray and a shadow ray.)
template <class Block>
__attribute__((target("avx2"))) inline unsigned culling_box_lanes(const Block& block, const Ray& ray,
                                                                  const Vec3& inv, double t_max) {
    const __m256d widen = _mm256_set1_pd(1 + 6 * std::numeric_limits<double>::epsilon());
    __m256d t0 = _mm256_setzero_pd();
    __m256d t1 = _mm256_set1_pd(t_max);
    for (int axis = 0; axis < 3; ++axis) {
        const __m256d origin = _mm256_set1_pd(ray.origin[axis]);
        const __m256d inverse = _mm256_set1_pd(inv[axis]);
        const __m256d a = mul(sub(load(block.box_lo[axis]), origin), inverse);
        const __m256d b = mul(sub(load(block.box_hi[axis]), origin), inverse);
        // near = a > b ? b : a; far = (a > b ? a : b) · widen; a NaN compares false, as in the scalar test.
        const __m256d swapped = _mm256_cmp_pd(a, b, _CMP_GT_OQ);
        const __m256d near = _mm256_blendv_pd(a, b, swapped);
        const __m256d far = mul(_mm256_blendv_pd(b, a, swapped), widen);
        t0 = _mm256_blendv_pd(t0, near, _mm256_cmp_pd(near, t0, _CMP_GT_OQ));
        t1 = _mm256_blendv_pd(t1, far, _mm256_cmp_pd(far, t1, _CMP_LT_OQ));
    }
    return static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(t0, t1, _CMP_LE_OQ)));
}

// The group of (up to) four entries of a list with rectangles (the flat list, whose groups start at
// multiples of four) from i, in a range that ends before `end`: lanes past the end are dropped.
// Sphere and rectangle lanes are tested and reported together, and other lanes only when the ray may
// meet their culling box (the list's own shapes' tests then skip that box). Fills `lanes` in place.
// (A list of spheres alone is tested whole instead: nearest_sphere_of_list, any_sphere_of_list.)
template <class ShapeList>
__attribute__((target("avx2"))) inline void test_group(const ShapeList& list, std::uint32_t i,
                                                       std::uint32_t end, const Ray& ray,
                                                       const Vec3& inv_direction, double inverse_a,
                                                       double t_limit, SphereLanes& lanes) {
    assert(list.with_rectangles);
    const unsigned in_range = (1u << std::min<std::uint32_t>(end - i, 4)) - 1;
    const auto& block = list.rectangles[i / 4];
    if ((block.spheres & in_range) != 0) {
        test_sphere_lanes(reinterpret_cast<const double*>(list.spheres.data() + i), ray, inverse_a, t_limit,
                          lanes);
    } else {
        // t's of 0 in lanes that are not hit; the rectangles' points are left unset, not zeroed (that
        // alone cost more than solving the nearest rectangle again).
        _mm256_store_pd(lanes.t, _mm256_setzero_pd());
        lanes.hit = 0;
    }
    if ((block.rectangles & in_range) != 0) {
        lanes.hit |=
            test_rectangle_lanes(block, ray, t_limit, lanes.t, lanes.point, lanes.ab) & block.rectangles;
    }
    const unsigned inline_lanes = block.spheres | block.rectangles;
    lanes.hit &= in_range;
    lanes.other = ~inline_lanes & in_range;
    if (lanes.other != 0) {
        // Only the other shapes whose culling box the ray may meet are left for their own tests.
        lanes.other &= culling_box_lanes(block, ray, inv_direction, t_limit);
    }
}
#endif

// f(std::true_type{}) for a list of spheres only, else f(std::false_type{}): the choice made once a
// ray, between testing the list whole (nearest_sphere_of_list) and group by group (test_group).
// (Reading the flag once a group cost the Cornell box 0.5 % of its instructions; once a ray, 0.3 %.)
template <class ShapeList, class F>
inline bool with_spheres_only(const ShapeList& list, F&& f) {
    return list.spheres_only() ? f(std::true_type{}) : f(std::false_type{});
}

// Whether the flat list is tested four at a time (with AVX2): from kFewestSpheresForFour spheres and
// rectangles.
template <class ShapeList>
inline bool flat_list_four_at_a_time(const ShapeList& list) {
    return list.sphere_count + list.rectangle_count >= kFewestSpheresForFour;
}

}  // namespace

BvhAccelerator::BvhAccelerator(std::span<const Shape* const> shapes, std::size_t flat_max_shapes) {
    const auto start = std::chrono::steady_clock::now();
    direct_.with_rectangles = true;
    std::vector<Bounds3> boxes;
    std::vector<std::uint32_t> bounded;
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const Bounds3 b = shapes[i]->bounds();
        bounds_.grow(b);
        // The tree stores boxes in float: a box beyond float's range (a sphere of radius 1e116) would
        // saturate to infinity there, and a box infinite in every direction broke the traversal. Such
        // shapes are tested apart, as unbounded ones are.
        const double float_max = std::numeric_limits<float>::max();
        const bool fits_float =
            b.is_finite() && max_component(abs(b.lo)) <= float_max && max_component(abs(b.hi)) <= float_max;
        if (fits_float) {
            bounded_bounds_.grow(b);
            boxes.push_back(b);
            bounded.push_back(static_cast<std::uint32_t>(i));
        } else if (!b.empty()) {
            direct_.add(shapes[i], static_cast<std::uint32_t>(i));
        }
    }
    unbounded_count_ = direct_.size();
    // A lone bounded shape (a scene of one mesh) is never worth a tree of one leaf.
    if (boxes.size() <= std::max<std::size_t>(flat_max_shapes, 1)) {
        for (std::uint32_t i : bounded) {
            direct_.add(shapes[i], i);
        }
        boxes.clear();
        bounded.clear();
    }
    bvh_.build(boxes);
    for (std::uint32_t position : bvh_.primitive_order()) {
        leaves_.add(shapes[bounded[position]], bounded[position]);
    }
    // Packets only where they give every ray its own answer cheaply: a tree of spheres alone (tested
    // inline, ties seen) and nothing outside it. What they save is the single ray's branches, which
    // the AVX2 traversal pays.
    packet_traversal_ = direct_.size() == 0 && leaves_.size() > 0 && leaves_.spheres_only();
    // A lone mesh: its tree's root node culls what the flat list's box test would, and the list's set-up
    // (four divisions a ray, the box test in double, the lambdas' state) was a tenth of the bunny's
    // diffuse rays' time (bench/accel: 0.86 of Embree's speed before, 0.89-0.90 after).
    if (direct_.size() == 1 && leaves_.size() == 0 &&
        dynamic_cast<const Mesh*>(direct_.shapes[0]) != nullptr) {
        lone_mesh_ = direct_.shapes[0];
        lone_mesh_index_ = direct_.scene_index[0];
    }
    build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Vec3 BvhAccelerator::culling_inverse(const Ray& ray) const {
    // Three divisions a ray, spent only when the flat list has shapes other than spheres (smallpt's
    // nine spheres never read it).
    return direct_.spheres_only() ? Vec3{}
                                  : Vec3{1 / ray.direction.x, 1 / ray.direction.y, 1 / ray.direction.z};
}

// nearest_rectangle_point and _ab are read only when nearest_is_rectangle, which is set only where they
// are written; inlined into intersect_avx2, GCC cannot see that and warns. (Clang does not warn, and
// would reject the unknown warning group.)
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
template <bool kFourSpheres>
bool BvhAccelerator::intersect_with(const Ray& ray, double t_max, Hit& hit) const {
    // The nearest sphere so far (entry `nearest_sphere` of `nearest_list`), if it is nearer than every
    // other hit: its Hit is filled at the end.
    // A rectangle tested four at a time may be the nearest instead: its own intersect fills the Hit at
    // the end (it finds the same t).
    const ShapeList* nearest_list = nullptr;
    std::uint32_t nearest_sphere = 0;
    double nearest_sphere_t = 0;
    bool nearest_is_rectangle = false;
    // When nearest_is_rectangle: its point and (a, b) from the lanes. Plain doubles, left unset: a Vec3
    // zeroed for every ray made the tree's traversal, which never reads them, 3 % slower on RTIOW.
    double nearest_rectangle_point[3];
    double nearest_rectangle_ab[2];
    const auto take_sphere = [&](const ShapeList& list, std::uint32_t i, double t, double& t_limit) {
        t_limit = t;
        nearest_sphere_t = t;
        nearest_list = &list;
        nearest_sphere = i;
        if constexpr (kFourSpheres) {  // (only the four-at-a-time path meets rectangles inline)
            nearest_is_rectangle = false;
        }
    };
    const Vec3 inv_direction = culling_inverse(ray);
    const double inverse_a = inverse_length_squared(ray.direction);  // for every sphere test of the ray
    // box_tested: test_group has tested the culling box already.
    const auto test_other = [&](const ShapeList& list, std::uint32_t i, double& t_limit, bool box_tested) {
        if (!box_tested && !list.culling_boxes.empty() &&
            !ray_may_meet(list.culling_boxes[i], ray, inv_direction, t_limit)) {
            return false;
        }
        if (!list.shapes[i]->intersect(ray, t_limit, hit)) {
            return false;
        }
        t_limit = hit.t;
        hit.primitive = list.scene_index[i];
        nearest_list = nullptr;
        if constexpr (kFourSpheres) {
            nearest_is_rectangle = false;
        }
        return true;
    };
    // Entries [first, first + count) in order, each lowering t_limit to its hit: the first of equal
    // nearest t's wins.
    const auto test_range = [&](const ShapeList& list, std::uint32_t first, std::uint32_t count,
                                double& t_limit, auto four_at_a_time, auto spheres_only) {
        bool found = false;
#ifdef GLINT_BVH_HAVE_AVX2_PATH
        if (decltype(four_at_a_time)::value && count >= kFewestSpheresForFour) {
            const std::uint32_t end = first + count;
            if constexpr (decltype(spheres_only)::value) {
                std::uint32_t nearest = 0;
                double t = 0;
                if (!nearest_sphere_of_list(reinterpret_cast<const double*>(list.spheres.data()), first, end,
                                            ray, inverse_a, t_limit, nearest, t)) {
                    return false;
                }
                take_sphere(list, nearest, t, t_limit);
                return true;
            } else {
                SphereLanes lanes;
                for (std::uint32_t i = first; i < end; i += 4) {
                    test_group(list, i, end, ray, inv_direction, inverse_a, t_limit, lanes);
                    // The lanes' t's were found against the t_limit of the group's start; walking them in
                    // order against the t_limit of the moment gives what the one-at-a-time loop gives.
                    // (Boxes are culled against that t_limit too: a box culled against it is culled against
                    // the lower one of the moment, and one that passes may cost its shape's own test, which
                    // then misses. The same results, not always the same tests.)
                    for (unsigned todo = lanes.hit | lanes.other; todo != 0; todo &= todo - 1) {
                        const auto lane = static_cast<unsigned>(__builtin_ctz(todo));
                        if ((lanes.other >> lane) & 1) {
                            found |= test_other(list, i + lane, t_limit, true);
                        } else if (lanes.t[lane] < t_limit) {
                            take_sphere(list, i + lane, lanes.t[lane], t_limit);
                            nearest_is_rectangle = ((list.rectangles[i / 4].rectangles >> lane) & 1) != 0;
                            if (nearest_is_rectangle) {
                                for (int axis = 0; axis < 3; ++axis) {
                                    nearest_rectangle_point[axis] = lanes.point[axis][lane];
                                }
                                nearest_rectangle_ab[0] = lanes.ab[0][lane];
                                nearest_rectangle_ab[1] = lanes.ab[1][lane];
                            }
                            found = true;
                        }
                    }
                }
                return found;
            }
        }
#endif
        for (std::uint32_t i = first; i < first + count; ++i) {
            const LeafSphere& sphere = list.spheres[i];
            if (sphere.radius > 0) {
                double t = 0;
                if (sphere_hit_t(sphere.center, sphere.radius, ray, inverse_a, t_limit, t)) {
                    take_sphere(list, i, t, t_limit);
                    found = true;
                }
            } else {
                found |= test_other(list, i, t_limit, false);
            }
        }
        return found;
    };
    bool found = with_spheres_only(direct_, [&](auto spheres_only) {
        return test_range(direct_, 0, static_cast<std::uint32_t>(direct_.size()), t_max,
                          std::bool_constant<kFourSpheres>{}, spheres_only);
    });
    if (leaves_.size() > 0) {
        found |=
            bvh_.intersect(ray, t_max, [&](std::uint32_t first, std::uint32_t count, double& t_limit, auto) {
                return test_range(leaves_, first, count, t_limit, std::false_type{}, std::false_type{});
            });
    }
    if (kFourSpheres && nearest_is_rectangle) {
        static_cast<const Rectangle*>(nearest_list->shapes[nearest_sphere])
            ->fill_hit(nearest_sphere_t,
                       {nearest_rectangle_point[0], nearest_rectangle_point[1], nearest_rectangle_point[2]},
                       {nearest_rectangle_ab[0], nearest_rectangle_ab[1]}, hit);
        hit.primitive = nearest_list->scene_index[nearest_sphere];
    } else if (nearest_list != nullptr) {
        // The sphere's own intersect would find the same t; it fills the rest of the Hit from it.
        static_cast<const Sphere*>(nearest_list->shapes[nearest_sphere])
            ->fill_hit(ray, nearest_sphere_t, hit);
        hit.primitive = nearest_list->scene_index[nearest_sphere];
    }
    return found;
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

template <bool kFourSpheres>
bool BvhAccelerator::occluded_with(const Ray& ray, double t_max) const {
    const Vec3 inv_direction = culling_inverse(ray);
    const double inverse_a = inverse_length_squared(ray.direction);
    const auto other_occludes = [&](const ShapeList& list, std::uint32_t i, double t_limit, bool box_tested) {
        return (box_tested || list.culling_boxes.empty() ||
                ray_may_meet(list.culling_boxes[i], ray, inv_direction, t_limit)) &&
               list.shapes[i]->occluded(ray, t_limit);
    };
    const auto range_occludes = [&](const ShapeList& list, std::uint32_t first, std::uint32_t count,
                                    double t_limit, auto four_at_a_time, auto spheres_only) {
#ifdef GLINT_BVH_HAVE_AVX2_PATH
        if (decltype(four_at_a_time)::value && count >= kFewestSpheresForFour) {
            const std::uint32_t end = first + count;
            if constexpr (decltype(spheres_only)::value) {
                return any_sphere_of_list(reinterpret_cast<const double*>(list.spheres.data()), first, end,
                                          ray, inverse_a, t_limit);
            } else {
                SphereLanes lanes;
                for (std::uint32_t i = first; i < end; i += 4) {
                    test_group(list, i, end, ray, inv_direction, inverse_a, t_limit, lanes);
                    if (lanes.hit != 0) {
                        return true;
                    }
                    for (unsigned others = lanes.other; others != 0; others &= others - 1) {
                        if (other_occludes(list, i + static_cast<unsigned>(__builtin_ctz(others)), t_limit,
                                           true)) {
                            return true;
                        }
                    }
                }
                return false;
            }
        }
#endif
        for (std::uint32_t i = first; i < first + count; ++i) {
            const LeafSphere& sphere = list.spheres[i];
            if (sphere.radius > 0 ? sphere_occludes(sphere.center, sphere.radius, ray, inverse_a, t_limit)
                                  : other_occludes(list, i, t_limit, false)) {
                return true;
            }
        }
        return false;
    };
    return with_spheres_only(direct_,
                             [&](auto spheres_only) {
                                 return range_occludes(direct_, 0, static_cast<std::uint32_t>(direct_.size()),
                                                       t_max, std::bool_constant<kFourSpheres>{},
                                                       spheres_only);
                             }) ||
           (leaves_.size() > 0 &&
            bvh_.occluded(ray, t_max,
                          [&](std::uint32_t first, std::uint32_t count, double t_limit, auto /*avx2*/) {
                              return range_occludes(leaves_, first, count, t_limit, std::false_type{},
                                                    std::false_type{});
                          }));
}

#ifdef GLINT_BVH_HAVE_AVX2_PATH
// Flattened: before, a ray went through intersect_with (compiled for the baseline CPU) and then called
// the traversal (compiled for AVX2 and FMA, so that it could not be inlined there), each with its own
// set-up, closures and register saves. One function instead: bench/ab.py, 0.973 of the time for RTIOW's
// final scene, 0.951 for the Cornell box, 0.977 for smallpt's scene. FMA does not change a bit: the
// build has -ffp-contract=off, and no FMA intrinsic is used outside the node test.
template <bool kFourSpheres>
__attribute__((target("avx2,fma"), flatten)) bool BvhAccelerator::intersect_avx2(const Ray& ray, double t_max,
                                                                                 Hit& hit) const {
    return intersect_with<kFourSpheres>(ray, t_max, hit);
}
template <bool kFourSpheres>
__attribute__((target("avx2,fma"), flatten)) bool BvhAccelerator::occluded_avx2(const Ray& ray,
                                                                                double t_max) const {
    return occluded_with<kFourSpheres>(ray, t_max);
}
#endif

// With AVX2 (the switch the tree's traversal uses, which tests force off to compare both paths): the
// flat list's spheres and rectangles four at a time when it has enough of them. Without: one at a time,
// compiled for the baseline CPU. The same bits either way.
bool BvhAccelerator::intersect(const Ray& ray, double t_max, Hit& hit) const {
    if (lone_mesh_ != nullptr) {
        if (!lone_mesh_->intersect(ray, t_max, hit)) {
            return false;
        }
        hit.primitive = lone_mesh_index_;
        return true;
    }
#ifdef GLINT_BVH_HAVE_AVX2_PATH
    if (WideBvh::uses_avx2()) {
        return flat_list_four_at_a_time(direct_) ? intersect_avx2<true>(ray, t_max, hit)
                                                 : intersect_avx2<false>(ray, t_max, hit);
    }
#endif
    return intersect_one_at_a_time(ray, t_max, hit);
}

__attribute__((noinline)) bool BvhAccelerator::intersect_one_at_a_time(const Ray& ray, double t_max,
                                                                       Hit& hit) const {
    return intersect_with<false>(ray, t_max, hit);
}

bool BvhAccelerator::traces_packets() const {
#ifdef GLINT_BVH_HAVE_AVX2_PATH
    return packet_traversal_ && WideBvh::uses_avx2();
#else
    return false;
#endif
}

void BvhAccelerator::intersect_packet(const Ray* const* rays, int n, double t_max, Hit* const* hits,
                                      bool* found) const {
#ifdef GLINT_BVH_HAVE_AVX2_PATH
    if (traces_packets()) {
        for (int first = 0; first < n; first += WideBvh::kMaxPacket) {
            const int count = std::min(n - first, WideBvh::kMaxPacket);
            intersect_packet_avx2(rays + first, count, t_max, hits + first, found + first);
        }
        return;
    }
#endif
    for (int k = 0; k < n; ++k) {
        found[k] = intersect(*rays[k], t_max, *hits[k]);
    }
}

#ifdef GLINT_BVH_HAVE_AVX2_PATH
// Compiled for AVX2 and flattened, as intersect_avx2 is: the traversal, the leaf tests and the node
// tests in one function.
__attribute__((target("avx2,fma"), flatten)) void BvhAccelerator::intersect_packet_avx2(
    const Ray* const* rays, int n, double t_max, Hit* const* hits, bool* found) const {
    constexpr int kMax = WideBvh::kMaxPacket;
    PacketRays p;
    std::memset(&p, 0, sizeof p);
    for (int k = 0; k < n; ++k) {
        const Ray& ray = *rays[k];
        p.ox[k] = ray.origin.x;
        p.oy[k] = ray.origin.y;
        p.oz[k] = ray.origin.z;
        p.dx[k] = ray.direction.x;
        p.dy[k] = ray.direction.y;
        p.dz[k] = ray.direction.z;
        p.a[k] = dot(ray.direction, ray.direction);
        p.inverse_a[k] = inverse_length_squared(ray.direction);
        p.nearest_t[k] = t_max;
    }
    unsigned hit_rays = 0;
    // Rays that met two spheres at the same nearest t: which one their own traversal finds depends on
    // the order it visits them (the first wins), and the packet's order is not theirs. They are traced
    // again alone, so that a ray's hit never depends on the rays beside it.
    unsigned tied = 0;
    const auto leaf = [&](unsigned packet_rays, std::uint32_t first, std::uint32_t count) {
        unsigned lowered = 0;
        for (int g = 0; g < kMax / 4; ++g) {
            const unsigned group = (packet_rays >> (4 * g)) & 0xFu;
            if (group == 0) {
                continue;
            }
            const int k = 4 * g;
            unsigned tied_lanes = 0;
            const unsigned closer_lanes =
                test_leaf_against_group(&leaves_.spheres[0].center.x, first, count, p, k, group, tied_lanes);
            lowered |= closer_lanes << k;
            tied |= tied_lanes << k;
        }
        hit_rays |= lowered;
        return lowered;
    };
    bvh_.intersect_packet(rays, n, p.nearest_t, leaf);
    for (int k = 0; k < n; ++k) {
        const auto bit = 1u << k;
        if ((tied & bit) != 0) {
            found[k] = intersect(*rays[k], t_max, *hits[k]);
        } else if ((hit_rays & bit) != 0) {
            const auto position = static_cast<std::size_t>(p.nearest[k]);
            static_cast<const Sphere*>(leaves_.shapes[position])
                ->fill_hit(*rays[k], p.nearest_t[k], *hits[k]);
            hits[k]->primitive = leaves_.scene_index[position];
            found[k] = true;
        } else {
            found[k] = false;
        }
    }
}
#endif

bool BvhAccelerator::occluded(const Ray& ray, double t_max) const {
    if (lone_mesh_ != nullptr) {
        return lone_mesh_->occluded(ray, t_max);
    }
#ifdef GLINT_BVH_HAVE_AVX2_PATH
    if (WideBvh::uses_avx2()) {
        return flat_list_four_at_a_time(direct_) ? occluded_avx2<true>(ray, t_max)
                                                 : occluded_avx2<false>(ray, t_max);
    }
#endif
    return occluded_one_at_a_time(ray, t_max);
}

__attribute__((noinline)) bool BvhAccelerator::occluded_one_at_a_time(const Ray& ray, double t_max) const {
    return occluded_with<false>(ray, t_max);
}

}  // namespace glint
