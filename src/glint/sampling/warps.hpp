// Warps: maps from the unit square [0,1)² onto disks, hemispheres, spheres and cones, each with the
// density (pdf) of the points it produces. They carry a sample pattern's stratification over to the
// domain, so a jittered film pattern gives a jittered lens or a jittered hemisphere.
//
// Directions are in a local frame about +z (turn them to world space with Frame::to_world); densities
// of directions are per unit solid angle, densities of disk points per unit area. Each map is
// area-preserving up to the constant factor its pdf states, except the cosine-power map, whose density
// the pdf function gives. Every map is continuous and monotone in each coordinate, so strata of the
// square stay compact regions of the target.
#pragma once

#include "glint/core/vec.hpp"

namespace glint {

// Shirley & Chiu's concentric map ("A Low Distortion Map Between Disk and Square", 1997): squares
// centred on (½, ½) go to circles, so strata keep their aspect ratio. Onto the unit disk; area-
// preserving (Jacobian π), so the density is uniform_disk_pdf().
Point2 square_to_disk_concentric(Point2 u);
double uniform_disk_pdf();  // 1/π per unit area

// Uniform over the hemisphere z ≥ 0.
Vec3 square_to_uniform_hemisphere(Point2 u);
double uniform_hemisphere_pdf();  // 1/(2π) per steradian, for z ≥ 0

// Density (e+1)/(2π) · cos^e θ about +z (θ the angle to +z): e = 0 is uniform, e = 1 cosine-weighted
// (Lambert), large e a Phong lobe. Precondition: exponent ≥ 0.
Vec3 square_to_cosine_power_hemisphere(Point2 u, double exponent);
// The density of `local` (a unit vector in the frame about +z); 0 below the horizon (z < 0).
double cosine_power_hemisphere_pdf(const Vec3& local, double exponent);

// Uniform over the unit sphere.
Vec3 square_to_uniform_sphere(Point2 u);
double uniform_sphere_pdf();  // 1/(4π) per steradian

// Uniform over the directions within angle θ_max of +z, given cos_max = cos θ_max (what a sphere light
// subtends seen from outside it). Precondition: −1 ≤ cos_max < 1.
Vec3 square_to_uniform_cone(Point2 u, double cos_max);
// 1/(2π (1 − cos_max)) per steradian, for directions inside the cone.
double uniform_cone_pdf(double cos_max);

}  // namespace glint
