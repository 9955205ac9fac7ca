// The pbrt-v4 importer: the statements of a pbrt-v4 scene (pbrt_parser.cpp) run through pbrt's graphics
// state — the current transform, material, area light and orientation, pushed and popped by
// AttributeBegin/End — into glint's tree: one object per shape with its transform as a matrix,
// materials by name, lights, the camera and the render settings. docs/import-pbrt.md is the mapping.
//
// Handedness. pbrt's camera space is left-handed (x right, y up, z forward), so a camera placed with
// LookAt (a transform of determinant > 0) sees the world as a mirror image of what glint's camera,
// given the same eye, target and up, would see. glint's camera cannot mirror; so the importer mirrors
// the world instead (x → −x, applied to every object, light and the camera) whenever the camera's
// transform keeps handedness, and leaves it as it is when the scene already mirrors the camera (the
// `Scale -1 1 1` exporters write before LookAt). Either way the image is pbrt's, not its mirror image.
#include "glint/import/pbrt_scene.hpp"

#include <cmath>
#include <map>
#include <optional>

#include "glint/core/math.hpp"
#include "glint/core/transform.hpp"
#include "glint/import/pbrt_convert.hpp"
#include "glint/import/pbrt_parser.hpp"
#include "glint/import/scene_tree.hpp"

namespace glint {
namespace {

namespace tree = scene_tree;
using pbrt::Params;
using pbrt::SpectrumUse;

// AttributeBegin inside AttributeBegin …: far beyond any real scene, and each level copies the state.
constexpr std::size_t kMaxAttributeNesting = 1024;
// Room kept under glint's limit on a scene's values for the camera, materials and lights.
constexpr std::size_t kValuesKeptForTheRest = 20'000;

struct MaterialRef {
    enum class Kind { Default, Anonymous, Named } kind = Kind::Default;
    std::size_t index = 0;  // Anonymous: into Importer::anonymous_materials_
    std::string name;       // Named
    SourcePos pos;          // of the Material or NamedMaterial statement
};

struct AreaLight {
    Node emissive;  // the glint material of the emitting shapes
    SourcePos pos;
};

struct GraphicsState {
    Transform ctm;  // object space → pbrt's world space
    MaterialRef material;
    std::optional<AreaLight> area_light;
    bool reverse_orientation = false;
    bool end_transform_only = false;  // after ActiveTransform EndTime: transforms of the motion's end
};

// What AttributeBegin, TransformBegin, ObjectBegin and an Import push.
struct Pushed {
    GraphicsState state;
    std::string opened_by;  // the directive, to match its end
    SourcePos pos;
};

// A shape converted, in its own space, waiting for the end to be given its material and transform.
struct PendingShape {
    Node shape;
    Transform to_world;  // object → pbrt's world
    MaterialRef material;
    std::optional<Node> emissive;
    std::size_t values = 0;
};

struct MaterialDef {
    PbrtStatement statement;
    std::string type;
};

struct Entity {  // Camera, Film, Sampler, Integrator, PixelFilter: their statement, if given
    std::optional<PbrtStatement> statement;
    std::string type() const { return statement ? statement->strings.front() : ""; }
};

Transform checked_transform(const Transform::Matrix& m, const SourcePos& pos, const std::string& what) {
    const std::optional<Transform> t = Transform::from_matrix(m);
    if (!t) {
        throw SceneError(pos, what + " cannot be inverted (it flattens space)");
    }
    return *t;
}

// pbrt's Transform and ConcatTransform give the 4×4 matrix column by column.
Transform matrix_transform(const PbrtStatement& s) {
    const std::vector<double>& m = s.numbers;
    if (m[3] != 0 || m[7] != 0 || m[11] != 0 || m[15] == 0) {
        throw SceneError(s.pos, s.directive +
                                    ": glint takes affine transforms only (the last row, the 4th, "
                                    "8th, 12th and 16th numbers, must be 0 0 0 w with w ≠ 0)");
    }
    const double w = m[15];
    return checked_transform({{{m[0] / w, m[4] / w, m[8] / w, m[12] / w},
                               {m[1] / w, m[5] / w, m[9] / w, m[13] / w},
                               {m[2] / w, m[6] / w, m[10] / w, m[14] / w}}},
                             s.pos, s.directive);
}

// pbrt's LookAt: the camera-from-world transform of a camera at `eye` looking at `target`, its +y
// towards `up`, and its +x = up × forward (pbrt's left-handed camera space).
Transform look_at(const PbrtStatement& s) {
    const std::vector<double>& n = s.numbers;
    const Vec3 eye{n[0], n[1], n[2]}, target{n[3], n[4], n[5]}, up{n[6], n[7], n[8]};
    if (length(target - eye) == 0 || length(up) == 0) {
        throw SceneError(s.pos, "LookAt needs an eye apart from the point looked at, and a non-zero up");
    }
    const Vec3 forward = normalize(target - eye);
    const Vec3 side = cross(normalize(up), forward);
    if (length(side) < 1e-9) {
        throw SceneError(s.pos, "LookAt's up vector is parallel to the direction looked in");
    }
    const Vec3 right = normalize(side);
    const Vec3 new_up = cross(forward, right);
    const Transform world_from_camera = checked_transform({{{right.x, new_up.x, forward.x, eye.x},
                                                            {right.y, new_up.y, forward.y, eye.y},
                                                            {right.z, new_up.z, forward.z, eye.z}}},
                                                          s.pos, "LookAt");
    return world_from_camera.inverse();
}

double determinant(const Transform& t) {
    return dot(cross(t.vector({1, 0, 0}), t.vector({0, 1, 0})), t.vector({0, 0, 1}));
}

bool is_identity(const Transform& t) {
    const Transform::Matrix& m = t.matrix();
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 4; ++j) {
            if (m[i][j] != (i == j ? 1.0 : 0.0)) {
                return false;
            }
        }
    }
    return true;
}

