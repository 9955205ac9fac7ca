// The glTF importer. Every mesh primitive a node places becomes a glint mesh object that refers back
// to the file ({type: mesh, file: model.gltf, gltf_mesh: M, gltf_primitive: P}) with the node's world
// matrix as its transform, so converting a model writes a small YAML next to it rather than copying its
// geometry into text. Materials become `principled` (glTF's own model), emissive ones `emissive`; a
// material's normal map becomes its meshes' `normal_map`. Every message, and every node made from an
// element of the file, is at that element's line and column in the JSON (gltf_positions.hpp).
#include "glint/import/gltf_scene.hpp"

#include <array>
#include <cmath>
#include <set>

#include "glint/core/bounds.hpp"
#include "glint/core/math.hpp"
#include "glint/geometry/mesh_io/gltf_file.hpp"
#include "glint/geometry/mesh_io/tinygltf.hpp"
#include "glint/import/gltf_positions.hpp"
#include "glint/import/scene_tree.hpp"

namespace glint {
namespace {

namespace tree = scene_tree;

// A 4 × 4 matrix, row by row: m[4 r + c].
using Matrix = std::array<double, 16>;

constexpr Matrix kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Matrix multiply(const Matrix& a, const Matrix& b) {
    Matrix m{};
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            for (int k = 0; k < 4; ++k) {
                m[4 * r + c] += a[4 * r + k] * b[4 * k + c];
            }
        }
    }
    return m;
}

// A node's matrix: `matrix` (column-major in glTF) or translation × rotation × scale.
Matrix local_matrix(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        Matrix m{};
        for (int r = 0; r < 4; ++r) {
            for (int c = 0; c < 4; ++c) {
                m[4 * r + c] = node.matrix[static_cast<std::size_t>(4 * c + r)];
            }
        }
        return m;
    }
    const double tx = node.translation.size() == 3 ? node.translation[0] : 0;
    const double ty = node.translation.size() == 3 ? node.translation[1] : 0;
    const double tz = node.translation.size() == 3 ? node.translation[2] : 0;
    double x = 0, y = 0, z = 0, w = 1;  // the unit quaternion (x, y, z, w)
    if (node.rotation.size() == 4) {
        x = node.rotation[0], y = node.rotation[1], z = node.rotation[2], w = node.rotation[3];
        const double norm = std::sqrt(x * x + y * y + z * z + w * w);
        if (norm > 0) {
            x /= norm, y /= norm, z /= norm, w /= norm;
        }
    }
    const double sx = node.scale.size() == 3 ? node.scale[0] : 1;
    const double sy = node.scale.size() == 3 ? node.scale[1] : 1;
    const double sz = node.scale.size() == 3 ? node.scale[2] : 1;
    return {(1 - 2 * (y * y + z * z)) * sx,
            2 * (x * y - z * w) * sy,
            2 * (x * z + y * w) * sz,
            tx,
            2 * (x * y + z * w) * sx,
            (1 - 2 * (x * x + z * z)) * sy,
            2 * (y * z - x * w) * sz,
            ty,
            2 * (x * z - y * w) * sx,
            2 * (y * z + x * w) * sy,
            (1 - 2 * (x * x + y * y)) * sz,
            tz,
            0,
            0,
            0,
            1};
}

Vec3 transform_point(const Matrix& m, const Vec3& p) {
    return {m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
            m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]};
}

Vec3 transform_direction(const Matrix& m, const Vec3& d) {
    return {m[0] * d.x + m[1] * d.y + m[2] * d.z, m[4] * d.x + m[5] * d.y + m[6] * d.z,
            m[8] * d.x + m[9] * d.y + m[10] * d.z};
}

Rgb rgb_of(const std::vector<double>& values, const Rgb& fallback) {
    return values.size() >= 3 ? Rgb{values[0], values[1], values[2]} : fallback;
}

class GltfImporter {
  public:
    GltfImporter(const std::filesystem::path& path, const ImportOptions& options)
        : path_(path),
          options_(options),
          at_(tree::file_position(path.string())),
          gltf_(load_positioned_gltf(path, at_)),
          file_(gltf_.file),
          model_(file_->model.get()) {}

