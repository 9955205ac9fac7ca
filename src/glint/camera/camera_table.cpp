// The one name → constructor table of cameras. Adding a camera: a file here and a line below.
#include "glint/camera/fisheye.hpp"
#include "glint/camera/orthographic.hpp"
#include "glint/camera/pinhole.hpp"
#include "glint/camera/spherical.hpp"
#include "glint/camera/thin_lens.hpp"

namespace glint {

const std::vector<CameraEntry>& camera_table() {
    static const std::vector<CameraEntry> table = {
        {"pinhole", &PinholeCamera::create},           {"thin-lens", &ThinLensCamera::create},
        {"orthographic", &OrthographicCamera::create}, {"spherical", &SphericalCamera::create},
        {"equirectangular", &SphericalCamera::create},  // another name for the same panorama
        {"fisheye", &FisheyeCamera::create},
    };
    return table;
}

}  // namespace glint