Node matrix_node(const Transform& t, const SourcePos& pos) {
    std::vector<double> numbers;
    for (const auto& row : t.matrix()) {
        numbers.insert(numbers.end(), row.begin(), row.end());
    }
    return tree::map({{"matrix", tree::numbers(numbers, pos)}}, pos);
}

class Importer {
  public:
    Importer(std::filesystem::path search_dir, std::string display_root)
        : search_dir_(std::move(search_dir)), whole_file_(tree::file_position(display_root)) {}

    void statement(PbrtStatement& s);
    SceneDesc finish();

  private:
    // Directives of the world block (after WorldBegin) and of the options block (before it).
    void require_world(const PbrtStatement& s) const {
        if (!in_world_) {
            throw SceneError(s.pos, s.directive + " is allowed only after WorldBegin");
        }
    }
    void require_options(const PbrtStatement& s) const {
        if (in_world_) {
            throw SceneError(s.pos, s.directive + " is allowed only before WorldBegin");
        }
    }
    void warn(const SourcePos& pos, const std::string& message) { warnings_.push_back({pos, message}); }

    void apply(const PbrtStatement& s, const Transform& t, bool replace);
    void push(const PbrtStatement& s);
    void pop(const PbrtStatement& s);
    void decide_mirror();
    Transform to_glint(const Transform& to_pbrt_world) const { return to_pbrt_world.then(mirror_); }

    void shape(const PbrtStatement& s);
    void object_instance(const PbrtStatement& s);
    void area_light(const PbrtStatement& s);
    void light(const PbrtStatement& s);
    void add_shape(PendingShape shape, const SourcePos& pos);

    Node render_node();
    Node camera_node();
    Node materials_node(std::vector<Node>& objects);
    std::optional<Node> material_named(const std::string& name, const SourcePos& used_at, int depth);

    std::filesystem::path search_dir_;
    SourcePos whole_file_;
    std::vector<SceneWarning> warnings_;

    GraphicsState state_;
    std::vector<Pushed> stack_;
    std::map<std::string, Transform> coordinate_systems_;
    bool in_world_ = false;
    Transform mirror_;  // identity, or x → −x (see the top of the file)
    bool mirrored_ = false;

    Entity camera_, film_, sampler_, integrator_, filter_;
    Transform camera_from_world_;

    pbrt::Textures textures_;
    std::map<std::string, MaterialDef> named_materials_;
    std::vector<MaterialDef> anonymous_materials_;

    std::vector<PendingShape> shapes_;
    std::map<std::string, std::vector<PendingShape>> objects_;
    std::optional<std::string> defining_object_;
    std::size_t values_ = 0;

    std::vector<Node> lights_;
    bool has_environment_ = false;
};

void Importer::apply(const PbrtStatement& s, const Transform& t, bool replace) {
    if (state_.end_transform_only) {
        warn(s.pos, "glint has no motion blur: this transform of the motion's end is left out");
        return;
    }
    state_.ctm = replace ? t : t.then(state_.ctm);  // pbrt post-multiplies: ctm ← ctm · t
}

void Importer::push(const PbrtStatement& s) {
    if (stack_.size() >= kMaxAttributeNesting) {
        throw SceneError(s.pos,
                         s.directive + " nested more than " + std::to_string(kMaxAttributeNesting) + " deep");
    }
    stack_.push_back({state_, s.directive, s.pos});
}

void Importer::pop(const PbrtStatement& s) {
    const std::string opener = s.directive == "AttributeEnd"   ? "AttributeBegin"
                               : s.directive == "TransformEnd" ? "TransformBegin"
                               : s.directive == "ObjectEnd"    ? "ObjectBegin"
                                                               : "ImportBegin";
    if (opener == "ImportBegin") {
        // The imported file's state ends with it, whatever it left open.
        while (!stack_.empty() && stack_.back().opened_by != "ImportBegin") {
            warn(stack_.back().pos, stack_.back().opened_by + " is not closed in its imported file");
            stack_.pop_back();
        }
    }
    if (stack_.empty() || stack_.back().opened_by != opener) {
        if (stack_.empty()) {
            warn(s.pos, s.directive + " without a " + opener + " is ignored (as pbrt-v4 does)");
            return;
        }
        throw SceneError(s.pos, s.directive + " closes " + stack_.back().opened_by + " (line " +
                                    std::to_string(stack_.back().pos.line) + "), not a " + opener);
    }
    if (opener == "TransformBegin") {
        state_.ctm = stack_.back().state.ctm;  // TransformBegin keeps only the transform
    } else {
        state_ = stack_.back().state;
    }
    stack_.pop_back();
}