    SceneDesc run() {
        desc_.base_dir = path_.parent_path();
        for (std::size_t i = 0; i < model_->extensionsUsed.size(); ++i) {
            const std::string& extension = model_->extensionsUsed[i];
            if (extension != "KHR_lights_punctual" && extension != "KHR_materials_emissive_strength") {
                warn("/extensionsUsed/" + std::to_string(i),
                     "the extension " + extension + " is not read by glint");
            }
        }
        for (const auto& [root, named_at] : root_nodes()) {
            visit(root, named_at, kIdentity, 0);
        }
        std::vector<std::pair<std::string, Node>> root;
        root.push_back({"render", tree::map({{"integrator", tree::text("path", at_)}}, at_)});
        root.push_back({"camera", camera_ ? std::move(*camera_) : default_camera()});
        root.push_back({"objects", tree::list(std::move(objects_), at_)});
        if (lights_.empty() && !emits_) {
            warn(
                scene_pointer(),
                "the glTF scene has no light: glint lights it by a white sky (an environment of radiance 1)");
            lights_.push_back(tree::white_sky(at_));
        }
        if (!lights_.empty()) {
            root.push_back({"lights", tree::list(std::move(lights_), at_)});
        }
        desc_.root = tree::map(std::move(root), at_);
        return std::move(desc_);
    }

  private:
    // The position of the element at JSON pointer `pointer` (or of the nearest element around it).
    SourcePos at(const std::string& pointer) const { return gltf_.positions.at(pointer); }

    void warn(const std::string& pointer, const std::string& message) {
        desc_.warnings.push_back({at(pointer), message});
    }

    [[noreturn]] void fail(const std::string& pointer, const std::string& message) const {
        throw SceneError(at(pointer), "glTF file '" + path_.string() + "': " + message);
    }

    // The scene rendered: the default scene (or the first); -1 when the file has none.
    int scene_index() const {
        if (model_->scenes.empty()) {
            return -1;
        }
        return model_->defaultScene >= 0 &&
                       static_cast<std::size_t>(model_->defaultScene) < model_->scenes.size()
                   ? model_->defaultScene
                   : 0;
    }

    // Where what the whole scene lacks (a camera, a light) is reported: the scene, or the file's start.
    std::string scene_pointer() const {
        const int scene = scene_index();
        return scene < 0 ? "" : "/scenes/" + std::to_string(scene);
    }

    // The nodes of the scene rendered, or, with no scene, every node no other names; each with the
    // pointer of where it is named.
    std::vector<std::pair<int, std::string>> root_nodes() const {
        std::vector<std::pair<int, std::string>> roots;
        if (const int scene = scene_index(); scene >= 0) {
            const std::vector<int>& nodes = model_->scenes[static_cast<std::size_t>(scene)].nodes;
            for (std::size_t k = 0; k < nodes.size(); ++k) {
                roots.push_back({nodes[k], scene_pointer() + "/nodes/" + std::to_string(k)});
            }
            return roots;
        }
        std::set<int> children;
        for (const tinygltf::Node& node : model_->nodes) {
            children.insert(node.children.begin(), node.children.end());
        }
        for (int i = 0; i < static_cast<int>(model_->nodes.size()); ++i) {
            if (!children.count(i)) {
                roots.push_back({i, "/nodes/" + std::to_string(i)});
            }
        }
        return roots;
    }

    // Node `index`, named at `named_at` (a scene's `nodes`, a node's `children`), under `parent`.
    void visit(int index, const std::string& named_at, const Matrix& parent, int depth) {
        // A node hierarchy is a tree, at most as deep as there are nodes; a cycle is an error.
        if (index < 0 || static_cast<std::size_t>(index) >= model_->nodes.size()) {
            fail(named_at, "node " + std::to_string(index) + " does not exist");
        }
        if (depth > static_cast<int>(model_->nodes.size()) || depth > 1000) {
            fail(named_at, "its nodes form a cycle or nest deeper than 1000 levels");
        }
        const tinygltf::Node& node = model_->nodes[static_cast<std::size_t>(index)];
        const std::string pointer = "/nodes/" + std::to_string(index);
        const Matrix world = multiply(parent, local_matrix(node));
        if (node.mesh >= 0) {
            add_mesh(node, pointer, world);
        }
        if (node.camera >= 0) {
            add_camera(node, pointer, world);
        }
        const auto light = node.extensions.find("KHR_lights_punctual");
        if (light != node.extensions.end() && light->second.Has("light")) {
            add_light(light->second.Get("light").GetNumberAsInt(),
                      pointer + "/extensions/KHR_lights_punctual/light", world);
        }
        if (node.skin >= 0 && skin_warned_.insert(node.skin).second) {
            warn(pointer + "/skin",
                 "node '" + node.name + "' is skinned: glint renders its mesh in the rest pose");
        }
        for (std::size_t k = 0; k < node.children.size(); ++k) {
            visit(node.children[k], pointer + "/children/" + std::to_string(k), world, depth + 1);
        }
    }

