// Noise {type: noise, scale, octaves, color_a, color_b}:
//   scale    features per scene unit (> 0), default 1;
//   octaves  number of summed frequencies, 1 … 16, default 6;
//   color_a, color_b  colours at turbulence 0 and 1, default 0.1 and 0.9.
#include "glint/texture/noise.hpp"

#include <algorithm>
#include <cmath>

#include "glint/core/hash.hpp"
#include "glint/params/params.hpp"

namespace glint {

namespace {

double fade(double t) {
    return t * t * t * (t * (t * 6 - 15) + 10);
}  // 6t⁵ − 15t⁴ + 10t³

// Dot product of the lattice gradient selected by `hash` with the offset (x, y, z): the 12 directions
// to the edges of a cube, (±1, ±1, 0) and permutations; 4 of them repeated to fill 16 slots.
double gradient_dot(std::uint8_t hash, double x, double y, double z) {
    switch (hash & 15) {
        case 0:
            return x + y;
        case 1:
            return -x + y;
        case 2:
            return x - y;
        case 3:
            return -x - y;
        case 4:
            return x + z;
        case 5:
            return -x + z;
        case 6:
            return x - z;
        case 7:
            return -x - z;
        case 8:
            return y + z;
        case 9:
            return -y + z;
        case 10:
            return y - z;
        case 11:
            return -y - z;
        case 12:
            return x + y;
        case 13:
            return -y + z;
        case 14:
            return -x + y;
        default:
            return -y - z;
    }
}

}  // namespace

PerlinNoise::PerlinNoise(std::uint32_t seed) {
    for (std::uint32_t i = 0; i < 256; ++i) {
        perm_[i] = perm_[i + 256] =
            static_cast<std::uint8_t>(permute(i, 256, static_cast<std::uint32_t>(hash_values(seed))));
    }
}

double PerlinNoise::noise(const Vec3& p) const {
    if (!is_finite(p)) {
        return 0;
    }
    const double fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
    // Lattice cell (mod 256; the permutation repeats with period 256) and the offset inside it.
    const auto cell = [](double f) { return static_cast<int>(f - 256.0 * std::floor(f / 256.0)) & 255; };
    const int X = cell(fx), Y = cell(fy), Z = cell(fz);
    const double x = p.x - fx, y = p.y - fy, z = p.z - fz;
    const double u = fade(x), v = fade(y), w = fade(z);
    const int A = perm_[X] + Y, AA = perm_[A] + Z, AB = perm_[A + 1] + Z;
    const int B = perm_[X + 1] + Y, BA = perm_[B] + Z, BB = perm_[B + 1] + Z;
    return lerp(
        w,
        lerp(v, lerp(u, gradient_dot(perm_[AA], x, y, z), gradient_dot(perm_[BA], x - 1, y, z)),
             lerp(u, gradient_dot(perm_[AB], x, y - 1, z), gradient_dot(perm_[BB], x - 1, y - 1, z))),
        lerp(v,
             lerp(u, gradient_dot(perm_[AA + 1], x, y, z - 1), gradient_dot(perm_[BA + 1], x - 1, y, z - 1)),
             lerp(u, gradient_dot(perm_[AB + 1], x, y - 1, z - 1),
                  gradient_dot(perm_[BB + 1], x - 1, y - 1, z - 1))));
}

double PerlinNoise::turbulence(const Vec3& p, int octaves) const {
    double sum = 0, weight = 1;
    Vec3 q = p;
    for (int i = 0; i < octaves; ++i) {
        sum += weight * std::abs(noise(q));
        weight *= 0.5;
        q *= 2;
    }
    return sum;
}

Rgb NoiseTexture::evaluate(const Hit& hit) const {
    const double t = std::min(1.0, noise_.turbulence(hit.point * scale_, octaves_));
    return (1 - t) * a_ + t * b_;
}

double NoiseTexture::min_value() const {
    return std::min({a_.r, a_.g, a_.b, b_.r, b_.g, b_.b});
}
double NoiseTexture::max_value() const {
    return std::max(a_.max_component(), b_.max_component());
}

std::shared_ptr<const Texture> NoiseTexture::create(Params& params, const BuildContext&) {
    const double scale = params.positive("scale", 1.0);
    const std::int64_t octaves = params.positive_integer("octaves", 6);
    if (octaves > 16) {
        params.fail("octaves",
                    params.what() + ".octaves must be 1 … 16 (finer octaves are below double precision)");
    }
    const Rgb a = params.color("color_a", Rgb(0.1));
    const Rgb b = params.color("color_b", Rgb(0.9));
    return std::make_shared<NoiseTexture>(scale, static_cast<int>(octaves), a, b);
}

}  // namespace glint