void Importer::decide_mirror() {
    const Transform world_from_camera = camera_from_world_.inverse();
    mirrored_ = determinant(world_from_camera) > 0;
    mirror_ = mirrored_ ? *Transform::scale({-1, 1, 1}) : Transform();
}

void Importer::statement(PbrtStatement& s) {
    const std::string& d = s.directive;
    const std::vector<double>& n = s.numbers;
    if (d == "Translate") {
        apply(s, Transform::translate({n[0], n[1], n[2]}), false);
    } else if (d == "Scale") {
        const std::optional<Transform> scale = Transform::scale({n[0], n[1], n[2]});
        if (!scale) {
            throw SceneError(s.pos, "Scale by zero flattens space: glint cannot invert it");
        }
        apply(s, *scale, false);
    } else if (d == "Rotate") {
        if (length(Vec3{n[1], n[2], n[3]}) == 0) {
            throw SceneError(s.pos, "Rotate about a zero axis");
        }
        apply(s, Transform::rotate({n[1], n[2], n[3]}, n[0]), false);
    } else if (d == "LookAt") {
        apply(s, look_at(s), false);
    } else if (d == "Transform") {
        apply(s, matrix_transform(s), true);
    } else if (d == "ConcatTransform") {
        apply(s, matrix_transform(s), false);
    } else if (d == "Identity") {
        apply(s, Transform(), true);
    } else if (d == "CoordinateSystem") {
        coordinate_systems_[s.strings[0]] = state_.ctm;
    } else if (d == "CoordSysTransform") {
        const auto found = coordinate_systems_.find(s.strings[0]);
        if (found == coordinate_systems_.end()) {
            warn(s.pos, "no coordinate system named '" + s.strings[0] + "': ignored (as pbrt-v4 does)");
        } else {
            apply(s, found->second, true);
        }
    } else if (d == "ActiveTransform") {
        const std::string& which = s.strings[0];
        if (which != "All" && which != "StartTime" && which != "EndTime") {
            throw SceneError(s.pos, "ActiveTransform takes All, StartTime or EndTime, not '" + which + "'");
        }
        if (which != "All") {
            warn(s.pos, "glint has no motion blur: shapes keep their transform at the start time");
        }
        state_.end_transform_only = which == "EndTime";
    } else if (d == "TransformTimes") {
        warn(s.pos, "glint has no motion blur: TransformTimes is left out");
    } else if (d == "AttributeBegin" || d == "TransformBegin" || d == "ImportBegin") {
        push(s);
    } else if (d == "AttributeEnd" || d == "TransformEnd" || d == "ImportEnd") {
        pop(s);
    } else if (d == "ReverseOrientation") {
        state_.reverse_orientation = !state_.reverse_orientation;
    } else if (d == "WorldBegin") {
        require_options(s);
        in_world_ = true;
        state_.ctm = Transform();
        state_.end_transform_only = false;
        coordinate_systems_["world"] = Transform();
        decide_mirror();
    } else if (d == "WorldEnd") {
        // pbrt-v3's end of the world block; pbrt-v4 ignores it too.
    } else if (d == "Camera") {
        require_options(s);
        camera_.statement = s;
        camera_from_world_ = state_.ctm;
        coordinate_systems_["camera"] = state_.ctm.inverse();
    } else if (d == "Film" || d == "Sampler" || d == "Integrator" || d == "PixelFilter") {
        require_options(s);
        Entity& entity = d == "Film"         ? film_
                         : d == "Sampler"    ? sampler_
                         : d == "Integrator" ? integrator_
                                             : filter_;
        entity.statement = s;
    } else if (d == "Accelerator") {
        // glint builds its own BVH; the choice of accelerator does not change the image.
        require_options(s);
    } else if (d == "ColorSpace") {
        if (s.strings[0] != "srgb") {
            warn(s.pos, "glint renders in linear sRGB: colours of the '" + s.strings[0] +
                            "' space are taken as sRGB");
        }
    } else if (d == "Option") {
        if (s.params.size() != 1) {
            throw SceneError(s.pos, "Option takes one parameter: Option \"type name\" value");
        }
        warn(s.pos, "the option '" + s.params.front().name + "' is not read by glint");
    } else if (d == "Attribute") {
        warn(s.pos, "glint does not take Attribute's default parameters: they are left out");
    } else if (d == "MakeNamedMedium" || d == "MediumInterface") {
        warn(s.pos, "glint has no participating media: " + d + " is left out");
    } else if (d == "Texture") {
        require_world(s);
        Params params(s, warnings_);
        pbrt::define_texture(params, textures_);
    } else if (d == "Material") {
        require_world(s);
        anonymous_materials_.push_back({s, s.strings[0]});
        state_.material = {MaterialRef::Kind::Anonymous, anonymous_materials_.size() - 1, "", s.pos};
    } else if (d == "MakeNamedMaterial") {
        require_world(s);
        const std::string& name = s.strings[0];
        if (named_materials_.count(name) != 0) {
            throw SceneError(s.pos, "material '" + name + "' is defined again (pbrt-v4 refuses that too)");
        }
        Params params(s, warnings_);
        named_materials_[name] = {s, params.text("type", "")};
        if (named_materials_[name].type.empty()) {
            throw SceneError(s.pos, "MakeNamedMaterial '" + name + "' needs \"string type\"");
        }
    } else if (d == "NamedMaterial") {
        require_world(s);
        state_.material = {MaterialRef::Kind::Named, 0, s.strings[0], s.pos};
    } else if (d == "AreaLightSource") {
        require_world(s);
        area_light(s);
    } else if (d == "LightSource") {
        require_world(s);
        light(s);
    } else if (d == "Shape") {
        require_world(s);
        shape(s);
    } else if (d == "ObjectBegin") {
        require_world(s);
        if (defining_object_) {
            throw SceneError(s.pos,
                             "ObjectBegin inside the definition of object '" + *defining_object_ + "'");
        }
        if (objects_.count(s.strings[0]) != 0) {
            throw SceneError(s.pos,
                             "object '" + s.strings[0] + "' is defined again (pbrt-v4 refuses that too)");
        }
        push(s);
        defining_object_ = s.strings[0];
        objects_[s.strings[0]];
    } else if (d == "ObjectEnd") {
        if (!defining_object_) {
            throw SceneError(s.pos, "ObjectEnd without ObjectBegin");
        }
        pop(s);
        defining_object_.reset();
    } else if (d == "ObjectInstance") {
        require_world(s);
        object_instance(s);
    } else {
        throw SceneError(s.pos,
                         "glint does not read the directive '" + d + "'");  // the parser knows them all
    }
}

