#include "glint/render/aov.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "glint/geometry/hit.hpp"
#include "glint/params/diagnostics.hpp"
#include "glint/render/render.hpp"

namespace glint {

namespace {

// What one camera ray gives the albedo, normal and depth AOVs.
struct AovSample {
    Rgb albedo;
    Vec3 normal;
    double depth = 0;
    bool hit = false;  // the camera ray met a surface (depth is valid)
};

AovSample trace_aov_sample(const World& world, Ray ray, SampleStream& samples) {
    AovSample result;
    for (int bounce = 0; bounce <= kMaxSpecularBounces; ++bounce) {
        Hit hit;
        if (!world.intersect(ray, kInf, hit)) {
            return result;
        }
        if (bounce == 0) {
            result.hit = true;
            result.depth = hit.t * length(ray.direction);
        }
        const Material& material = world.material(hit);
        const Vec3 wo = normalize(-ray.direction);
        const Bsdf bsdf = material.bsdf(hit);
        const MaterialPoint& point = bsdf.point();
        // A surface with no diffuse part whose BSDF samples a delta lobe (mirror, smooth metal, smooth
        // glass) is looked through; a fuzzy metal's random "delta" directions are a glossy lobe.
        if (point.diffuse.is_black() && !material.random_delta_direction()) {
            const std::optional<BsdfSample> s = bsdf.sample(wo, samples.next_2d());
            if (s && s->delta) {
                ray = spawn_ray(hit, s->wi);
                continue;
            }
        }
        const Rgb reflectance = point.diffuse + point.specular;
        result.albedo = {std::min(reflectance.r, 1.0), std::min(reflectance.g, 1.0),
                         std::min(reflectance.b, 1.0)};
        result.normal = dot(hit.shading_normal, wo) < 0 ? -hit.shading_normal : hit.shading_normal;
        return result;
    }
    return result;  // still between mirrors: nothing to show
}

void put(float* to, const Rgb& c) {
    to[0] = static_cast<float>(c.r);
    to[1] = static_cast<float>(c.g);
    to[2] = static_cast<float>(c.b);
}

}  // namespace

namespace {

// The AOVs by name, in the order they are written, each with the flag of AovRequest it sets.
struct AovName {
    const char* name;
    bool AovRequest::*flag;
};
constexpr AovName kAovNames[] = {{"albedo", &AovRequest::albedo},
                                 {"normal", &AovRequest::normal},
                                 {"depth", &AovRequest::depth},
                                 {"spp", &AovRequest::spp},
                                 {"variance", &AovRequest::variance}};

}  // namespace

const std::vector<std::string>& aov_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> all;
        for (const AovName& aov : kAovNames) {
            all.emplace_back(aov.name);
        }
        return all;
    }();
    return names;
}

AovRequest parse_aov_list(const std::string& list) {
    AovRequest request;
    std::stringstream in(list);
    std::string name;
    while (std::getline(in, name, ',')) {
        const auto* aov = std::find_if(std::begin(kAovNames), std::end(kAovNames),
                                       [&](const AovName& a) { return name == a.name; });
        if (aov == std::end(kAovNames)) {
            throw std::invalid_argument(unknown_name_message("AOV", name, aov_names(), "AOVs"));
        }
        request.*(aov->flag) = true;
    }
    if (!request.any()) {
        throw std::invalid_argument("no AOV named in '" + list + "' (AOVs: " + join_words(aov_names()) + ")");
    }
    return request;
}

std::vector<ImageLayer> render_aovs(const World& world, const View& view, const Film& film,
                                    const PixelWindow& window, std::uint32_t samples_per_pixel,
                                    const AovRequest& request) {
    const int width = window.width(), height = window.height();
    ImageLayer albedo("albedo", {"R", "G", "B"}, width, height);
    ImageLayer normal("normal", {"X", "Y", "Z"}, width, height);
    ImageLayer depth("depth", {"Z"}, width, height);
    if (request.albedo || request.normal || request.depth) {
        const std::uint32_t samples = std::min(samples_per_pixel, kMaxAovSamples);
        // One task per row: each pixel is written by one task, its samples summed in order.
        tbb::parallel_for(0, height, [&](int row) {
            const int y = window.y0 + row;
            for (int x = window.x0; x < window.x1; ++x) {
                const PixelHashes pixel(SampleHashes::pixel_hash(
                    view.settings.seed, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)));
                Rgb albedo_sum;
                Vec3 normal_sum;
                double depth_sum = 0;
                std::uint32_t hits = 0;
                for (std::uint32_t s = 0; s < samples; ++s) {
                    const SampleHashes key(pixel, s);
                    const std::optional<Ray> ray = camera_ray(view, key, x, y);
                    if (!ray) {
                        continue;
                    }
                    SampleStream stream(*view.sampler, key, kFirstIntegratorDimension);
                    const AovSample a = trace_aov_sample(world, *ray, stream);
                    albedo_sum += a.albedo;
                    normal_sum += a.normal;
                    if (a.hit) {
                        depth_sum += a.depth;
                        ++hits;
                    }
                }
                const double n = std::max<std::uint32_t>(samples, 1);
                const int column = x - window.x0;
                put(albedo.pixel(column, row), albedo_sum / n);
                const Vec3 mean_normal = normal_sum / n;
                put(normal.pixel(column, row), Rgb(mean_normal.x, mean_normal.y, mean_normal.z));
                depth.pixel(column, row)[0] =
                    hits ? static_cast<float>(depth_sum / hits) : std::numeric_limits<float>::infinity();
            }
        });
    }
    std::vector<ImageLayer> layers;
    if (request.albedo) {
        layers.push_back(std::move(albedo));
    }
    if (request.normal) {
        layers.push_back(std::move(normal));
    }
    if (request.depth) {
        layers.push_back(std::move(depth));
    }
    if (request.spp) {
        ImageLayer& spp = layers.emplace_back("spp", std::vector<std::string>{"Y"}, width, height);
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                spp.pixel(x, y)[0] = static_cast<float>(film.sample_count(window.x0 + x, window.y0 + y));
            }
        }
    }
    if (request.variance) {
        ImageLayer& variance = layers.emplace_back("variance", std::vector<std::string>{"Y"}, width, height);
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                variance.pixel(x, y)[0] =
                    static_cast<float>(film.mean_variance(window.x0 + x, window.y0 + y));
            }
        }
    }
    return layers;
}

}  // namespace glint
