// Where the view sees each sphere light, learnt before the first sample (issue 13).
//
// A light partly buried in other geometry is mostly hidden: smallpt's light is a sphere of radius 600
// of which a cap about 36 units across shows below the ceiling, and sampling the whole cone it
// subtends sends ~95 % of the shadow rays into the ceiling. Before rendering, the path tracer follows a
// few thousand paths from the camera and samples each sphere light from their vertices, as next-event
// estimation would; the smallest cap of the sphere (about an axis through its centre) that holds every
// unoccluded sample, widened a little, is then sampled uniformly by area with probability kCapShare,
// and the cone as before with the rest. The mixture's density is positive wherever the cone's is, so
// the estimate stays unbiased whatever the learning found (a cap that misses part of what a point sees
// costs variance there, never bias), and it is known in closed form for multiple importance sampling.
// Lights that the view mostly sees already (half or more of the learning samples unoccluded), or whose
// seen part is not within a hemisphere, keep the cone alone.
//
// The learning is a pure function of the world, the camera and the film size (fixed hashes, one
// thread), so the image stays bit-identical for any thread count or tiling.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "glint/camera/camera.hpp"
#include "glint/core/frame.hpp"
#include "glint/light/light.hpp"

namespace glint {

struct World;
class AreaLight;
class Sphere;

// The part of a sphere light to favour: its points whose outward normal is within the angle
// acos(cos_max) of `frame.n`.
struct SphereCap {
    const AreaLight* light = nullptr;
    const Sphere* sphere = nullptr;
    Frame frame;             // n: the cap's axis, from the sphere's centre outwards
    double cos_max = 1;      // −1 < cos_max < 1
    double pdf_area = 0;     // 1 / the cap's area
    std::size_t seen = 0;    // learning samples that reached the light unoccluded
    std::size_t traced = 0;  // learning shadow rays
};

class LightVisibility {
  public:
    // The share of light samples drawn from the cap; the rest sample the whole cone. The cone's 10 %
    // bound the variance where the cap is wrong, and cost 1/0.9 in the variance where it is right.
    static constexpr double kCapShare = 0.9;

    LightVisibility() = default;
    // Follows paths through a grid of film points of `camera` (film size `film`), up to `max_depth`
    // vertices (at most 3), and samples every sphere light from each vertex with a non-delta BSDF.
    static LightVisibility learn(const World& world, const Camera& camera, FilmSize film, int max_depth);

    // Whether any light got a cap (otherwise sampling is exactly the lights' own).
    bool any() const;
    // The cap of world.lights[index], if it has one.
    const SphereCap* cap(std::size_t index) const {
        return index < caps_.size() && caps_[index] ? &*caps_[index] : nullptr;
    }

    // Light::sample and Light::pdf of world.lights[index], `light`, with its cap when it has one.
    std::optional<LightSample> sample(std::size_t index, const Light& light, const Hit& at, Point2 u) const;
    double pdf(std::size_t index, const Light& light, const Hit& at, const Vec3& wi,
               const Hit* on_light) const;

  private:
    std::vector<std::optional<SphereCap>> caps_;  // one per light of the world
};

}  // namespace glint