void Importer::add_shape(PendingShape shape, const SourcePos& pos) {
    if (values_ + shape.values + kValuesKeptForTheRest > kMaxSceneValues) {
        throw SceneError(pos, "the scene takes more than glint's limit of " +
                                  std::to_string(kMaxSceneValues) +
                                  " values here (instances are expanded: each copies its shapes)");
    }
    values_ += shape.values;
    if (defining_object_) {
        objects_[*defining_object_].push_back(std::move(shape));
    } else {
        shapes_.push_back(std::move(shape));
    }
}

void Importer::shape(const PbrtStatement& s) {
    Params params(s, warnings_);
    pbrt::ShapeContext context;
    context.reverse_orientation = state_.reverse_orientation;
    context.emits = state_.area_light.has_value();
    const std::size_t used = values_ + kValuesKeptForTheRest;
    context.values_left = used < kMaxSceneValues ? kMaxSceneValues - used : 0;
    std::vector<Node> nodes = pbrt::convert_shape(params, s.strings[0], context);
    for (Node& node : nodes) {
        PendingShape pending{std::move(node), state_.ctm, state_.material, std::nullopt, 0};
        if (state_.area_light) {
            if (defining_object_) {
                warn(s.pos,
                     "an area light inside an object (ObjectBegin) is not emitted (pbrt-v4 refuses "
                     "area lights in instances too)");
            } else {
                pending.emissive = state_.area_light->emissive;
            }
        }
        pending.values = pbrt::count_nodes(pending.shape) + 20;  // and its transform and material
        add_shape(std::move(pending), s.pos);
    }
}

void Importer::object_instance(const PbrtStatement& s) {
    if (defining_object_) {
        throw SceneError(s.pos, "ObjectInstance inside the definition of object '" + *defining_object_ + "'");
    }
    const auto found = objects_.find(s.strings[0]);
    if (found == objects_.end()) {
        std::vector<std::string> names;
        for (const auto& [name, shapes] : objects_) {
            names.push_back(name);
        }
        throw SceneError(s.pos, unknown_name_message("object", s.strings[0], names, "defined"));
    }
    // Each instance is the object's shapes, each placed by its own transform then the instance's.
    for (const PendingShape& prototype : found->second) {
        PendingShape copy = prototype;
        copy.to_world = prototype.to_world.then(state_.ctm);
        add_shape(std::move(copy), s.pos);
    }
}

void Importer::area_light(const PbrtStatement& s) {
    Params params(s, warnings_);
    if (s.strings[0] != "diffuse") {
        throw SceneError(s.pos, "unknown area light '" + s.strings[0] + "' (pbrt-v4 has only \"diffuse\")");
    }
    // pbrt-v4 scales an RGB L so that it renders as that RGB (its spectrum over the colour space's
    // illuminant, divided by the illuminant's luminance): glint's radiance is then L × scale as given.
    std::optional<Node> radiance = pbrt::color_param(params, "L", SpectrumUse::Illuminant, textures_);
    const double scale = params.number("scale", 1);
    const bool two_sided = params.boolean("twosided", false);
    if (params.has("filename")) {
        params.text("filename", "");
        warn(s.pos, "glint's emissive surfaces take one radiance: the image 'filename' is left out");
    }
    params.warn_unread("the area light");
    warn(s.pos,
         "glint's emissive surfaces reflect no light: the material of the shapes this lights is "
         "left out");
    state_.area_light = AreaLight{tree::map({{"type", tree::text("emissive", s.pos)},
                                             {"radiance", radiance ? *radiance : tree::number(1, s.pos)},
                                             {"scale", tree::number(scale, s.pos)},
                                             {"two_sided", tree::boolean(two_sided, s.pos)}},
                                            s.pos),
                                  s.pos};
}

