// The one name → constructor table of accelerators.
#include "glint/accel/bvh.hpp"
#include "glint/accel/embree.hpp"
#include "glint/accel/linear.hpp"

namespace glint {

const NameTable<AcceleratorEntry>& accelerator_table() {
    static const NameTable<AcceleratorEntry> table = {
        {"bvh", "8-wide SAH bounding volume hierarchy (the default)",
         [](std::span<const Shape* const> shapes) { return std::make_unique<BvhAccelerator>(shapes); }},
#ifdef GLINT_HAVE_EMBREE
        {"embree", "Intel Embree 3 (built because Embree was found; a check on and a rival to bvh)",
         [](std::span<const Shape* const> shapes) { return std::make_unique<EmbreeAccelerator>(shapes); }},
#endif
        {"list", "every shape tested for every ray (brute force; the reference)",
         [](std::span<const Shape* const> shapes) { return std::make_unique<LinearAccelerator>(shapes); }},
    };
    return table;
}

std::unique_ptr<Accelerator> make_accelerator(const std::string& name, std::span<const Shape* const> shapes) {
    const AcceleratorEntry* entry = accelerator_table().find(name);
    return entry ? entry->create(shapes) : nullptr;
}

}  // namespace glint
