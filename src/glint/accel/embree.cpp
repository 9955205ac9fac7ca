#ifdef GLINT_HAVE_EMBREE

#include "glint/accel/embree.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "glint/bvh/wide_bvh.hpp"
#include "glint/geometry/mesh.hpp"

namespace glint {
namespace {

// What the user-geometry callbacks need besides Embree's float ray: the double ray and where to put
// the nearest user-geometry hit. RTCIntersectContext must come first (Embree passes a pointer to it).
struct QueryContext {
    RTCIntersectContext base;
    const Ray* ray;
    Hit* hit;      // the nearest user-geometry hit so far (intersect only)
    double t_max;  // the caller's bound, in double
};

const QueryContext& query(RTCIntersectContext* context) {
    return *reinterpret_cast<QueryContext*>(context);
}

void shape_bounds(const RTCBoundsFunctionArguments* args) {
    const Bounds3 b = static_cast<const Shape*>(args->geometryUserPtr)->bounds();
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    // Round outwards, so the float box holds the double one.
    args->bounds_o->lower_x = std::nextafter(saturate_to_float(b.lo.x), -kInfinity);
    args->bounds_o->lower_y = std::nextafter(saturate_to_float(b.lo.y), -kInfinity);
    args->bounds_o->lower_z = std::nextafter(saturate_to_float(b.lo.z), -kInfinity);
    args->bounds_o->upper_x = std::nextafter(saturate_to_float(b.hi.x), kInfinity);
    args->bounds_o->upper_y = std::nextafter(saturate_to_float(b.hi.y), kInfinity);
    args->bounds_o->upper_z = std::nextafter(saturate_to_float(b.hi.z), kInfinity);
}

void shape_intersect(const RTCIntersectFunctionNArguments* args) {
    if (args->valid[0] == 0) {
        return;
    }
    auto* rayhit = reinterpret_cast<RTCRayHit*>(args->rayhit);  // N = 1: rtcIntersect1
    const QueryContext& q = query(args->context);
    const double limit = std::min(q.t_max, static_cast<double>(rayhit->ray.tfar));
    Hit hit;
    if (!static_cast<const Shape*>(args->geometryUserPtr)->intersect(*q.ray, limit, hit)) {
        return;
    }
    hit.primitive = args->geomID;
    *q.hit = hit;
    rayhit->ray.tfar = round_up_to_float(hit.t);  // Embree's float bound must not cut off t
    rayhit->hit.geomID = args->geomID;
    rayhit->hit.primID = args->primID;
    rayhit->hit.u = 0;
    rayhit->hit.v = 0;
    rayhit->hit.Ng_x = saturate_to_float(hit.normal.x);
    rayhit->hit.Ng_y = saturate_to_float(hit.normal.y);
    rayhit->hit.Ng_z = saturate_to_float(hit.normal.z);
    rayhit->hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

void shape_occluded(const RTCOccludedFunctionNArguments* args) {
    if (args->valid[0] == 0) {
        return;
    }
    auto* ray = reinterpret_cast<RTCRay*>(args->ray);
    const QueryContext& q = query(args->context);
    if (static_cast<const Shape*>(args->geometryUserPtr)
            ->occluded(*q.ray, std::min(q.t_max, static_cast<double>(ray->tfar)))) {
        ray->tfar = -std::numeric_limits<float>::infinity();  // Embree's mark for "occluded"
    }
}

// Embree's candidate triangle hits, checked in double before Embree may accept them: its float test
// can find the triangle a ray leaves from (about 0.2 % of the bunny's shadow rays, despite the start
// offset below), which would be a false shadow, or a false nearest hit at t ≈ 0. Rejected candidates
// let Embree go on, so the answer is the one the double-precision test gives.
void mesh_filter(const RTCFilterFunctionNArguments* args) {
    if (args->N != 1 || args->valid[0] == 0) {
        return;  // only rtcIntersect1 / rtcOccluded1 are used
    }
    const auto* hit = reinterpret_cast<const RTCHit*>(args->hit);
    const auto* mesh = static_cast<const Mesh*>(args->geometryUserPtr);
    const QueryContext& q = query(args->context);
    if (!mesh->hits_triangle(hit->primID, *q.ray, q.t_max)) {
        args->valid[0] = 0;
    }
}

RTCRay embree_ray(const Ray& ray, double t_max) {
    RTCRay r{};
    r.org_x = saturate_to_float(ray.origin.x);
    r.org_y = saturate_to_float(ray.origin.y);
    r.org_z = saturate_to_float(ray.origin.z);
    r.dir_x = saturate_to_float(ray.direction.x);
    r.dir_y = saturate_to_float(ray.direction.y);
    r.dir_z = saturate_to_float(ray.direction.z);
    // Embree works in float: the origin alone is rounded by half a float ulp, so a ray leaving a surface
    // (offset only for double precision) could hit that surface again. Start it a few float ulps of
    // the origin's size along, in the ray's units. (The BVH needs no such start: it works in double.)
    const double origin_in_t = max_component(abs(ray.origin)) / length(ray.direction);
    r.tnear = saturate_to_float(8 * 0x1p-24 * origin_in_t);
    // The far end, by as much further: Embree's float t of a hit just before t_max can come out past it
    // (by a few float ulps of the coordinates, divided by the cosine of the angle of incidence), and the
    // hit would be culled before the filter sees it. Letting Embree look further is safe: the filters
    // and the user-geometry callbacks test every candidate against the exact t_max, in double.
    r.tfar = round_up_to_float(t_max + 0x1p-12 * (origin_in_t + t_max));
    r.mask = 0xffffffffu;
    r.flags = 0;
    return r;
}

// Whether Embree may trace the ray: its RayK::valid() (which it asserts) wants every origin and
// direction component within ±1.844e18 and tnear, tfar not NaN. A ray from beyond that is traced here
// instead, shape by shape.
bool embree_can_trace(const RTCRay& r) {
    constexpr float kLargest = static_cast<float>(EmbreeAccelerator::kEmbreeLargest);
    for (const float c : {r.org_x, r.org_y, r.org_z, r.dir_x, r.dir_y, r.dir_z}) {
        if (!(std::abs(c) <= kLargest)) {
            return false;
        }
    }
    return !std::isnan(r.tnear) && !std::isnan(r.tfar);
}

}  // namespace

EmbreeAccelerator::EmbreeAccelerator(std::span<const Shape* const> shapes, const std::string& device_config)
    : shapes_(shapes.begin(), shapes.end()) {
    device_ = rtcNewDevice(device_config.empty() ? nullptr : device_config.c_str());
    if (device_ == nullptr) {
        throw std::runtime_error("Embree: cannot create a device" +
                                 (device_config.empty() ? std::string() : " with '" + device_config + "'"));
    }
    scene_ = rtcNewScene(device_);
    // Robust: Embree's watertight mode, so that its answers can be compared with the BVH's.
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    meshes_.resize(shapes_.size(), nullptr);
    for (std::size_t i = 0; i < shapes_.size(); ++i) {
        const Shape* shape = shapes_[i];
        const Bounds3 b = shape->bounds();
        bounds_.grow(b);
        const bool within_embree = b.is_finite() && max_component(abs(b.lo)) < kEmbreeLargest &&
                                   max_component(abs(b.hi)) < kEmbreeLargest;
        if (!within_embree) {
            if (!b.empty()) {
                direct_.push_back(static_cast<std::uint32_t>(i));
            }
            continue;
        }
        RTCGeometry geometry = nullptr;
        if (const auto* mesh = dynamic_cast<const Mesh*>(shape)) {
            meshes_[i] = mesh;
            geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
            auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                                         RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                                         mesh->positions().size()));
            for (std::size_t v = 0; v < mesh->positions().size(); ++v) {
                vertices[3 * v + 0] = saturate_to_float(mesh->positions()[v].x);
                vertices[3 * v + 1] = saturate_to_float(mesh->positions()[v].y);
                vertices[3 * v + 2] = saturate_to_float(mesh->positions()[v].z);
            }
            auto* indices = static_cast<unsigned*>(
                rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                        3 * sizeof(unsigned), mesh->triangles().size()));
            for (std::size_t t = 0; t < mesh->triangles().size(); ++t) {
                for (int k = 0; k < 3; ++k) {
                    indices[3 * t + static_cast<std::size_t>(k)] =
                        mesh->triangles()[t][static_cast<std::size_t>(k)];
                }
            }
            rtcSetGeometryUserData(geometry, const_cast<Mesh*>(mesh));
            rtcSetGeometryIntersectFilterFunction(geometry, mesh_filter);
            rtcSetGeometryOccludedFilterFunction(geometry, mesh_filter);
        } else {
            geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
            rtcSetGeometryUserPrimitiveCount(geometry, 1);
            rtcSetGeometryUserData(geometry, const_cast<Shape*>(shape));
            rtcSetGeometryBoundsFunction(geometry, shape_bounds, nullptr);
            rtcSetGeometryIntersectFunction(geometry, shape_intersect);
            rtcSetGeometryOccludedFunction(geometry, shape_occluded);
        }
        traced_.push_back(static_cast<std::uint32_t>(i));
        rtcCommitGeometry(geometry);
        rtcAttachGeometryByID(scene_, geometry, static_cast<unsigned>(i));
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(scene_);
}