void Importer::light(const PbrtStatement& s) {
    Params params(s, warnings_);
    const std::string& type = s.strings[0];
    const SourcePos& pos = s.pos;
    const Transform to_glint_world = to_glint(state_.ctm);
    const double scale = params.number("scale", 1);
    const auto light_color = [&](const char* key) {
        std::optional<Node> c = pbrt::color_param(params, key, SpectrumUse::Illuminant, textures_);
        return c ? *c : tree::number(1, pos);
    };
    const Vec3 from = params.vec3("from").value_or(Vec3{0, 0, 0});
    Node light;
    if (type == "point" || type == "goniometric" || type == "projection") {
        if (type != "point") {
            warn(pos, "glint has no " + type + " light: rendered as a point light of the same intensity");
            for (const PbrtParam& param : s.params) {
                param.used = param.used || param.name == "filename" || param.name == "fov";
            }
        }
        light = tree::map({{"type", tree::text("point", pos)},
                           {"position", tree::vec3(to_glint_world.point(from), pos)},
                           {"intensity", light_color("I")},
                           {"scale", tree::number(scale, pos)}},
                          pos);
    } else if (type == "spot") {
        const Vec3 to = params.vec3("to").value_or(Vec3{0, 0, 1});
        const double cone = params.number("coneangle", 30), delta = params.number("conedeltaangle", 5);
        if (length(to - from) == 0) {
            throw SceneError(pos, "the spot light's 'from' and 'to' are the same point");
        }
        light = tree::map({{"type", tree::text("spot", pos)},
                           {"position", tree::vec3(to_glint_world.point(from), pos)},
                           {"direction", tree::vec3(to_glint_world.vector(to - from), pos)},
                           {"intensity", light_color("I")},
                           {"scale", tree::number(scale, pos)},
                           {"angle", tree::number(cone, pos)},
                           {"falloff_angle", tree::number(std::max(cone - delta, 0.0), pos)}},
                          pos);
    } else if (type == "distant") {
        const Vec3 to = params.vec3("to").value_or(Vec3{0, 0, 1});
        if (length(to - from) == 0) {
            throw SceneError(pos, "the distant light's 'from' and 'to' are the same point");
        }
        // pbrt's light arrives from `from` towards `to`; glint's direction is the way it travels.
        light = tree::map({{"type", tree::text("directional", pos)},
                           {"direction", tree::vec3(to_glint_world.vector(to - from), pos)},
                           {"irradiance", light_color("L")},
                           {"scale", tree::number(scale, pos)}},
                          pos);
    } else if (type == "infinite") {
        if (has_environment_) {
            warn(pos, "glint takes one environment light: this second infinite light is left out");
            for (const PbrtParam& param : s.params) {
                param.used = true;
            }
            return;
        }
        has_environment_ = true;
        const std::string file = params.text("filename", "");
        if (!file.empty()) {
            warn(pos,
                 "glint reads environment maps as equirectangular (latitude-longitude); pbrt-v4's are "
                 "equal-area octahedral (square): the map is not resampled, so it is seen wrongly");
            light = tree::map({{"type", tree::text("environment", pos)},
                               {"image", tree::text(file, pos)},
                               {"scale", tree::number(scale, pos)}},
                              pos);
        } else {
            light = tree::map({{"type", tree::text("environment", pos)},
                               {"radiance", light_color("L")},
                               {"scale", tree::number(scale, pos)}},
                              pos);
        }
    } else {
        throw SceneError(
            pos, unknown_name_message("light", type,
                                      {"point", "spot", "distant", "infinite", "goniometric", "projection"}));
    }
    params.warn_unread("the light");
    lights_.push_back(std::move(light));
}