    void add_mesh(const tinygltf::Node& node, const std::string& node_pointer, const Matrix& world) {
        if (static_cast<std::size_t>(node.mesh) >= model_->meshes.size()) {
            fail(node_pointer + "/mesh", "node '" + node.name + "' names mesh " + std::to_string(node.mesh) +
                                             ", which does not exist");
        }
        const tinygltf::Mesh& mesh = model_->meshes[static_cast<std::size_t>(node.mesh)];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = mesh.primitives[p];
            const std::string pointer =
                "/meshes/" + std::to_string(node.mesh) + "/primitives/" + std::to_string(p);
            const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
            if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
                mode != TINYGLTF_MODE_TRIANGLE_FAN) {
                warn(pointer + "/mode",
                     "mesh '" + mesh.name + "' primitive " + std::to_string(p) +
                         " is made of points or lines: glint renders surfaces only, so it is "
                         "left out");
                continue;
            }
            // The bounds, for a camera when the file has none. A bad accessor is an error at the
            // primitive, whose attributes name it.
            const SourcePos pos = at(pointer);
            const MeshData data = gltf_primitive_mesh(*file_, node.mesh, static_cast<int>(p), pos);
            for (const Vec3& position : data.positions) {
                bounds_.grow(transform_point(world, position));
            }
            std::vector<std::pair<std::string, Node>> object = {
                {"type", tree::text("mesh", pos)},
                {"file", tree::text(path_.filename().generic_string(), pos)},
                {"gltf_mesh", tree::number(node.mesh, pos)},
                {"gltf_primitive", tree::number(static_cast<double>(p), pos)}};
            if (world != kIdentity) {
                object.push_back(
                    {"transform",
                     tree::map(
                         {{"matrix", tree::numbers(std::vector<double>(world.begin(), world.end()), pos)}},
                         pos)});
            }
            if (primitive.material >= 0 &&
                static_cast<std::size_t>(primitive.material) < model_->materials.size()) {
                if (auto normal_map = normal_map_of(primitive.material, data, mesh.name, p, pointer)) {
                    object.push_back({"normal_map", std::move(*normal_map)});
                }
                object.push_back({"material", material(primitive.material)});
            }
            objects_.push_back(tree::map(std::move(object), pos));
        }
    }

    using Keys = std::vector<std::pair<std::string, Node>>;

    // The keys that name the image of a glTF texture (`file`, and `gltf_image` for one stored in the
    // model), or nothing when the texture or its image does not exist. `extensions` are the texture
    // reference's own (KHR_texture_transform is one). What glint leaves out is warned about when `warn_about`
    // (once per material, not at each of its uses).
    // `reference` is the texture reference's pointer (/materials/0/normalTexture); the keys are at the
    // image's `uri` (or the image), where a file that cannot be read is named.
    std::optional<Keys> image_keys(int texture, int tex_coord, const tinygltf::ExtensionMap& extensions,
                                   const std::string& what, bool warn_about, const std::string& reference) {
        if (texture < 0 || static_cast<std::size_t>(texture) >= model_->textures.size()) {
            return std::nullopt;
        }
        const int source = model_->textures[static_cast<std::size_t>(texture)].source;
        if (source < 0 || static_cast<std::size_t>(source) >= model_->images.size()) {
            return std::nullopt;
        }
        const std::string& uri = model_->images[static_cast<std::size_t>(source)].uri;
        if (tex_coord != 0 && warn_about) {
            warn(reference + "/texCoord",
                 what + " uses TEXCOORD_" + std::to_string(tex_coord) + ": glint reads TEXCOORD_0 only");
        }
        if (extensions.count("KHR_texture_transform") && warn_about) {
            warn(reference + "/extensions/KHR_texture_transform",
                 what + " has a KHR_texture_transform: glint maps it without the transform");
        }
        const SourcePos pos = at("/images/" + std::to_string(source) + "/uri");
        if (uri.empty() || uri.rfind("data:", 0) == 0) {  // stored in the model: decoded from it
            return Keys{{"file", tree::text(path_.filename().generic_string(), pos)},
                        {"gltf_image", tree::number(source, pos)}};
        }
        std::string file;  // URIs escape spaces and other characters as %XX
        for (std::size_t i = 0; i < uri.size(); ++i) {
            if (uri[i] == '%' && i + 2 < uri.size() &&
                std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
                std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
                file += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
                i += 2;
            } else {
                file += uri[i];
            }
        }
        return Keys{{"file", tree::text(file, pos)}};
    }

    // An image texture {type: image, file, …} of a glTF texture reference, times `factor` per channel;
    // `channel` r, g or b for a number stored in one channel, `linear` for data rather than colour.
    // `reference` is the reference's pointer, where the texture's own keys are.
    template <class TextureInfo>
    std::optional<Node> image_texture(const TextureInfo& info, const std::string& reference,
                                      const Rgb& factor, const std::string& what, bool warn_about,
                                      const std::string& channel = "", bool linear = false) {
        std::optional<Keys> keys =
            image_keys(info.index, info.texCoord, info.extensions, what, warn_about, reference);
        if (!keys) {
            return std::nullopt;
        }
        const SourcePos pos = at(reference);
        keys->insert(keys->begin(), {"type", tree::text("image", pos)});
        if (!channel.empty()) {
            keys->push_back({"channel", tree::text(channel, pos)});
        }
        if (linear) {
            keys->push_back({"encoding", tree::text("linear", pos)});
        }
        if (factor != Rgb(1.0)) {
            const bool grey = factor.r == factor.g && factor.g == factor.b;
            keys->push_back({"scale", grey ? tree::number(factor.r, pos) : tree::color(factor, pos)});
        }
        return tree::map(std::move(*keys), pos);
    }

    std::string material_what(int index) const {
        const tinygltf::Material& m = model_->materials[static_cast<std::size_t>(index)];
        return "material '" + (m.name.empty() ? std::to_string(index) : m.name) + "'";
    }

    // The mesh's normal_map {file, gltf_image, scale} for material `index`'s normalTexture: a key of
    // the mesh, not of the material, since it is the shading normal the mesh gives its hits that the map
    // changes (docs/importers.md). None when the material has no normal map, or (with a warning) when
    // the primitive has no TEXCOORD_0 to map it by.
    std::optional<Node> normal_map_of(int index, const MeshData& data, const std::string& mesh_name,
                                      std::size_t primitive, const std::string& primitive_pointer) {
        const tinygltf::NormalTextureInfo& info =
            model_->materials[static_cast<std::size_t>(index)].normalTexture;
        const std::string reference = material_pointer(index) + "/normalTexture";
        const bool first_use = warned_normal_maps_.insert(index).second;
        std::optional<Keys> keys = image_keys(info.index, info.texCoord, info.extensions,
                                              material_what(index) + "'s normal map", first_use, reference);
        if (!keys) {
            return std::nullopt;
        }
        if (data.uvs.empty()) {
            warn(primitive_pointer + "/attributes",
                 "mesh '" + mesh_name + "' primitive " + std::to_string(primitive) +
                     " has no TEXCOORD_0: the normal map of its " + material_what(index) + " is left out");
            return std::nullopt;
        }
        const SourcePos pos = at(reference);
        keys->push_back({"scale", tree::number(info.scale, pos)});
        return tree::map(std::move(*keys), pos);
    }

    static std::string material_pointer(int index) { return "/materials/" + std::to_string(index); }

    Node material(int index) {
        const tinygltf::Material& m = model_->materials[static_cast<std::size_t>(index)];
        const std::string what = material_what(index);
        const std::string pointer = material_pointer(index);
        const SourcePos pos = at(pointer);
        const bool first_use = warned_materials_.insert(index).second;  // warnings once per material
        if (first_use) {
            if (m.occlusionTexture.index >= 0) {
                warn(pointer + "/occlusionTexture", what +
                                                        ": its occlusion map is ignored (baked ambient "
                                                        "occlusion: glint's path tracer computes "
                                                        "occlusion itself, and would darken twice)");
            }
            if (m.alphaMode != "OPAQUE") {
                warn(pointer + "/alphaMode", what + ": alphaMode " + m.alphaMode + " is rendered opaque");
            }
            for (const auto& [name, value] : m.extensions) {
                if (name != "KHR_materials_emissive_strength") {
                    warn(pointer + "/extensions/" + json_pointer_token(name),
                         what + ": " + name + " is not read by glint");
                }
            }
        }
        // Emission: glint's emitters reflect nothing, so an emissive material is an emissive surface.
        Rgb emission = rgb_of(m.emissiveFactor, {0, 0, 0});
        const auto strength = m.extensions.find("KHR_materials_emissive_strength");
        if (strength != m.extensions.end() && strength->second.Has("emissiveStrength")) {
            const double s = strength->second.Get("emissiveStrength").GetNumberAsDouble();
            emission = {emission.r * s, emission.g * s, emission.b * s};
        }
        if (emission.r > 0 || emission.g > 0 || emission.b > 0) {
            emits_ = true;
            if (warned_emitters_.insert(index).second) {
                warn(pointer + "/emissiveFactor",
                     what + " emits: glint renders it as an emissive surface, without its base colour");
            }
            Node radiance = tree::color(emission, at(pointer + "/emissiveFactor"));
            if (auto texture = image_texture(m.emissiveTexture, pointer + "/emissiveTexture", emission,
                                             what + "'s emissive map", first_use)) {
                radiance = std::move(*texture);  // the map times the factor (and the strength)
            }
            return tree::map({{"type", tree::text("emissive", pos)}, {"radiance", std::move(radiance)}}, pos);
        }
        const auto& pbr = m.pbrMetallicRoughness;
        const std::string pbr_pointer = pointer + "/pbrMetallicRoughness";
        const auto unit = [](double v) { return std::clamp(v, 0.0, 1.0); };
        const Rgb factor = rgb_of(pbr.baseColorFactor, {1, 1, 1});
        const Rgb base_factor{unit(factor.r), unit(factor.g), unit(factor.b)};
        Node base = tree::color(base_factor, at(pbr_pointer + "/baseColorFactor"));
        if (auto texture = image_texture(pbr.baseColorTexture, pbr_pointer + "/baseColorTexture", base_factor,
                                         what + "'s base colour map", first_use)) {
            base = std::move(*texture);
        }
        // glTF's metallic-roughness map: metallic in its blue channel, roughness in its green, linear,
        // each times its factor.
        const double metallic_factor = unit(pbr.metallicFactor), roughness_factor = unit(pbr.roughnessFactor);
        Node metallic = tree::number(metallic_factor, at(pbr_pointer + "/metallicFactor"));
        Node roughness = tree::number(roughness_factor, at(pbr_pointer + "/roughnessFactor"));
        const std::string map_what = what + "'s metallic-roughness map";
        const std::string map_pointer = pbr_pointer + "/metallicRoughnessTexture";
        if (auto texture = image_texture(pbr.metallicRoughnessTexture, map_pointer, Rgb(metallic_factor),
                                         map_what, first_use, "b", true)) {
            metallic = std::move(*texture);
        }
        // The same texture reference again: its warnings were given just above.
        if (auto texture = image_texture(pbr.metallicRoughnessTexture, map_pointer, Rgb(roughness_factor),
                                         map_what, false, "g", true)) {
            roughness = std::move(*texture);
        }
        return tree::map({{"type", tree::text("principled", pos)},
                          {"base_color", std::move(base)},
                          {"metallic", std::move(metallic)},
                          {"roughness", std::move(roughness)}},
                         pos);
    }

    void add_camera(const tinygltf::Node& node, const std::string& node_pointer, const Matrix& world) {
        if (static_cast<std::size_t>(node.camera) >= model_->cameras.size()) {
            fail(node_pointer + "/camera", "node '" + node.name + "' names camera " +
                                               std::to_string(node.camera) + ", which does not exist");
        }
        const tinygltf::Camera& camera = model_->cameras[static_cast<std::size_t>(node.camera)];
        const bool wanted = options_.camera.empty()
                                ? !camera_
                                : (camera.name == options_.camera || node.name == options_.camera);
        if (!wanted || camera_) {
            return;
        }
        const SourcePos pos = at("/cameras/" + std::to_string(node.camera));
        const Vec3 eye = transform_point(world, {0, 0, 0});
        const Vec3 forward = transform_direction(world, {0, 0, -1});
        const Vec3 up = transform_direction(world, {0, 1, 0});
        std::vector<std::pair<std::string, Node>> keys;
        if (camera.type == "orthographic") {
            keys = {{"type", tree::text("orthographic", pos)},
                    {"height", tree::number(2 * camera.orthographic.ymag, pos)}};
        } else {
            keys = {{"type", tree::text("pinhole", pos)},
                    {"fov", tree::number(degrees(camera.perspective.yfov), pos)}};
        }
        // Where the camera is placed: its node.
        const SourcePos placed = at(node_pointer);
        keys.push_back({"eye", tree::vec3(eye, placed)});
        keys.push_back({"look_at", tree::vec3(eye + forward, placed)});
        keys.push_back({"up", tree::vec3(up, placed)});
        camera_ = tree::map(std::move(keys), pos);
    }

    Node default_camera() {
        if (!options_.camera.empty()) {
            throw SceneError(
                at_, "glTF file '" + path_.string() + "' has no camera named '" + options_.camera + "'");
        }
        warn(scene_pointer(), "the glTF scene has no camera: glint looks at it from +z");
        return tree::framing_camera(bounds_, at(scene_pointer()));
    }

    // Light `index` of KHR_lights_punctual, named at `named_at` (a node's extension), placed by `world`.
    void add_light(int index, const std::string& named_at, const Matrix& world) {
        if (index < 0 || static_cast<std::size_t>(index) >= model_->lights.size()) {
            fail(named_at, "a node names light " + std::to_string(index) + ", which does not exist");
        }
        const std::string pointer = "/extensions/KHR_lights_punctual/lights/" + std::to_string(index);
        const SourcePos pos = at(pointer);
        const tinygltf::Light& light = model_->lights[static_cast<std::size_t>(index)];
        const Rgb colour = rgb_of(light.color, {1, 1, 1});
        const Rgb power{colour.r * light.intensity, colour.g * light.intensity, colour.b * light.intensity};
        const Vec3 position = transform_point(world, {0, 0, 0});
        const Vec3 direction = transform_direction(world, {0, 0, -1});
        if (light.range > 0) {
            warn(pointer + "/range", "light '" + light.name +
                                         "' has a range: glint's lights reach everywhere (the inverse square "
                                         "law alone)");
        }
        if (light.type == "directional") {
            lights_.push_back(tree::map({{"type", tree::text("directional", pos)},
                                         {"direction", tree::vec3(direction, pos)},
                                         {"irradiance", tree::color(power, pos)}},
                                        pos));
        } else if (light.type == "spot") {
            const double outer = std::clamp(degrees(light.spot.outerConeAngle), 1e-3, 90.0);
            const double inner = std::clamp(degrees(light.spot.innerConeAngle), 0.0, outer);
            lights_.push_back(tree::map({{"type", tree::text("spot", pos)},
                                         {"position", tree::vec3(position, pos)},
                                         {"direction", tree::vec3(direction, pos)},
                                         {"intensity", tree::color(power, pos)},
                                         {"angle", tree::number(outer, pos)},
                                         {"falloff_angle", tree::number(inner, pos)}},
                                        pos));
        } else {
            lights_.push_back(tree::map({{"type", tree::text("point", pos)},
                                         {"position", tree::vec3(position, pos)},
                                         {"intensity", tree::color(power, pos)}},
                                        pos));
        }
    }

    std::filesystem::path path_;
    ImportOptions options_;
    SourcePos at_;  // the whole file, for what no element stands for
    PositionedGltf gltf_;
    std::shared_ptr<const GltfFile> file_;
    const tinygltf::Model* model_ = nullptr;
    SceneDesc desc_;
    std::vector<Node> objects_;
    std::vector<Node> lights_;
    std::optional<Node> camera_;
    Bounds3 bounds_;
    bool emits_ = false;
    std::set<int> warned_materials_, warned_emitters_, warned_normal_maps_, skin_warned_;
};

}  // namespace

SceneDesc import_gltf_scene(const std::filesystem::path& path, const ImportOptions& options) {
    return GltfImporter(path, options).run();
}

}  // namespace glint