EmbreeAccelerator::~EmbreeAccelerator() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
}

bool EmbreeAccelerator::intersect(const Ray& ray, double t_max, Hit& hit) const {
    bool found = false;
    for (std::uint32_t i : direct_) {
        if (shapes_[i]->intersect(ray, t_max, hit)) {
            t_max = hit.t;
            hit.primitive = i;
            found = true;
        }
    }
    RTCRayHit rayhit{};
    rayhit.ray = embree_ray(ray, t_max);
    if (!embree_can_trace(rayhit.ray)) {
        for (std::uint32_t i : traced_) {
            if (shapes_[i]->intersect(ray, t_max, hit)) {
                t_max = hit.t;
                hit.primitive = i;
                found = true;
            }
        }
        return found;
    }
    Hit user_hit;
    QueryContext context{{}, &ray, &user_hit, t_max};
    rtcInitIntersectContext(&context.base);
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context.base, &rayhit);
    const unsigned id = rayhit.hit.geomID;
    if (id == RTC_INVALID_GEOMETRY_ID) {
        return found;
    }
    if (const Mesh* mesh = meshes_[id]) {
        // Embree's triangle passed the double test in mesh_filter; redo it for the hit's details.
        Hit mesh_hit;
        if (!mesh->intersect_triangle(rayhit.hit.primID, ray, t_max, mesh_hit)) {
            return found;  // cannot happen: the filter ran this very test
        }
        hit = mesh_hit;
        hit.primitive = id;
        return true;
    }
    hit = user_hit;
    return true;
}

bool EmbreeAccelerator::occluded(const Ray& ray, double t_max) const {
    for (std::uint32_t i : direct_) {
        if (shapes_[i]->occluded(ray, t_max)) {
            return true;
        }
    }
    RTCRay r = embree_ray(ray, t_max);
    if (!embree_can_trace(r)) {
        return std::any_of(traced_.begin(), traced_.end(),
                           [&](std::uint32_t i) { return shapes_[i]->occluded(ray, t_max); });
    }
    Hit unused;
    QueryContext context{{}, &ray, &unused, t_max};
    rtcInitIntersectContext(&context.base);
    rtcOccluded1(scene_, &context.base, &r);
    return r.tfar < 0;
}

}  // namespace glint

#endif