Node Importer::render_node() {
    const SourcePos& at = whole_file_;
    Node render = tree::map({}, at);
    // Film: the resolution; the file name is glint's -o.
    // Kept as given: glint's builder checks the size (and a huge number must not be cast to int).
    double width = 1280, height = 720;
    if (film_.statement) {
        Params film(*film_.statement, warnings_);
        const std::string type = film_.type();
        if (type != "rgb" && type != "gbuffer" && type != "spectral") {
            throw SceneError(film.pos(), unknown_name_message("film", type, {"rgb", "gbuffer", "spectral"}));
        }
        width = film.number("xresolution", 1280);
        height = film.number("yresolution", 720);
        if (film.has("filename")) {
            film.text("filename", "");
            warn(film.pos(), "the film's 'filename' is not used: glint writes the image `-o` names");
        }
        film.boolean("savefp16", true);  // the file's precision, which -o's format decides
        film.number("diagonal", 35);     // only the realistic camera reads it
        film.warn_unread("the film");
    }
    tree::set(render, "width", tree::number(width, film_.statement ? film_.statement->pos : at));
    tree::set(render, "height", tree::number(height, film_.statement ? film_.statement->pos : at));

    // Sampler: the count of samples per pixel, and the nearest of glint's patterns.
    std::string pattern = "sobol";
    double samples = 16;
    if (sampler_.statement) {
        Params sampler(*sampler_.statement, warnings_);
        const std::string type = sampler_.type();
        if (type == "stratified") {
            samples = sampler.number("xsamples", 4) * sampler.number("ysamples", 4);
            pattern = sampler.boolean("jitter", true) ? "jittered" : "regular";
        } else {
            samples = sampler.number("pixelsamples", 16);
            const std::map<std::string, std::string> patterns = {
                {"zsobol", "sobol"},  {"sobol", "sobol"},        {"paddedsobol", "sobol"},
                {"halton", "halton"}, {"independent", "random"}, {"pmj02bn", "multi-jittered"}};
            const auto found = patterns.find(type);
            if (found == patterns.end()) {
                throw SceneError(sampler.pos(), "unknown sampler '" + type + "'");
            }
            pattern = found->second;
            if (type == "pmj02bn") {
                sampler.warn(sampler.pos(), "pmj02bn is rendered with glint's multi-jittered pattern");
            }
        }
        sampler.text("randomization", "");  // the scrambling: glint's patterns use their own
        sampler.warn_unread("the sampler");
    }
    const SourcePos& sampler_pos = sampler_.statement ? sampler_.statement->pos : at;
    tree::set(render, "samples", tree::number(samples, sampler_pos));
    tree::set(render, "sampler", tree::text(pattern, sampler_pos));

    // PixelFilter: glint's box or tent; pbrt-v4's default is a Gaussian.
    Node filter;
    if (!filter_.statement) {
        warn(at,
             "pbrt-v4's default pixel filter, a Gaussian of σ 0.5, is rendered as a tent of the same "
             "variance (radius 0.5·√6)");
        filter = tree::map(
            {{"type", tree::text("tent", at)}, {"radius", tree::number(0.5 * std::sqrt(6.0), at)}}, at);
    } else {
        Params params(*filter_.statement, warnings_);
        const std::string type = filter_.type();
        const SourcePos& pos = params.pos();
        // pbrt-v4's filters take a radius per axis; glint's are square.
        const auto radius = [&](double fallback) {
            const double x = params.number("xradius", fallback), y = params.number("yradius", fallback);
            if (x != y) {
                warn(pos, "glint's pixel filters are square: 'xradius' is used for both axes");
            }
            return x;
        };
        if (type == "box") {
            if (radius(0.5) != 0.5) {
                warn(pos, "glint's box filter covers its own pixel: the radius is left out");
            }
            filter = tree::text("box", pos);
        } else if (type == "triangle") {
            filter =
                tree::map({{"type", tree::text("tent", pos)}, {"radius", tree::number(radius(2), pos)}}, pos);
        } else if (type == "gaussian" || type == "mitchell" || type == "lanczos") {
            const double sigma = type == "gaussian" ? params.number("sigma", 0.5) : 0;
            radius(type == "gaussian" ? 1.5 : 2);
            warn(pos, "glint has no " + type + " filter: rendered with a tent of radius " +
                          (type == "gaussian" ? "σ·√6 (the same variance)" : "1"));
            filter =
                tree::map({{"type", tree::text("tent", pos)},
                           {"radius", tree::number(type == "gaussian" ? sigma * std::sqrt(6.0) : 1.0, pos)}},
                          pos);
        } else {
            throw SceneError(pos,
                             unknown_name_message("pixel filter", type,
                                                  {"box", "triangle", "gaussian", "mitchell", "lanczos"}));
        }
        params.warn_unread("the pixel filter");
    }
    tree::set(render, "filter", std::move(filter));

    // Integrator: glint's path tracer, as deep as pbrt's (maxdepth 5 by default).
    double max_depth = 5;
    const SourcePos& integrator_pos = integrator_.statement ? integrator_.statement->pos : at;
    if (integrator_.statement) {
        Params params(*integrator_.statement, warnings_);
        const std::string type = integrator_.type();
        if (type != "path" && type != "volpath") {
            warn(params.pos(), "glint has no '" + type + "' integrator: rendered by its path tracer");
        }
        max_depth = params.number("maxdepth", 5);
        params.text("lightsampler", "bvh");  // which light is sampled: noise only, not the image
        params.warn_unread("the integrator");
    }
    tree::set(render, "integrator",
              tree::map({{"type", tree::text("path", integrator_pos)},
                         {"max_depth", tree::number(max_depth, integrator_pos)}},
                        integrator_pos));
    return render;
}

