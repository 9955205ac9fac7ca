// Checks every shape's tests share: area sampling against the surface, the sampled normal against
// intersect(), the same hits at any scale, and no self-intersection ("acne") of rays leaving a hit.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <memory>

#include "glint/core/hash.hpp"
#include "glint/geometry/hit.hpp"
#include "glint/geometry/shape.hpp"
#include "glint/scene/scene_desc.hpp"

namespace glint::testing {

// A deterministic uniform number: the hash of (test seed, index, dimension).
inline double uniform(std::uint64_t seed, std::uint32_t index, std::uint32_t dimension) {
    return SampleKey{seed, index, 0, 0}.uniform(dimension);
}

// A uniformly distributed unit vector.
inline Vec3 random_direction(std::uint64_t seed, std::uint32_t index) {
    const double z = 1 - 2 * uniform(seed, index, 0);
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    const double phi = 2 * kPi * uniform(seed, index, 1);
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// A uniform point of the box.
inline Vec3 random_point_in(const Bounds3& box, std::uint64_t seed, std::uint32_t index) {
    const Vec3 e = box.extent();
    return box.lo +
           Vec3{e.x * uniform(seed, index, 2), e.y * uniform(seed, index, 3), e.z * uniform(seed, index, 4)};
}

inline double distance(const Vec3& a, const Vec3& b) {
    return length(a - b);
}

// Samples the shape on the midpoints of an n × n grid of the unit square and checks each sample: pdf
// = 1 / area, unit normal, on the surface (|surface_distance| below tolerance · size), and that a ray
// shot at it from just off the surface along the normal hits it with that same normal. Returns the
// mean of the points, which for uniform-by-area sampling is the centroid.
inline Vec3 check_area_samples(const Shape& shape, int n,
                               const std::function<double(const Vec3&)>& surface_distance, double size) {
    EXPECT_GT(shape.area(), 0);
    Vec3 sum;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const Point2 u{(i + 0.5) / n, (j + 0.5) / n};
            const std::optional<ShapeSample> s = shape.sample_area(u);
            if (!s) {
                ADD_FAILURE() << "no sample at u = (" << u.x << ", " << u.y << ")";
                return {};
            }
            EXPECT_NEAR(s->pdf_area * shape.area(), 1.0, 1e-12);
            EXPECT_NEAR(length(s->normal), 1.0, 1e-12);
            EXPECT_NEAR(surface_distance(s->point), 0, 1e-12 * size) << "sample " << s->point;
            sum += s->point;
            if ((i * n + j) % 7 == 0) {
                const double offset = 1e-3 * size;
                Hit hit;
                const Ray ray{s->point + offset * s->normal, -s->normal};
                EXPECT_TRUE(shape.intersect(ray, kInf, hit)) << "sample " << s->point;
                EXPECT_NEAR(hit.t, offset, 1e-9 * size);
                EXPECT_NEAR(distance(hit.point, s->point), 0, 1e-9 * size);
                EXPECT_NEAR(distance(hit.normal, s->normal), 0, 1e-9) << "sample " << s->point;
            }
        }
    }
    return sum / (n * n);
}

