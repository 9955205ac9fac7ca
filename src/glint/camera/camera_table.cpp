// The one name → constructor table of cameras. Adding a camera: a file here and a line below.
#include "glint/camera/pinhole.hpp"

namespace glint {

const std::vector<CameraEntry>& camera_table() {
    static const std::vector<CameraEntry> table = {
        {"pinhole", &PinholeCamera::create},
    };
    return table;
}

}  // namespace glint