Node Importer::camera_node() {
    const SourcePos pos = camera_.statement ? camera_.statement->pos : whole_file_;
    PbrtStatement defaults{"Camera", whole_file_, {"perspective"}, {}, {}};
    const PbrtStatement& statement = camera_.statement ? *camera_.statement : defaults;
    Params params(statement, warnings_);
    const std::string type = statement.strings.front();

    const Transform world_from_camera = to_glint(camera_from_world_.inverse());
    const Vec3 eye = world_from_camera.point({0, 0, 0});
    const Vec3 forward = world_from_camera.vector({0, 0, 1});
    const Vec3 up = world_from_camera.vector({0, 1, 0});
    const std::optional<double> uniform = world_from_camera.uniform_scale();
    if (!uniform) {
        warn(pos,
             "the camera's transform stretches or shears: glint's camera does not, so the view is "
             "approximated");
    }
    const double scale = uniform ? *uniform : length(up);

    // The screen window: by default the shorter image axis spans [−1, 1] (so pbrt's fov is that axis').
    const double width =
        film_.statement ? Params(*film_.statement, warnings_).number("xresolution", 1280) : 1280;
    const double height =
        film_.statement ? Params(*film_.statement, warnings_).number("yresolution", 720) : 720;
    const double frame = params.number("frameaspectratio", width / height);
    double x0 = -1, x1 = 1, y0 = -1, y1 = 1;
    if (frame > 1) {
        x0 = -frame;
        x1 = frame;
    } else {
        y0 = -1 / frame;
        y1 = 1 / frame;
    }
    const std::vector<double> window = params.numbers("screenwindow", {"float"});
    if (!window.empty()) {
        if (window.size() != 4) {
            throw SceneError(pos, "'screenwindow' takes 4 numbers: xmin xmax ymin ymax");
        }
        x0 = window[0], x1 = window[1], y0 = window[2], y1 = window[3];
    }
    if (!(y1 > y0) || !(x1 > x0)) {
        throw SceneError(pos, "the camera's screen window is empty");
    }
    const double window_aspect = (x1 - x0) / (y1 - y0);
    if (std::abs(x0 + x1) > 1e-9 * (x1 - x0) || std::abs(y0 + y1) > 1e-9 * (y1 - y0) ||
        std::abs(window_aspect - width / height) > 1e-6 * window_aspect) {
        warn(pos,
             "glint's view is centred on the image with square pixels: this screen window is "
             "approximated by its height");
    }

    Node camera = tree::map({}, pos);
    const auto place = [&](const char* glint_type) {
        tree::set(camera, "type", tree::text(glint_type, pos));
        tree::set(camera, "eye", tree::vec3(eye, pos));
        tree::set(camera, "look_at", tree::vec3(eye + normalize(forward), pos));
        tree::set(camera, "up", tree::vec3(up, pos));
    };
    params.number("shutteropen", 0);
    params.number("shutterclose", 1);
    if (type == "perspective" || type == "realistic") {
        if (type == "realistic") {
            warn(pos, "glint has no lens systems: the realistic camera is rendered as a pinhole of fov 90");
            for (const PbrtParam& param : statement.params) {
                param.used = true;
            }
        }
        const double fov = params.number("fov", 90);
        const double lens_radius = params.number("lensradius", 0);
        const double focus = params.number("focaldistance", 1e6);
        // glint's fov is vertical: the angle the window's height spans, tan(fov/2) a unit of it.
        const double vertical = degrees(2 * std::atan(std::tan(radians(fov) / 2) * (y1 - y0) / 2));
        place(lens_radius > 0 ? "thin-lens" : "pinhole");
        tree::set(camera, "fov", tree::number(vertical, pos));
        if (lens_radius > 0) {
            tree::set(camera, "lens_radius", tree::number(lens_radius * scale, pos));
            tree::set(camera, "focus_distance", tree::number(focus * scale, pos));
        }
    } else if (type == "orthographic") {
        if (params.number("lensradius", 0) > 0) {
            warn(pos, "glint's orthographic camera has no lens: 'lensradius' is left out");
        }
        params.number("focaldistance", 1e6);
        place("orthographic");
        tree::set(camera, "height", tree::number((y1 - y0) * scale, pos));
    } else if (type == "spherical") {
        if (params.text("mapping", "equalarea") != "equirectangular") {
            warn(pos, "glint's panorama is equirectangular: pbrt's equal-area mapping is not");
        }
        place("equirectangular");
    } else {
        throw SceneError(pos, unknown_name_message(
                                  "camera", type, {"perspective", "orthographic", "realistic", "spherical"}));
    }
    params.warn_unread("the camera");
    return camera;
}

std::optional<Node> Importer::material_named(const std::string& name, const SourcePos& used_at, int depth) {
    const auto found = named_materials_.find(name);
    if (found == named_materials_.end()) {
        std::vector<std::string> names;
        for (const auto& [known, def] : named_materials_) {
            names.push_back(known);
        }
        throw SceneError(used_at, unknown_name_message("named material", name, names, "defined"));
    }
    if (depth > 16) {
        throw SceneError(used_at, "mix materials nest more than 16 deep (a mix of itself?)");
    }
    Params params(found->second.statement, warnings_);
    params.text("type", "");
    return pbrt::convert_material(
        params, found->second.type, textures_,
        [&](const std::string& other, const SourcePos& at) { return material_named(other, at, depth + 1); });
}