// Random rays from around the shape towards points of its bounds: the shape built at `scale` (every
// length multiplied) must give the same hits at t·scale, with the hit point's error bound scaled too,
// and rays leaving each hit (spawn_ray, in random directions on both sides) must not find the same
// surface again within a distance that rounding could explain. `make(scale)` builds the shape.
inline void check_scale_independence(const std::function<std::unique_ptr<Shape>(double)>& make,
                                     int rays = 400) {
    const std::unique_ptr<Shape> unit = make(1.0);
    const Bounds3 box = unit->bounds();
    const double size = max_component(box.extent());
    for (const double scale : {1e-3, 1e4}) {
        const std::unique_ptr<Shape> scaled = make(scale);
        int hits = 0;
        for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(rays); ++i) {
            const Vec3 origin = box.center() + 2 * size * random_direction(11, i);
            const Vec3 target = random_point_in(box, 12, i);
            const Ray ray{origin, target - origin};
            const Ray scaled_ray{origin * scale, ray.direction * scale};
            Hit a, b;
            const bool hit_a = unit->intersect(ray, kInf, a);
            const bool hit_b = scaled->intersect(scaled_ray, kInf, b);
            ASSERT_EQ(hit_a, hit_b) << "ray " << i << " at scale " << scale;
            EXPECT_EQ(unit->occluded(ray, kInf), hit_a);
            EXPECT_EQ(scaled->occluded(scaled_ray, kInf), hit_b);
            if (!hit_a) {
                continue;
            }
            ++hits;
            EXPECT_NEAR(b.t, a.t, 1e-9 * a.t) << "ray " << i << " at scale " << scale;
            EXPECT_NEAR(distance(b.point / scale, a.point), 0, 1e-9 * size);
            EXPECT_NEAR(distance(b.normal, a.normal), 0, 1e-9);
            EXPECT_NEAR(b.error / scale, a.error, 1e-6 * a.error);
            EXPECT_GT(a.error, 0);
            // t_max is respected: a ray that stops just short of the hit finds nothing.
            EXPECT_FALSE(unit->occluded(ray, a.t * (1 - 1e-9)));
            Hit unused;
            EXPECT_FALSE(unit->intersect(ray, a.t * (1 - 1e-9), unused));
            for (const Hit* h : {&a, &b}) {
                const Shape& shape = h == &a ? *unit : *scaled;
                const double hit_scale = h == &a ? 1 : scale;
                for (std::uint32_t k = 0; k < 2; ++k) {
                    Vec3 dir = random_direction(13 + k, i);
                    if ((dot(dir, h->normal) > 0) != (k == 0)) {
                        dir = -dir;  // one ray leaves to each side of the surface
                    }
                    Hit again;
                    if (shape.intersect(spawn_ray(*h, dir), kInf, again)) {
                        EXPECT_GT(again.t * length(dir), 1e-6 * size * hit_scale)
                            << "acne: ray " << i << " at scale " << hit_scale << " re-hits " << again.point
                            << " leaving " << h->point;
                    }
                }
            }
        }
        EXPECT_GT(hits, rays / 10) << "too few rays hit the shape for the test to mean anything";
    }
}

// Random rays, from around the shape and from points inside its bounds, towards points of its bounds:
// every hit lies on the surface (|surface_distance| ≤ 1e-9 · size), has the unit normal
// expected_normal(point) gives, and occluded() agrees with intersect(). Returns the number of hits.
inline int check_random_hits(const Shape& shape, const std::function<double(const Vec3&)>& surface_distance,
                             const std::function<Vec3(const Vec3&)>& expected_normal, int rays = 500) {
    const Bounds3 box = shape.bounds();
    const double size = max_component(box.extent());
    int hits = 0;
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(rays); ++i) {
        const Vec3 origin =
            i % 2 ? box.center() + 2 * size * random_direction(21, i) : random_point_in(box, 22, i);
        const Vec3 target = random_point_in(box, 23, i);
        const Ray ray{origin, target - origin};
        Hit hit;
        const bool found = shape.intersect(ray, kInf, hit);
        EXPECT_EQ(shape.occluded(ray, kInf), found) << "ray " << i;
        if (!found) {
            continue;
        }
        ++hits;
        EXPECT_GT(hit.t, 0);
        EXPECT_NEAR(surface_distance(hit.point), 0, 1e-9 * size) << "ray " << i << " hits " << hit.point;
        EXPECT_NEAR(distance(hit.point, ray.at(hit.t)), 0, 1e-9 * size) << "ray " << i;
        EXPECT_NEAR(length(hit.normal), 1, 1e-12);
        EXPECT_NEAR(distance(hit.normal, expected_normal(hit.point)), 0, 1e-7)
            << "ray " << i << " hits " << hit.point << " with normal " << hit.normal;
        EXPECT_EQ(hit.shading_normal, hit.normal);
        const Point2 uv = surface_uv(hit);
        EXPECT_TRUE(uv.x >= 0 && uv.x <= 1 && uv.y >= 0 && uv.y <= 1) << "uv " << uv.x << ", " << uv.y;
    }
    EXPECT_GT(hits, rays / 10) << "too few rays hit the shape for the test to mean anything";
    return hits;
}

// Builds a scene from text and returns the error it raises ("" when it builds).
std::string scene_error(const std::string& yaml);

}  // namespace glint::testing
