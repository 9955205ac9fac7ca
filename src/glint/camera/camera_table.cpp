// The one name → constructor table of cameras. Adding a camera: a file here and a line below.
#include "glint/camera/fisheye.hpp"
#include "glint/camera/orthographic.hpp"
#include "glint/camera/pinhole.hpp"
#include "glint/camera/spherical.hpp"
#include "glint/camera/thin_lens.hpp"

namespace glint {

const NameTable<CameraEntry>& camera_table() {
    // One entry a line, so that adding a camera is a one-line change.
    // clang-format off
    static const NameTable<CameraEntry> table = {
        {"pinhole", &PinholeCamera::create},  // the first: the camera of a scene that names no type
        {"thin-lens", &ThinLensCamera::create},
        {"orthographic", &OrthographicCamera::create},
        {"spherical", &SphericalCamera::create},
        {"equirectangular", &SphericalCamera::create},  // another name for the same panorama
        {"fisheye", &FisheyeCamera::create},
    };
    // clang-format on
    return table;
}

}  // namespace glint
