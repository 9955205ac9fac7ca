#include "glint/world/world.hpp"

#include "glint/light/area.hpp"

namespace glint {

bool attach_material(World& world, std::size_t shape, std::uint32_t material) {
    const Material& m = *world.materials[material];
    if (emits_light(m) && !(world.shapes[shape]->area() > 0)) {
        return false;
    }
    world.shape_materials[shape] = material;
    world.shape_lights[shape] = -1;
    if (emits_light(m)) {
        world.shape_lights[shape] = static_cast<std::int32_t>(world.lights.size());
        world.lights.push_back(std::make_unique<AreaLight>(*world.shapes[shape], m, 1));
    }
    return true;
}

}  // namespace glint
