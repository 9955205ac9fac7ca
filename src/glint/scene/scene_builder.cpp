// SceneDesc → Scene: reads every object through Params and the name → constructor tables, so that
// each mistake is reported at its position before anything is rendered.
#include <cmath>
#include <map>
#include <optional>

#include "glint/geometry/instance.hpp"
#include "glint/geometry/mesh_io/gltf_file.hpp"
#include "glint/integrator/integrator.hpp"
#include "glint/light/area.hpp"
#include "glint/material/matte.hpp"
#include "glint/params/build_context.hpp"
#include "glint/params/name_table.hpp"
#include "glint/params/params.hpp"
#include "glint/sampling/pixel_filter.hpp"
#include "glint/sampling/sampler.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_writer.hpp"

namespace glint {

namespace {

// An object without a material is grey matte of this albedo.
constexpr double kDefaultAlbedo = 0.8;

// The limits of render settings, with the reason a user needs to understand them (settings.hpp).
std::string side_limit_message(const std::string& what) {
    return what + " is larger than " + std::to_string(kMaxFilmSide) + " pixels";
}
std::string samples_limit_message(const std::string& what) {
    return what + " is more than " + std::to_string(kMaxSamplesPerPixel) + " per pixel";
}

// An empty map standing for a block the scene leaves out, positioned at `pos`.
Node empty_map_at(const SourcePos& pos) {
    Node empty;
    empty.kind = Node::Kind::Map;
    empty.pos = pos;
    return empty;
}

// The `render:` block's own keys. The sampler, filter and integrator are objects of their own, read by
// build_view; here their nodes are only marked as read.
RenderSettings read_render_settings(Params& p) {
    RenderSettings s;
    const auto side = [&](const std::string& key, int fallback) {
        const std::int64_t v = p.positive_integer(key, fallback);
        if (v > kMaxFilmSide) {
            p.fail(key, side_limit_message("render." + key));
        }
        return static_cast<int>(v);
    };
    s.width = side("width", s.width);
    s.height = side("height", s.height);
    const std::int64_t spp = p.positive_integer("samples", s.samples_per_pixel);
    if (spp > kMaxSamplesPerPixel) {
        p.fail("samples", samples_limit_message("render.samples"));
    }
    s.samples_per_pixel = static_cast<std::uint32_t>(spp);
    if (p.has("accelerator")) {
        s.accelerator = accelerator_table().lookup(p, "accelerator", "accelerator").name;
    }
    const std::int64_t depth = p.positive_integer("max_depth", s.max_depth);
    if (depth > kMaxPathDepth) {
        p.fail("max_depth", max_depth_limit_message("render.max_depth"));
    }
    s.max_depth = static_cast<int>(depth);
    const std::int64_t seed = p.integer("seed", static_cast<std::int64_t>(s.seed));
    if (seed < 0) {
        p.fail("seed", "render.seed must be zero or more");
    }
    s.seed = static_cast<std::uint64_t>(seed);
    if (const Node* crop = p.node("crop")) {
        const auto fail_crop = [&](const std::string& why) {
            p.fail("crop", "render.crop " + why +
                               ": expected [x0, y0, x1, y1], the pixels x0 ≤ x < x1 and y0 ≤ y < y1 of the " +
                               std::to_string(s.width) + "x" + std::to_string(s.height) + " image");
        };
        if (!crop->is_sequence() || crop->items.size() != 4) {
            fail_crop("is not four numbers");
        }
        std::int64_t v[4];
        for (std::size_t i = 0; i < 4; ++i) {
            v[i] = node_integer(crop->items[i], "render.crop");
        }
        if (v[0] < 0 || v[1] < 0 || v[2] > s.width || v[3] > s.height || v[0] >= v[2] || v[1] >= v[3]) {
            fail_crop("is not a non-empty window inside the image");
        }
        s.crop = PixelWindow{static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<int>(v[2]),
                             static_cast<int>(v[3])};
    }
    s.clamp = p.non_negative("clamp", 0);
    if (!std::isfinite(s.clamp)) {
        p.fail("clamp", "render.clamp must be a finite number ≥ 0 (0: no clamp)");
    }
    s.display.exposure = p.number("exposure", 0);
    if (!(std::abs(s.display.exposure) <= kMaxExposureStops)) {
        p.fail("exposure", "render.exposure must be a number of stops from -64 to 64");
    }
    s.display.curve = p.enumeration("tonemap", tone_curve_table(), ToneCurve::Clamp);
    // Both sides may be within their limit and the whole still too large for memory.
    if (static_cast<std::int64_t>(s.width) * s.height > kMaxFilmPixels) {
        p.fail("render: the image is " + std::to_string(s.width) + "x" + std::to_string(s.height) +
               ", more than " + std::to_string(kMaxFilmPixels) +
               " pixels (16384x8192): the film would need more than 4 GiB");
    }
    return s;
}

// `map` without `key` (a copy).
Node without_key(Node map, const std::string& key) {
    map.remove(key);
    return map;
}

// The text that identifies a shape for WorldCache: its description without `material` (which the
// shape does not depend on), with the folder its files resolve in.
std::string shape_key(const Node& object, const std::filesystem::path& base_dir) {
    return base_dir.string() + "\n" + write_scene_yaml(without_key(object, "material"));
}

}  // namespace

View build_view(const SceneDesc& desc) {
    Params top(desc.root, "scene");
    const Node* render_node = top.node("render");
    const Node render_map = render_node ? *render_node : empty_map_at(top.pos());
    Params render(render_map, "render");
    BuildContext context{desc.base_dir, {}};
    View view;
    view.settings = read_render_settings(render);

    // The sampler, the filter and the integrator: objects with a type, or a plain word (the short form); left
    // out, the default's word.
    const auto typed = [&](const std::string& key, const std::string& fallback) {
        const Node* node = render.node(key);
        Node word;
        if (!node) {
            word.kind = Node::Kind::Scalar;
            word.scalar = fallback;
            word.pos = render.pos();
        }
        Node object = typed_object(node ? *node : word);
        if (!object.is_map()) {
            throw SceneError(object.pos, "render." + key + " must be a name or a map with a type, not " +
                                             object.describe());
        }
        return object;
    };
    {
        const Node node = typed("sampler", view.settings.sampler);
        Params p(node, "sampler");
        const std::string name = sampler_table().lookup_type(p, "sampler").name;
        view.settings.sampler = name;
        view.sampler = make_sampler(name, view.settings.samples_per_pixel);
        p.finish();
    }
    {
        const Node node = typed("filter", pixel_filter_types().name_of(RenderSettings{}.filter.type));
        Params p(node, "filter");
        view.settings.filter = read_pixel_filter(p);
        p.finish();
    }
    {
        const Node node = typed("integrator", view.settings.integrator);
        Params p(node, "integrator");
        view.settings.integrator = integrator_table().lookup_type(p, "integrator").name;
        view.integrator = build_object(integrator_table(), node, view.settings.integrator + " integrator",
                                       "integrator", view.settings);
    }
    render.finish();

    // Camera: a map with an optional type (pinhole by default).
    const Node* camera_node = top.node("camera");
    const Node camera_map = camera_node ? *camera_node : empty_map_at(top.pos());
    Params p(camera_map, "camera");
    const FilmSize film{view.settings.width, view.settings.height};
    if (!p.has("type")) {
        view.camera = camera_table().front().create(p, context, film);
    } else {
        view.camera = camera_table().lookup_type(p, "camera").create(p, context, film);
    }
    p.finish();
    return view;
}

std::shared_ptr<const World> build_world(const SceneDesc& desc, WorldCache* cache) {
    // The glTF file its meshes read is kept while they are built, not while the image renders.
    struct ForgetGltfFiles {
        ~ForgetGltfFiles() { forget_gltf_files(); }
    } forget_gltf_files_after_building;
    Params top(desc.root, "scene");
    BuildContext context{desc.base_dir, {}};
    auto world = std::make_shared<World>();
    std::string accelerator = RenderSettings{}.accelerator;
    if (const Node* render_node = top.node("render")) {
        if (const Node* name = render_node->is_map() ? render_node->find("accelerator") : nullptr) {
            accelerator = accelerator_table()
                              .lookup(node_string(*name, "render.accelerator"), "accelerator", name->pos)
                              .name;
        }
    }

    if (const Node* background = top.node("background")) {
        world->background = node_color(*background, "background");
        if (world->background.r < 0 || world->background.g < 0 || world->background.b < 0) {
            throw SceneError(background->pos, "background must not be negative");
        }
    }

    // Materials: a map from name to {type: …, parameters}.
    std::map<std::string, std::uint32_t> material_index;
    const auto build_material = [&](const Node& node, const std::string& what) {
        world->materials.push_back(build_object(material_table(), node, what, "material", context));
        return static_cast<std::uint32_t>(world->materials.size() - 1);
    };
    if (const Node* materials = top.node("materials")) {
        if (!materials->is_map()) {
            throw SceneError(materials->pos,
                             "materials must be a map from names to materials, not " + materials->describe());
        }
        for (size_t i = 0; i < materials->keys.size(); ++i) {
            material_index[materials->keys[i]] =
                build_material(materials->items[i], "material '" + materials->keys[i] + "'");
        }
    }
    std::optional<std::uint32_t> default_material;  // grey matte, made only if some object needs it
    const auto material_for = [&](Params& p) -> std::uint32_t {
        const Node* node = p.node("material");
        if (!node) {
            if (!default_material) {
                default_material = static_cast<std::uint32_t>(world->materials.size());
                world->materials.push_back(std::make_unique<Matte>(Rgb(kDefaultAlbedo)));
            }
            return *default_material;
        }
        if (node->is_map()) {
            return build_material(*node, p.what() + ".material");
        }
        const std::string name = node_string(*node, p.what() + ".material");
        const auto found = material_index.find(name);
        if (found == material_index.end()) {
            std::vector<std::string> names;
            for (const auto& [n, index] : material_index) {
                names.push_back(n);
            }
            throw SceneError(
                node->pos, names.empty() ? "unknown material '" + name + "' (the scene defines no materials)"
                                         : unknown_name_message("material", name, names, "defined"));
        }
        return found->second;
    };

    // A shape with its `transform`, or the one the cache holds for the same description (whose keys are
    // then only marked as read: they were checked when it was built).
    // The shapes this build uses: what the cache keeps afterwards.
    std::map<std::string, std::shared_ptr<const Shape>> used_shapes;
    const auto build_shape = [&](Params& shape_params,
                                 const ShapeEntry& entry) -> std::shared_ptr<const Shape> {
        std::string key;
        if (cache) {
            key = shape_key(shape_params.map(), desc.base_dir);
            if (const auto found = cache->shapes.find(key); found != cache->shapes.end()) {
                for (const std::string& k : shape_params.map().keys) {
                    if (k != "material") {
                        shape_params.node(k);
                    }
                }
                used_shapes.emplace(key, found->second);
                return found->second;
            }
        }
        std::shared_ptr<const Shape> shape =
            apply_transform(shape_params, entry.create(shape_params, context));  // `transform:`, any object
        if (cache) {
            used_shapes.emplace(std::move(key), shape);
        }
        return shape;
    };
    const auto add_object = [&](std::shared_ptr<const Shape> shape, std::uint32_t material,
                                std::int32_t light_index) {
        world->shapes.push_back(std::move(shape));
        world->shape_materials.push_back(material);
        world->shape_lights.push_back(light_index);
    };

    if (const Node* objects = top.node("objects")) {
        if (!objects->is_sequence()) {
            throw SceneError(objects->pos, "objects must be a list, not " + objects->describe());
        }
        for (size_t i = 0; i < objects->items.size(); ++i) {
            Params p(objects->items[i], "objects[" + std::to_string(i) + "]");
            const ShapeEntry& entry = shape_table().lookup_type(p, "object");
            Params shape_params(objects->items[i], entry.name);
            shape_params.string("type");
            std::shared_ptr<const Shape> shape = build_shape(shape_params, entry);
            const std::uint32_t material = material_for(shape_params);
            shape_params.finish();
            add_object(std::move(shape), 0, -1);
            if (!attach_material(*world, world->shapes.size() - 1, material)) {
                throw SceneError(p.pos(), "objects[" + std::to_string(i) + "] emits light, but a " +
                                              entry.name + " has no finite area: it cannot be an area light");
            }
        }
    }

    // {type: area} lights add their shape to the objects, with the light's emitting material.
    std::int32_t next_light_index = -1;
    context.add_object = [&](Params& shape_params, std::unique_ptr<Material> material) {
        const ShapeEntry& entry = shape_table().lookup_type(shape_params, "shape");
        std::shared_ptr<const Shape> shape = build_shape(shape_params, entry);
        shape_params.finish();
        world->materials.push_back(std::move(material));
        const Shape* added = shape.get();
        add_object(std::move(shape), static_cast<std::uint32_t>(world->materials.size() - 1),
                   next_light_index);
        return std::pair<const Shape*, const Material*>{added, world->materials.back().get()};
    };

    if (const Node* lights = top.node("lights")) {
        if (!lights->is_sequence()) {
            throw SceneError(lights->pos, "lights must be a list, not " + lights->describe());
        }
        for (size_t i = 0; i < lights->items.size(); ++i) {
            Params p(lights->items[i], "lights[" + std::to_string(i) + "]");
            const LightEntry& entry = light_table().lookup_type(p, "light");
            Params light_params(lights->items[i], entry.name + " light");
            next_light_index = static_cast<std::int32_t>(world->lights.size());
            auto light = build_object(light_table(), light_params, "light", context);
            world->ambient += light->ambient();
            if (light->is_environment()) {
                if (world->environment) {
                    light_params.fail("type", "a scene has at most one environment light");
                }
                if (top.node("background")) {
                    light_params.fail("type",
                                      "an environment light supplies the background: remove the scene's "
                                      "`background`");
                }
                world->environment = light.get();
            }
            world->lights.push_back(std::move(light));
        }
    }

    if (cache) {
        cache->shapes = std::move(used_shapes);
    }
    std::vector<const Shape*> shapes;
    for (const auto& s : world->shapes) {
        shapes.push_back(s.get());
    }
    if (cache && cache->accelerator.accelerator && cache->accelerator.name == accelerator &&
        cache->accelerator.shapes == shapes) {
        world->accelerator = cache->accelerator.accelerator;
    } else {
        world->accelerator = make_accelerator(accelerator, shapes);
        if (cache) {
            cache->accelerator = {accelerator, shapes, world->accelerator};
        }
    }
    return world;
}

Scene build_scene(const SceneDesc& desc, WorldCache* cache) {
    Scene scene;
    scene.view = build_view(desc);
    scene.world = build_world(desc, cache);
    // The top level's own keys: every block above is read by one of the two halves.
    Params top(desc.root, "scene");
    for (const char* key : {"render", "camera", "background", "materials", "objects", "lights"}) {
        top.node(key);
    }
    top.finish();
    return scene;
}

bool same_world(const SceneDesc& a, const SceneDesc& b) {
    if (a.base_dir != b.base_dir) {
        return false;
    }
    // The trees without the view's keys.
    const auto world_part = [](const Node& root) {
        Node accelerator;
        if (const Node* render = root.find("render");
            render && render->is_map() && render->find("accelerator")) {
            accelerator = *render->find("accelerator");
        }
        Node world = without_key(without_key(root, "camera"), "render");
        world.keys.push_back("render.accelerator");
        world.key_positions.emplace_back();
        world.items.push_back(accelerator);
        return world;
    };
    return same_tree(world_part(a.root), world_part(b.root));
}

}  // namespace glint
