#include "glint/integrator/light_visibility.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "glint/core/hash.hpp"
#include "glint/geometry/sphere.hpp"
#include "glint/integrator/direct_lighting.hpp"
#include "glint/light/area.hpp"
#include "glint/sampling/warps.hpp"
#include "glint/world/world.hpp"

namespace glint {

namespace {

// The learning: kGridColumns × kGridRows film points (pixel centres of a coarse grid, the lens at its
// centre), paths of at most kLearnDepth vertices, kSamplesPerVertex samples of each sphere light at
// each vertex. On smallpt's scene that is ~37 000 shadow rays (a few milliseconds, against seconds of
// render) and ~1 700 unoccluded samples to bound the cap.
constexpr int kGridColumns = 64;
constexpr int kGridRows = 48;
constexpr int kLearnDepth = 3;
constexpr int kSamplesPerVertex = 4;
// A cap needs this many unoccluded samples to be trusted, and is used only where the cone wastes at
// least half its samples (kMaxSeenFraction): a light the view mostly sees gains nothing from it.
constexpr std::size_t kMinSeen = 32;
constexpr double kMaxSeenFraction = 0.5;
// The cap is widened by this fraction of its angle (plus kCapMarginRadians): the learnt samples lie
// inside the seen part, whose rim they approach but do not reach.
constexpr double kCapMarginFraction = 0.05;
constexpr double kCapMarginRadians = 1e-4;
// The stream of the learning's random numbers (any constant: the learning only shapes the variance).
constexpr std::uint64_t kLearnSeed = 0x6c696768742d7669ull;

Point2 learn_sample(std::uint64_t path, int vertex, int dimension) {
    return unit_pair(hash_values(kLearnSeed, path, static_cast<std::uint64_t>(vertex),
                                 static_cast<std::uint64_t>(dimension)));
}

// The sphere of an area light whose shape is a sphere in world space (not under a transform).
const Sphere* sphere_of(const Light& light) {
    const auto* area = dynamic_cast<const AreaLight*>(&light);
    return area != nullptr ? dynamic_cast<const Sphere*>(&area->shape()) : nullptr;
}

// What the learning gathers for one sphere light: the unit normals of the points it saw.
struct Sightings {
    std::vector<Vec3> normals;
    std::size_t traced = 0;
};

std::optional<SphereCap> cap_from(const AreaLight& light, const Sphere& sphere, const Sightings& sightings) {
    const std::size_t seen = sightings.normals.size();
    if (seen < kMinSeen ||
        static_cast<double>(seen) >= kMaxSeenFraction * static_cast<double>(sightings.traced)) {
        return std::nullopt;
    }
    Vec3 sum;
    for (const Vec3& n : sightings.normals) {
        sum += n;
    }
    const double sum_length = length(sum);
    if (!(sum_length > 1e-3 * static_cast<double>(seen))) {
        return std::nullopt;  // seen all around: no cap about one axis is small
    }
    const Vec3 axis = sum / sum_length;
    double cos_min = 1;
    for (const Vec3& n : sightings.normals) {
        cos_min = std::min(cos_min, dot(axis, n));
    }
    const double angle =
        std::acos(std::clamp(cos_min, -1.0, 1.0)) * (1 + kCapMarginFraction) + kCapMarginRadians;
    if (angle >= kPi / 2) {
        return std::nullopt;  // more than a hemisphere: the cone already samples no more than that
    }
    SphereCap cap;
    cap.light = &light;
    cap.sphere = &sphere;
    cap.frame = Frame::from_normal(axis);
    cap.cos_max = std::cos(angle);
    cap.pdf_area = 1 / (2 * kPi * sqr(sphere.radius()) * (1 - cap.cos_max));
    cap.seen = seen;
    cap.traced = sightings.traced;
    return cap;
}

// The mixture's solid-angle density at `ref` of the direction wi, which meets the sphere first at
// `point` with outward unit normal `normal`. `area_to_solid_angle` is distance² / |cos θ| at the point,
// which turns the cap's density per unit area into one per steradian (0 when the point is seen
// edge-on: the cap then adds no density).
double cap_mixture_pdf(const SphereCap& cap, const Vec3& ref, const Vec3& wi, const Vec3& point,
                       const Vec3& normal, double area_to_solid_angle) {
    const double cone = cap.sphere->pdf_seen_from(ref, wi, point, normal);
    const double in_cap = dot(normal, cap.frame.n) >= cap.cos_max ? cap.pdf_area * area_to_solid_angle : 0;
    return LightVisibility::kCapShare * in_cap + (1 - LightVisibility::kCapShare) * cone;
}

// The same, the factor computed from wi (LightVisibility::pdf, and a sample of the cone).
double cap_mixture_pdf(const SphereCap& cap, const Vec3& ref, const Vec3& wi, const Vec3& point,
                       const Vec3& normal) {
    const double cos_light = std::abs(dot(wi, normal));
    return cap_mixture_pdf(cap, ref, wi, point, normal,
                           cos_light > 0 ? length_squared(point - ref) / cos_light : 0);
}

}  // namespace

LightVisibility LightVisibility::learn(const World& world, const Camera& camera, FilmSize film,
                                       int max_depth) {
    LightVisibility visibility;
    visibility.caps_.resize(world.lights.size());
    // The sphere lights: their index in world.lights and their sphere, found once.
    struct Candidate {
        std::size_t index;
        const Sphere* sphere;
    };
    std::vector<Candidate> candidates;
    for (std::size_t i = 0; i < world.lights.size(); ++i) {
        const Light& light = *world.lights[i];
        const Sphere* sphere = sphere_of(light);
        if (light.physical() && light.worth_sampling_in_paths() && sphere != nullptr) {
            candidates.push_back({i, sphere});
        }
    }
    if (candidates.empty() || film.width <= 0 || film.height <= 0) {
        return visibility;
    }
    std::vector<Sightings> sightings(world.lights.size());
    RayCounters unused;
    const int depth = std::min(max_depth, kLearnDepth);
    for (int row = 0; row < kGridRows; ++row) {
        for (int column = 0; column < kGridColumns; ++column) {
            const std::uint64_t path = static_cast<std::uint64_t>(row) * kGridColumns + column;
            const Point2 film_point{(column + 0.5) * film.width / kGridColumns,
                                    (row + 0.5) * film.height / kGridRows};
            Ray ray = camera.generate_ray(film_point, {0.5, 0.5});
            if (!sees_scene(ray)) {
                continue;
            }
            for (int vertex = 0; vertex < depth; ++vertex) {
                Hit hit;
                if (!world.intersect(ray, kInf, hit)) {
                    break;
                }
                const Vec3 wo = normalize(-ray.direction);
                const Bsdf bsdf = world.material(hit).bsdf(hit);
                const Hit at = facing(hit, wo);
                for (const auto& [light_index, sphere] : candidates) {
                    const Light& light = *world.lights[light_index];
                    const Vec3& center = sphere->center();
                    for (int k = 0; k < kSamplesPerVertex; ++k) {
                        const int dimension = 1 + static_cast<int>(light_index) * kSamplesPerVertex + k;
                        const std::optional<LightSample> ls =
                            light.sample(at, learn_sample(path, vertex, dimension));
                        if (!ls || ls->pdf <= 0 || dot(at.shading_normal, ls->wi) <= 0 ||
                            bsdf.evaluate(wo, ls->wi).is_black()) {
                            continue;  // no shadow ray would be traced for it
                        }
                        Sightings& s = sightings[light_index];
                        ++s.traced;
                        if (!shadowed(world, at, *ls, unused)) {
                            s.normals.push_back(normalize(ls->position - center));
                        }
                    }
                }
                const std::optional<BsdfSample> next = bsdf.sample(wo, learn_sample(path, vertex, 0));
                if (!next || next->pdf <= 0 || next->f.is_black()) {
                    break;
                }
                ray = spawn_ray(hit, next->wi);
            }
        }
    }
    for (const auto& [light_index, sphere] : candidates) {
        visibility.caps_[light_index] = cap_from(static_cast<const AreaLight&>(*world.lights[light_index]),
                                                 *sphere, sightings[light_index]);
    }
    return visibility;
}

bool LightVisibility::any() const {
    return std::any_of(caps_.begin(), caps_.end(), [](const auto& cap) { return cap.has_value(); });
}

std::optional<LightSample> LightVisibility::sample(std::size_t index, const Light& light, const Hit& at,
                                                   Point2 u) const {
    const SphereCap* cap = this->cap(index);
    if (cap == nullptr) {
        return light.sample(at, u);
    }
    // One sample of the mixture: the cap for u.x < kCapShare, the cone otherwise, each with u.x
    // stretched back to [0, 1) so that a stratified u stays stratified within each. (By a division:
    // the product by 1 / kCapShare, 0.992 of smallpt's time, within noise, takes the double just below
    // kCapShare to 1.)
    SeenSample seen;
    if (u.x < kCapShare) {
        const Vec3 normal = cap->frame.to_world(square_to_uniform_cone({u.x / kCapShare, u.y}, cap->cos_max));
        seen.point = cap->sphere->center() + cap->sphere->radius() * normal;
        seen.normal = normal;
        const Vec3 to_point = seen.point - at.point;
        const double d2 = length_squared(to_point);
        if (!(d2 >= std::numeric_limits<double>::min() && d2 <= std::numeric_limits<double>::max())) {
            return std::nullopt;  // at the point, or so near or far that 1/d² is not finite
        }
        // A point on the far side of the sphere gets no light through it: a one-sided emitter sends
        // none that way, and the shadow ray of a two-sided one meets the near side.
        // wi and d² / |cos θ| (= d³ / |n · (point − ref)|) from √(d²), 1/d² and one division side by
        // side, as seen_from (shape.hpp) does, rather than each waiting for the last. Written out, not
        // a call of seen_from with a density of 1 (the same bits): that took smallpt's scene 1.077 of
        // the time (bench/ab.py), with the SeenSample it returned copied through the stack.
        const double d = std::sqrt(d2);
        const double inverse_d2 = 1 / d2;
        const double projected = std::abs(dot(normal, to_point));  // d |cos θ|
        seen.wi = to_point * (d * inverse_d2);
        seen.pdf_solid_angle = cap_mixture_pdf(*cap, at.point, seen.wi, seen.point, seen.normal,
                                               projected > 0 ? d2 / projected * d : 0);
    } else {
        const std::optional<SeenSample> cone =
            cap->sphere->sample_seen_from(at.point, {(u.x - kCapShare) / (1 - kCapShare), u.y});
        if (!cone) {
            return std::nullopt;
        }
        seen = *cone;
        seen.pdf_solid_angle = cap_mixture_pdf(*cap, at.point, seen.wi, seen.point, seen.normal);
    }
    return cap->light->sample_of(seen);
}

double LightVisibility::pdf(std::size_t index, const Light& light, const Hit& at, const Vec3& wi,
                            const Hit* on_light) const {
    const SphereCap* cap = this->cap(index);
    if (cap == nullptr || on_light == nullptr) {
        return light.pdf(at, wi, on_light);
    }
    return cap_mixture_pdf(*cap, at.point, wi, on_light->point, on_light->normal);
}

}  // namespace glint
