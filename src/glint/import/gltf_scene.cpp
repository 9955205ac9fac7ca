// The glTF importer. Every mesh primitive a node places becomes a glint mesh object that refers back
// to the file ({type: mesh, file: model.gltf, gltf_mesh: M, gltf_primitive: P}) with the node's world
// matrix as its transform, so converting a model writes a small YAML next to it rather than copying its
// geometry into text. Materials become `principled` (glTF's own model), emissive ones `emissive`; a
// material's normal map becomes its meshes' `normal_map`.
#include "glint/import/gltf_scene.hpp"

#include <array>
#include <cmath>
#include <set>

#include "glint/core/bounds.hpp"
#include "glint/core/math.hpp"
#include "glint/geometry/mesh_io/gltf_file.hpp"
#include "glint/geometry/mesh_io/tinygltf.hpp"
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
        : path_(path), options_(options), at_(tree::file_position(path.string())) {
        file_ = load_gltf_file(path, at_);
        model_ = file_->model.get();
    }

    SceneDesc run() {
        desc_.base_dir = path_.parent_path();
        for (const std::string& extension : model_->extensionsUsed) {
            if (extension != "KHR_lights_punctual" && extension != "KHR_materials_emissive_strength") {
                warn("the extension " + extension + " is not read by glint");
            }
        }
        for (int root : root_nodes()) {
            visit(root, kIdentity, 0);
        }
        std::vector<std::pair<std::string, Node>> root;
        root.push_back({"render", tree::map({{"integrator", tree::text("path", at_)}}, at_)});
        root.push_back({"camera", camera_ ? std::move(*camera_) : default_camera()});
        root.push_back({"objects", tree::list(std::move(objects_), at_)});
        if (lights_.empty() && !emits_) {
            warn(
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
    void warn(const std::string& message) { desc_.warnings.push_back({at_, message}); }

    // The nodes of the default scene (or the first), or, with no scene, every node no other names.
    std::vector<int> root_nodes() const {
        if (!model_->scenes.empty()) {
            const std::size_t scene =
                model_->defaultScene >= 0 &&
                        static_cast<std::size_t>(model_->defaultScene) < model_->scenes.size()
                    ? static_cast<std::size_t>(model_->defaultScene)
                    : 0;
            return model_->scenes[scene].nodes;
        }
        std::set<int> children;
        for (const tinygltf::Node& node : model_->nodes) {
            children.insert(node.children.begin(), node.children.end());
        }
        std::vector<int> roots;
        for (int i = 0; i < static_cast<int>(model_->nodes.size()); ++i) {
            if (!children.count(i)) {
                roots.push_back(i);
            }
        }
        return roots;
    }

    void visit(int index, const Matrix& parent, int depth) {
        // A node hierarchy is a tree, at most as deep as there are nodes; a cycle is an error.
        if (index < 0 || static_cast<std::size_t>(index) >= model_->nodes.size()) {
            throw SceneError(at_, "glTF file '" + path_.string() + "': a scene names node " +
                                      std::to_string(index) + ", which does not exist");
        }
        if (depth > static_cast<int>(model_->nodes.size()) || depth > 1000) {
            throw SceneError(at_, "glTF file '" + path_.string() +
                                      "': its nodes form a cycle or nest deeper than " + "1000 levels");
        }
        const tinygltf::Node& node = model_->nodes[static_cast<std::size_t>(index)];
        const Matrix world = multiply(parent, local_matrix(node));
        if (node.mesh >= 0) {
            add_mesh(node, world);
        }
        if (node.camera >= 0) {
            add_camera(node, world);
        }
        const auto light = node.extensions.find("KHR_lights_punctual");
        if (light != node.extensions.end() && light->second.Has("light")) {
            add_light(light->second.Get("light").GetNumberAsInt(), world);
        }
        if (node.skin >= 0 && skin_warned_.insert(node.skin).second) {
            warn("node '" + node.name + "' is skinned: glint renders its mesh in the rest pose");
        }
        for (int child : node.children) {
            visit(child, world, depth + 1);
        }
    }

    void add_mesh(const tinygltf::Node& node, const Matrix& world) {
        if (static_cast<std::size_t>(node.mesh) >= model_->meshes.size()) {
            throw SceneError(at_, "glTF file '" + path_.string() + "': node '" + node.name + "' names mesh " +
                                      std::to_string(node.mesh) + ", which does not exist");
        }
        const tinygltf::Mesh& mesh = model_->meshes[static_cast<std::size_t>(node.mesh)];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = mesh.primitives[p];
            const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
            if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
                mode != TINYGLTF_MODE_TRIANGLE_FAN) {
                warn("mesh '" + mesh.name + "' primitive " + std::to_string(p) +
                     " is made of points or lines: glint renders surfaces only, so it is left out");
                continue;
            }
            // The bounds, for a camera when the file has none.
            const MeshData data = gltf_primitive_mesh(*file_, node.mesh, static_cast<int>(p), at_);
            for (const Vec3& position : data.positions) {
                bounds_.grow(transform_point(world, position));
            }
            std::vector<std::pair<std::string, Node>> object = {
                {"type", tree::text("mesh", at_)},
                {"file", tree::text(path_.filename().generic_string(), at_)},
                {"gltf_mesh", tree::number(node.mesh, at_)},
                {"gltf_primitive", tree::number(static_cast<double>(p), at_)}};
            if (world != kIdentity) {
                object.push_back(
                    {"transform",
                     tree::map(
                         {{"matrix", tree::numbers(std::vector<double>(world.begin(), world.end()), at_)}},
                         at_)});
            }
            if (primitive.material >= 0 &&
                static_cast<std::size_t>(primitive.material) < model_->materials.size()) {
                if (auto normal_map = normal_map_of(primitive.material, data, mesh.name, p)) {
                    object.push_back({"normal_map", std::move(*normal_map)});
                }
                object.push_back({"material", material(primitive.material)});
            }
            objects_.push_back(tree::map(std::move(object), at_));
        }
    }

    using Keys = std::vector<std::pair<std::string, Node>>;

    // The keys that name the image of a glTF texture (`file`, and `gltf_image` for one stored in the
    // model), or nothing when the texture or its image does not exist. `extensions` are the texture
    // reference's own (KHR_texture_transform is one). What glint leaves out is warned about when `warn_about`
    // (once per material, not at each of its uses).
    std::optional<Keys> image_keys(int texture, int tex_coord, const tinygltf::ExtensionMap& extensions,
                                   const std::string& what, bool warn_about) {
        if (texture < 0 || static_cast<std::size_t>(texture) >= model_->textures.size()) {
            return std::nullopt;
        }
        const int source = model_->textures[static_cast<std::size_t>(texture)].source;
        if (source < 0 || static_cast<std::size_t>(source) >= model_->images.size()) {
            return std::nullopt;
        }
        const std::string& uri = model_->images[static_cast<std::size_t>(source)].uri;
        if (tex_coord != 0 && warn_about) {
            warn(what + " uses TEXCOORD_" + std::to_string(tex_coord) + ": glint reads TEXCOORD_0 only");
        }
        if (extensions.count("KHR_texture_transform") && warn_about) {
            warn(what + " has a KHR_texture_transform: glint maps it without the transform");
        }
        if (uri.empty() || uri.rfind("data:", 0) == 0) {  // stored in the model: decoded from it
            return Keys{{"file", tree::text(path_.filename().generic_string(), at_)},
                        {"gltf_image", tree::number(source, at_)}};
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
        return Keys{{"file", tree::text(file, at_)}};
    }

    // An image texture {type: image, file, …} of a glTF texture reference, times `factor` per channel;
    // `channel` r, g or b for a number stored in one channel, `linear` for data rather than colour.
    template <class TextureInfo>
    std::optional<Node> image_texture(const TextureInfo& info, const Rgb& factor, const std::string& what,
                                      bool warn_about, const std::string& channel = "", bool linear = false) {
        std::optional<Keys> keys = image_keys(info.index, info.texCoord, info.extensions, what, warn_about);
        if (!keys) {
            return std::nullopt;
        }
        keys->insert(keys->begin(), {"type", tree::text("image", at_)});
        if (!channel.empty()) {
            keys->push_back({"channel", tree::text(channel, at_)});
        }
        if (linear) {
            keys->push_back({"encoding", tree::text("linear", at_)});
        }
        if (factor != Rgb(1.0)) {
            const bool grey = factor.r == factor.g && factor.g == factor.b;
            keys->push_back({"scale", grey ? tree::number(factor.r, at_) : tree::color(factor, at_)});
        }
        return tree::map(std::move(*keys), at_);
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
                                      std::size_t primitive) {
        const tinygltf::NormalTextureInfo& info =
            model_->materials[static_cast<std::size_t>(index)].normalTexture;
        const bool first_use = warned_normal_maps_.insert(index).second;
        std::optional<Keys> keys = image_keys(info.index, info.texCoord, info.extensions,
                                              material_what(index) + "'s normal map", first_use);
        if (!keys) {
            return std::nullopt;
        }
        if (data.uvs.empty()) {
            warn("mesh '" + mesh_name + "' primitive " + std::to_string(primitive) +
                 " has no TEXCOORD_0: the normal map of its " + material_what(index) + " is left out");
            return std::nullopt;
        }
        keys->push_back({"scale", tree::number(info.scale, at_)});
        return tree::map(std::move(*keys), at_);
    }

    Node material(int index) {
        const tinygltf::Material& m = model_->materials[static_cast<std::size_t>(index)];
        const std::string what = material_what(index);
        const bool first_use = warned_materials_.insert(index).second;  // warnings once per material
        if (first_use) {
            if (m.occlusionTexture.index >= 0) {
                warn(what +
                     ": its occlusion map is ignored (baked ambient occlusion: glint's path tracer computes "
                     "occlusion itself, and would darken twice)");
            }
            if (m.alphaMode != "OPAQUE") {
                warn(what + ": alphaMode " + m.alphaMode + " is rendered opaque");
            }
            for (const auto& [name, value] : m.extensions) {
                if (name != "KHR_materials_emissive_strength") {
                    warn(what + ": " + name + " is not read by glint");
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
                warn(what + " emits: glint renders it as an emissive surface, without its base colour");
            }
            Node radiance = tree::color(emission, at_);
            if (auto texture =
                    image_texture(m.emissiveTexture, emission, what + "'s emissive map", first_use)) {
                radiance = std::move(*texture);  // the map times the factor (and the strength)
            }
            return tree::map({{"type", tree::text("emissive", at_)}, {"radiance", std::move(radiance)}}, at_);
        }
        const auto& pbr = m.pbrMetallicRoughness;
        const auto unit = [](double v) { return std::clamp(v, 0.0, 1.0); };
        const Rgb factor = rgb_of(pbr.baseColorFactor, {1, 1, 1});
        const Rgb base_factor{unit(factor.r), unit(factor.g), unit(factor.b)};
        Node base = tree::color(base_factor, at_);
        if (auto texture =
                image_texture(pbr.baseColorTexture, base_factor, what + "'s base colour map", first_use)) {
            base = std::move(*texture);
        }
        // glTF's metallic-roughness map: metallic in its blue channel, roughness in its green, linear,
        // each times its factor.
        const double metallic_factor = unit(pbr.metallicFactor), roughness_factor = unit(pbr.roughnessFactor);
        Node metallic = tree::number(metallic_factor, at_);
        Node roughness = tree::number(roughness_factor, at_);
        const std::string map_what = what + "'s metallic-roughness map";
        if (auto texture = image_texture(pbr.metallicRoughnessTexture, Rgb(metallic_factor), map_what,
                                         first_use, "b", true)) {
            metallic = std::move(*texture);
        }
        // The same texture reference again: its warnings were given just above.
        if (auto texture = image_texture(pbr.metallicRoughnessTexture, Rgb(roughness_factor), map_what, false,
                                         "g", true)) {
            roughness = std::move(*texture);
        }
        return tree::map({{"type", tree::text("principled", at_)},
                          {"base_color", std::move(base)},
                          {"metallic", std::move(metallic)},
                          {"roughness", std::move(roughness)}},
                         at_);
    }

    void add_camera(const tinygltf::Node& node, const Matrix& world) {
        if (static_cast<std::size_t>(node.camera) >= model_->cameras.size()) {
            throw SceneError(at_, "glTF file '" + path_.string() + "': node '" + node.name +
                                      "' names camera " + std::to_string(node.camera) +
                                      ", which does not exist");
        }
        const tinygltf::Camera& camera = model_->cameras[static_cast<std::size_t>(node.camera)];
        const bool wanted = options_.camera.empty()
                                ? !camera_
                                : (camera.name == options_.camera || node.name == options_.camera);
        if (!wanted || camera_) {
            return;
        }
        const Vec3 eye = transform_point(world, {0, 0, 0});
        const Vec3 forward = transform_direction(world, {0, 0, -1});
        const Vec3 up = transform_direction(world, {0, 1, 0});
        std::vector<std::pair<std::string, Node>> keys;
        if (camera.type == "orthographic") {
            keys = {{"type", tree::text("orthographic", at_)},
                    {"height", tree::number(2 * camera.orthographic.ymag, at_)}};
        } else {
            keys = {{"type", tree::text("pinhole", at_)},
                    {"fov", tree::number(degrees(camera.perspective.yfov), at_)}};
        }
        keys.push_back({"eye", tree::vec3(eye, at_)});
        keys.push_back({"look_at", tree::vec3(eye + forward, at_)});
        keys.push_back({"up", tree::vec3(up, at_)});
        camera_ = tree::map(std::move(keys), at_);
    }

    Node default_camera() {
        if (!options_.camera.empty()) {
            throw SceneError(
                at_, "glTF file '" + path_.string() + "' has no camera named '" + options_.camera + "'");
        }
        warn("the glTF scene has no camera: glint looks at it from +z");
        return tree::framing_camera(bounds_, at_);
    }

    void add_light(int index, const Matrix& world) {
        if (index < 0 || static_cast<std::size_t>(index) >= model_->lights.size()) {
            throw SceneError(at_, "glTF file '" + path_.string() + "': a node names light " +
                                      std::to_string(index) + ", which does not exist");
        }
        const tinygltf::Light& light = model_->lights[static_cast<std::size_t>(index)];
        const Rgb colour = rgb_of(light.color, {1, 1, 1});
        const Rgb power{colour.r * light.intensity, colour.g * light.intensity, colour.b * light.intensity};
        const Vec3 position = transform_point(world, {0, 0, 0});
        const Vec3 direction = transform_direction(world, {0, 0, -1});
        if (light.range > 0) {
            warn("light '" + light.name +
                 "' has a range: glint's lights reach everywhere (the inverse square "
                 "law alone)");
        }
        if (light.type == "directional") {
            lights_.push_back(tree::map({{"type", tree::text("directional", at_)},
                                         {"direction", tree::vec3(direction, at_)},
                                         {"irradiance", tree::color(power, at_)}},
                                        at_));
        } else if (light.type == "spot") {
            const double outer = std::clamp(degrees(light.spot.outerConeAngle), 1e-3, 90.0);
            const double inner = std::clamp(degrees(light.spot.innerConeAngle), 0.0, outer);
            lights_.push_back(tree::map({{"type", tree::text("spot", at_)},
                                         {"position", tree::vec3(position, at_)},
                                         {"direction", tree::vec3(direction, at_)},
                                         {"intensity", tree::color(power, at_)},
                                         {"angle", tree::number(outer, at_)},
                                         {"falloff_angle", tree::number(inner, at_)}},
                                        at_));
        } else {
            lights_.push_back(tree::map({{"type", tree::text("point", at_)},
                                         {"position", tree::vec3(position, at_)},
                                         {"intensity", tree::color(power, at_)}},
                                        at_));
        }
    }

    std::filesystem::path path_;
    ImportOptions options_;
    SourcePos at_;
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