// The materials map, and each object's `material` (or its removal, for pbrt's interface material).
Node Importer::materials_node(std::vector<Node>& objects) {
    Node materials = tree::map({}, whole_file_);
    std::map<std::string, bool> is_surface;  // by glint name: false for "interface"
    const auto define = [&](const std::string& key, std::optional<Node> material) {
        is_surface[key] = material.has_value();
        if (material) {
            values_ += pbrt::count_nodes(*material);
            if (values_ > kMaxSceneValues) {
                throw SceneError(material->pos, "the scene's materials take it past glint's limit of " +
                                                    std::to_string(kMaxSceneValues) + " values");
            }
            tree::set(materials, key, std::move(*material));
        }
    };
    const auto resolve = [&](const std::string& other, const SourcePos& at) {
        return material_named(other, at, 1);
    };
    std::map<std::size_t, std::string> anonymous_keys;
    std::map<std::string, bool> named_done;
    std::vector<Node> kept;
    for (std::size_t i = 0; i < shapes_.size(); ++i) {
        PendingShape& shape = shapes_[i];
        Node& object = objects[i];
        if (shape.emissive) {
            tree::set(object, "material", std::move(*shape.emissive));
            kept.push_back(std::move(object));
            continue;
        }
        std::string key;
        switch (shape.material.kind) {
            case MaterialRef::Kind::Default:
                key = "pbrt-default";
                if (!is_surface.count(key)) {
                    // pbrt-v4's material before any Material statement: diffuse, reflectance 0.5.
                    define(key, tree::map({{"type", tree::text("matte", whole_file_)},
                                           {"albedo", tree::number(0.5, whole_file_)}},
                                          whole_file_));
                }
                break;
            case MaterialRef::Kind::Anonymous:
                if (!anonymous_keys.count(shape.material.index)) {
                    const MaterialDef& def = anonymous_materials_[shape.material.index];
                    std::string name = def.type + "-" + std::to_string(shape.material.pos.line);
                    while (named_materials_.count(name) || is_surface.count(name)) {
                        name += "'";
                    }
                    Params params(def.statement, warnings_);
                    define(name, pbrt::convert_material(params, def.type, textures_, resolve));
                    anonymous_keys[shape.material.index] = name;
                }
                key = anonymous_keys[shape.material.index];
                break;
            case MaterialRef::Kind::Named:
                key = shape.material.name;
                if (!named_done[key]) {
                    define(key, material_named(key, shape.material.pos, 0));
                    named_done[key] = true;
                }
                break;
        }
        if (is_surface[key]) {
            tree::set(object, "material", tree::text(key, shape.material.pos));
            kept.push_back(std::move(object));
        }
    }
    objects = std::move(kept);
    return materials;
}

SceneDesc Importer::finish() {
    if (!in_world_) {
        decide_mirror();
    }
    if (!stack_.empty()) {
        warn(stack_.back().pos, stack_.back().opened_by + " is not closed by the end of the scene");
    }
    if (defining_object_) {
        throw SceneError(stack_.back().pos,
                         "ObjectBegin '" + *defining_object_ + "' is not closed by ObjectEnd");
    }
    if (mirrored_ && has_environment_) {
        for (const Node& light : lights_) {
            if (light.find("image")) {
                warn(light.pos,
                     "the scene is mirrored in x for glint's camera (docs/import-pbrt.md): the "
                     "environment map is seen mirrored");
            }
        }
    }
    std::vector<Node> objects;
    objects.reserve(shapes_.size());
    for (PendingShape& shape : shapes_) {
        Node object = shape.shape;
        const Transform placed = to_glint(shape.to_world);
        if (!is_identity(placed)) {
            tree::set(object, "transform", matrix_node(placed, object.pos));
        }
        objects.push_back(std::move(object));
    }
    Node materials = materials_node(objects);

    SceneDesc desc;
    desc.base_dir = search_dir_;
    desc.root = tree::map({{"render", render_node()}, {"camera", camera_node()}}, whole_file_);
    if (!materials.items.empty()) {
        tree::set(desc.root, "materials", std::move(materials));
    }
    tree::set(desc.root, "objects", tree::list(std::move(objects), whole_file_));
    if (!lights_.empty()) {
        tree::set(desc.root, "lights", tree::list(std::move(lights_), whole_file_));
    }
    if (pbrt::count_nodes(desc.root) > kMaxSceneValues) {
        throw SceneError(whole_file_, "the scene takes more than glint's limit of " +
                                          std::to_string(kMaxSceneValues) + " values");
    }
    desc.warnings = std::move(warnings_);
    return desc;
}

}  // namespace

SceneDesc import_pbrt_scene(const std::filesystem::path& path, const ImportOptions&) {
    const std::filesystem::path folder = path.parent_path();
    Importer importer(folder, path.string());
    parse_pbrt_file(path, folder, [&](PbrtStatement& s) { importer.statement(s); });
    return importer.finish();
}

SceneDesc import_pbrt_text(const std::string& text, const std::string& display_path,
                           const std::filesystem::path& base_dir) {
    Importer importer(base_dir, display_path);
    parse_pbrt_text(text, display_path, base_dir, [&](PbrtStatement& s) { importer.statement(s); });
    return importer.finish();
}

}  // namespace glint
