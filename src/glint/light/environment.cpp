#include "glint/light/environment.hpp"

#include "glint/image/image_io.hpp"
#include "glint/params/build_context.hpp"
#include "glint/params/name_table.hpp"
#include "glint/sampling/warps.hpp"

namespace glint {

EnvironmentLight::EnvironmentLight(const Rgb& bottom, const Rgb& top) : bottom_(bottom), top_(top) {}

EnvironmentLight::EnvironmentLight(Image image, double rotation_degrees)
    : image_(std::move(image)),
      cos_rotation_(std::cos(radians(rotation_degrees))),
      sin_rotation_(std::sin(radians(rotation_degrees))) {
    const auto w = static_cast<size_t>(image_.width);
    const auto h = static_cast<size_t>(image_.height);
    std::vector<double> weights(w * h);
    for (size_t y = 0; y < h; ++y) {
        // sin θ at the row's centre: rows near the poles cover less solid angle.
        const double sin_theta = std::sin(kPi * (static_cast<double>(y) + 0.5) / static_cast<double>(h));
        for (size_t x = 0; x < w; ++x) {
            const float* p = image_.pixel(static_cast<int>(x), static_cast<int>(y));
            weights[y * w + x] = Rgb(p[0], p[1], p[2]).luminance() * sin_theta;
        }
    }
    distribution_ = std::make_unique<Distribution2D>(weights, w, h);
}

Point2 EnvironmentLight::direction_to_uv(const Vec3& dir) {
    double u = 0.5 + std::atan2(dir.x, -dir.z) / (2 * kPi);
    u = u - std::floor(u);
    return {u, std::acos(std::clamp(dir.y, -1.0, 1.0)) * kInvPi};
}

Vec3 EnvironmentLight::uv_to_direction(Point2 uv) {
    const double phi = 2 * kPi * (uv.x - 0.5);
    const double theta = kPi * uv.y;
    const double sin_theta = std::sin(theta);
    return {sin_theta * std::sin(phi), std::cos(theta), -sin_theta * std::cos(phi)};
}

Vec3 EnvironmentLight::to_map(const Vec3& v) const {
    return {cos_rotation_ * v.x - sin_rotation_ * v.z, v.y, sin_rotation_ * v.x + cos_rotation_ * v.z};
}
Vec3 EnvironmentLight::from_map(const Vec3& v) const {
    return {cos_rotation_ * v.x + sin_rotation_ * v.z, v.y, -sin_rotation_ * v.x + cos_rotation_ * v.z};
}

Rgb EnvironmentLight::escaped(const Vec3& dir) const {
    // `dir` is unit (Light::escaped), as every caller's is: a camera ray's (camera.hpp), a BSDF
    // sample's or a light sample's. Normalising it again cost a square root and a division on every
    // path that escapes (see PathIntegrator::shade).
    if (!distribution_) {
        const double t = 0.5 * (dir.y + 1);
        return (1 - t) * bottom_ + t * top_;
    }
    const Point2 uv = direction_to_uv(to_map(dir));
    const int x = std::min(image_.width - 1, static_cast<int>(uv.x * image_.width));
    const int y = std::min(image_.height - 1, static_cast<int>(uv.y * image_.height));
    const float* p = image_.pixel(x, y);
    return {p[0], p[1], p[2]};
}

std::optional<LightSample> EnvironmentLight::sample(const Hit& at, Point2 u) const {
    LightSample s;
    s.delta = false;
    s.infinite = true;
    if (!distribution_) {
        s.wi = square_to_uniform_sphere(u);
        s.pdf = uniform_sphere_pdf();
    } else {
        double pdf_uv = 0;
        const Point2 uv = distribution_->sample(u, pdf_uv);
        const double sin_theta = std::sin(kPi * uv.y);
        if (pdf_uv <= 0 || sin_theta <= 0) {
            return std::nullopt;
        }
        s.wi = from_map(uv_to_direction(uv));
        s.pdf = pdf_uv / (2 * kPi * kPi * sin_theta);  // Jacobian of (u, v) → (θ, φ) → ω
    }
    s.radiance = escaped(s.wi);
    s.position = at.point + s.wi;
    if (s.radiance.is_black()) {
        return std::nullopt;
    }
    return s;
}

double EnvironmentLight::pdf(const Hit&, const Vec3& wi, const Hit*) const {
    if (!distribution_) {
        return uniform_sphere_pdf();
    }
    const Point2 uv = direction_to_uv(to_map(wi));
    const double sin_theta = std::sin(kPi * uv.y);
    if (sin_theta <= 0) {
        return 0;
    }
    return distribution_->pdf(uv) / (2 * kPi * kPi * sin_theta);
}

std::unique_ptr<Light> EnvironmentLight::create(Params& params, const BuildContext& context) {
    const double scale = params.non_negative("scale", 1.0);
    if (params.has("image")) {
        if (params.has("radiance")) {
            params.fail("radiance", "an environment light takes either `radiance` or `image`, not both");
        }
        const std::filesystem::path file = context.resolve(params.string("image"));
        const double rotation = params.number("rotation", 0.0);
        const std::string ext = file.extension().string();
        const bool exr = ext == ".exr" || ext == ".EXR";
        if (!exr && ext != ".pfm" && ext != ".PFM") {
            params.fail(
                "image",
                std::string("environment images must be .exr or .pfm (linear radiance), not ").append(ext));
        }
        Image image;
        try {
            image = read_image(file);
        } catch (const std::runtime_error& e) {
            // The reader's message starts with the file's path.
            params.fail("image", std::string("cannot read environment image: ") + e.what());
        }
        for (float& v : image.rgb) {
            if (!std::isfinite(v) || v < 0) {
                params.fail("image", file.string() + " holds a negative or non-finite value");
            }
            v = static_cast<float>(v * scale);
        }
        return std::make_unique<EnvironmentLight>(std::move(image), rotation);
    }
    const Node* radiance = params.node("radiance");
    if (radiance && radiance->is_map()) {
        Params sky(*radiance, params.what() + ".radiance");
        enum class Sky { Gradient };  // the computed skies; one so far
        static const EnumTable<Sky> skies = {{"gradient", Sky::Gradient}};
        sky.enumeration("type", skies, Sky::Gradient);
        const Rgb bottom = sky.non_negative_color("bottom", Rgb(1.0));
        const Rgb top = sky.non_negative_color("top", Rgb(0.5, 0.7, 1.0));
        sky.finish();
        return std::make_unique<EnvironmentLight>(bottom * scale, top * scale);
    }
    Rgb constant(1.0);
    if (radiance) {
        constant = node_color(*radiance, params.what() + ".radiance");
        if (constant.r < 0 || constant.g < 0 || constant.b < 0) {
            params.fail("radiance", "environment radiance must not be negative");
        }
    }
    return std::make_unique<EnvironmentLight>(constant * scale, constant * scale);
}

}  // namespace glint
