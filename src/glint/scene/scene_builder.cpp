// SceneDesc → Scene: reads every object through Params and the name → constructor tables, so that
// each mistake is reported at its position before anything is rendered.
#include <map>
#include <optional>

#include "glint/geometry/instance.hpp"
#include "glint/integrator/integrator.hpp"
#include "glint/light/area.hpp"
#include "glint/material/matte.hpp"
#include "glint/params/build_context.hpp"
#include "glint/params/params.hpp"
#include "glint/params/table_lookup.hpp"
#include "glint/sampling/sampler.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"

namespace glint {

namespace {

// A name checked against a list, for command-line overrides and `render:` keys.
std::string check_name(const std::string& value, const std::vector<std::string>& names,
                       const std::string& what, const SourcePos& pos) {
    for (const std::string& n : names) {
        if (n == value) {
            return value;
        }
    }
    throw SceneError(pos, unknown_name_message(what, value, names));
}

std::vector<std::string> accelerator_names() {
    std::vector<std::string> names;
    for (const auto& e : accelerator_table()) {
        names.push_back(e.name);
    }
    return names;
}

// An object without a material is grey matte of this albedo.
constexpr double kDefaultAlbedo = 0.8;

// The limits of render settings, with the reason a user needs to understand them (settings.hpp).
std::string depth_limit_message(const std::string& what) {
    return what + " is more than " + std::to_string(kMaxPathDepth) +
           " bounces (paths that long carry no visible light, and every bounce costs time)";
}
std::string side_limit_message(const std::string& what) {
    return what + " is larger than " + std::to_string(kMaxFilmSide) + " pixels";
}
std::string samples_limit_message(const std::string& what) {
    return what + " is more than " + std::to_string(kMaxSamplesPerPixel) + " per pixel";
}

RenderSettings read_render_settings(const Node* node, const RenderOverrides& overrides) {
    RenderSettings s;
    SourcePos where;
    std::optional<Params> p;
    if (node) {
        p.emplace(*node, "render");
        where = p->pos();
        const auto side = [&](const std::string& key, int fallback) {
            const std::int64_t v = p->positive_integer(key, fallback);
            if (v > kMaxFilmSide) {
                p->fail(key, side_limit_message("render." + key));
            }
            return static_cast<int>(v);
        };
        s.width = side("width", s.width);
        s.height = side("height", s.height);
        const std::int64_t spp = p->positive_integer("samples", s.samples_per_pixel);
        if (spp > kMaxSamplesPerPixel) {
            p->fail("samples", samples_limit_message("render.samples"));
        }
        s.samples_per_pixel = static_cast<std::uint32_t>(spp);
        if (p->has("sampler")) {
            s.sampler = check_name(p->string("sampler"), sampler_names(), "sampler", p->pos_of("sampler"));
        }
        if (p->has("integrator")) {
            s.integrator = check_name(p->string("integrator"), integrator_names(), "integrator",
                                      p->pos_of("integrator"));
        }
        if (p->has("accelerator")) {
            s.accelerator = check_name(p->string("accelerator"), accelerator_names(), "accelerator",
                                       p->pos_of("accelerator"));
        }
        const std::int64_t depth = p->positive_integer("max_depth", s.max_depth);
        if (depth > kMaxPathDepth) {
            p->fail("max_depth", depth_limit_message("render.max_depth"));
        }
        s.max_depth = static_cast<int>(depth);
        const std::int64_t seed = p->integer("seed", static_cast<std::int64_t>(s.seed));
        if (seed < 0) {
            p->fail("seed", "render.seed must be zero or more");
        }
        s.seed = static_cast<std::uint64_t>(seed);
        p->finish();
    }
    // Command-line values are checked again here, so that every caller of the library (the preview,
    // a fuzzer, a program) meets the same limits as the command line.
    const SourcePos command_line{SourceFile::from_text("command line", ""), 0, 0};
    const auto check = [&](bool ok, const std::string& message) {
        if (!ok) {
            throw SceneError(command_line, message);
        }
    };
    if (overrides.width) {
        check(*overrides.width >= 1 && *overrides.width <= kMaxFilmSide, side_limit_message("--width"));
        s.width = *overrides.width;
    }
    if (overrides.height) {
        check(*overrides.height >= 1 && *overrides.height <= kMaxFilmSide, side_limit_message("--height"));
        s.height = *overrides.height;
    }
    if (overrides.samples_per_pixel) {
        check(*overrides.samples_per_pixel >= 1 && *overrides.samples_per_pixel <= kMaxSamplesPerPixel,
              samples_limit_message("--spp"));
        s.samples_per_pixel = *overrides.samples_per_pixel;
    }
    if (overrides.seed)
        s.seed = *overrides.seed;
    if (overrides.threads)
        s.threads = *overrides.threads;
    if (overrides.max_depth) {
        check(*overrides.max_depth >= 1 && *overrides.max_depth <= kMaxPathDepth,
              depth_limit_message("--max-depth"));
        s.max_depth = *overrides.max_depth;
    }
    if (overrides.sampler)
        s.sampler = check_name(*overrides.sampler, sampler_names(), "sampler", command_line);
    if (overrides.integrator) {
        s.integrator = check_name(*overrides.integrator, integrator_names(), "integrator", command_line);
    }
    if (overrides.accelerator) {
        s.accelerator = check_name(*overrides.accelerator, accelerator_names(), "accelerator", command_line);
    }
    // Both sides may be within their limit and the whole still too large for memory.
    if (static_cast<std::int64_t>(s.width) * s.height > kMaxFilmPixels) {
        const std::string message =
            "the image is " + std::to_string(s.width) + "x" + std::to_string(s.height) + ", more than " +
            std::to_string(kMaxFilmPixels) + " pixels (16384x8192): the film would need more than 4 GiB";
        if (node && !overrides.width && !overrides.height) {
            throw SceneError(where, "render: " + message);
        }
        throw SceneError(command_line, message);
    }
    return s;
}

}  // namespace

Scene build_scene(const SceneDesc& desc, const RenderOverrides& overrides) {
    Params top(desc.root, "scene");
    BuildContext context{desc.base_dir, {}};
    Scene scene;
    scene.settings = read_render_settings(top.node("render"), overrides);

    // Camera: a map with an optional type (pinhole by default).
    {
        const Node* camera_node = top.node("camera");
        Node empty_map;
        empty_map.kind = Node::Kind::Map;
        empty_map.pos = top.pos();
        Params p(camera_node ? *camera_node : empty_map, "camera");
        const FilmSize film{scene.settings.width, scene.settings.height};
        if (!p.has("type")) {
            scene.camera = camera_table().front().create(p, context, film);
        } else {
            scene.camera = lookup_type(camera_table(), p, "camera").create(p, context, film);
        }
        p.finish();
    }

    if (const Node* background = top.node("background")) {
        scene.background = node_color(*background, "background");
        if (scene.background.r < 0 || scene.background.g < 0 || scene.background.b < 0) {
            throw SceneError(background->pos, "background must not be negative");
        }
    }

    // Materials: a map from name to {type: …, parameters}.
    std::map<std::string, std::uint32_t> material_index;
    const auto build_material = [&](const Node& node, const std::string& what) {
        Params p(node, what);
        auto material = lookup_type(material_table(), p, "material").create(p, context);
        p.finish();
        scene.materials.push_back(std::move(material));
        return static_cast<std::uint32_t>(scene.materials.size() - 1);
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
                default_material = static_cast<std::uint32_t>(scene.materials.size());
                scene.materials.push_back(std::make_unique<Matte>(Rgb(kDefaultAlbedo)));
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

    if (const Node* objects = top.node("objects")) {
        if (!objects->is_sequence()) {
            throw SceneError(objects->pos, "objects must be a list, not " + objects->describe());
        }
        for (size_t i = 0; i < objects->items.size(); ++i) {
            Params p(objects->items[i], "objects[" + std::to_string(i) + "]");
            const ShapeEntry& entry = lookup_type(shape_table(), p, "object");
            Params shape_params(objects->items[i], entry.name);
            shape_params.string("type");
            auto shape = entry.create(shape_params, context);
            shape = apply_transform(shape_params, std::move(shape));  // `transform:`, any object
            const std::uint32_t material = material_for(shape_params);
            shape_params.finish();
            scene.shapes.push_back(std::move(shape));
            scene.shape_materials.push_back(material);
            scene.shape_lights.push_back(-1);
            // An object whose material emits is an area light, so that light sampling finds it.
            if (emits_light(*scene.materials[material])) {
                if (!(scene.shapes.back()->area() > 0)) {
                    throw SceneError(p.pos(), "objects[" + std::to_string(i) + "] emits light, but a " +
                                                  entry.name +
                                                  " has no finite area: it cannot be an area light");
                }
                scene.shape_lights.back() = static_cast<std::int32_t>(scene.lights.size());
                scene.lights.push_back(
                    std::make_unique<AreaLight>(*scene.shapes.back(), *scene.materials[material], 1));
            }
        }
    }

    // {type: area} lights add their shape to the objects, with the light's emitting material.
    std::int32_t next_light_index = -1;
    context.add_object = [&](Params& shape_params, std::unique_ptr<Material> material) {
        const ShapeEntry& entry = lookup_type(shape_table(), shape_params, "shape");
        auto shape = apply_transform(shape_params, entry.create(shape_params, context));
        shape_params.finish();
        scene.shapes.push_back(std::move(shape));
        scene.materials.push_back(std::move(material));
        scene.shape_materials.push_back(static_cast<std::uint32_t>(scene.materials.size() - 1));
        scene.shape_lights.push_back(next_light_index);
        return std::pair<const Shape*, const Material*>{scene.shapes.back().get(),
                                                        scene.materials.back().get()};
    };

    if (const Node* lights = top.node("lights")) {
        if (!lights->is_sequence()) {
            throw SceneError(lights->pos, "lights must be a list, not " + lights->describe());
        }
        for (size_t i = 0; i < lights->items.size(); ++i) {
            Params p(lights->items[i], "lights[" + std::to_string(i) + "]");
            const LightEntry& entry = lookup_type(light_table(), p, "light");
            Params light_params(lights->items[i], entry.name + " light");
            light_params.string("type");
            next_light_index = static_cast<std::int32_t>(scene.lights.size());
            auto light = entry.create(light_params, context);
            light_params.finish();
            scene.ambient += light->ambient();
            if (light->is_environment()) {
                if (scene.environment) {
                    light_params.fail("type", "a scene has at most one environment light");
                }
                if (top.node("background")) {
                    light_params.fail("type",
                                      "an environment light supplies the background: remove the scene's "
                                      "`background`");
                }
                scene.environment = light.get();
            }
            scene.lights.push_back(std::move(light));
        }
    }
    top.finish();

    std::vector<const Shape*> shapes;
    for (const auto& s : scene.shapes) {
        shapes.push_back(s.get());
    }
    scene.accelerator = make_accelerator(scene.settings.accelerator, shapes);
    return scene;
}

}  // namespace glint
