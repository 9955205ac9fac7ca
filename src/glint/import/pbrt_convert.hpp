// What the parts of the pbrt-v4 importer share (pbrt_scene.cpp, pbrt_shapes.cpp, pbrt_materials.cpp):
// typed, checked access to a statement's parameters, and the conversions of shapes, materials and
// textures to glint's scene tree. Internal to glint/import.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/color.hpp"
#include "glint/core/vec.hpp"
#include "glint/import/pbrt_parser.hpp"
#include "glint/params/node.hpp"

namespace glint::pbrt {

// A statement's parameters, read by name and type. Each getter marks what it read; warn_unread()
// reports the rest, so that no parameter is dropped silently. A parameter of a type the getter does
// not take is an error at the parameter (as in pbrt-v4).
class Params {
  public:
    Params(const PbrtStatement& statement, std::vector<SceneWarning>& warnings)
        : statement_(statement), warnings_(warnings) {}

    const PbrtStatement& statement() const { return statement_; }
    const SourcePos& pos() const { return statement_.pos; }
    std::vector<SceneWarning>& warnings() const { return warnings_; }
    void warn(const SourcePos& pos, const std::string& message) const { warnings_.push_back({pos, message}); }

    // The parameter `name` if given (marked read), checked to be of one of `types`.
    const PbrtParam* find(const std::string& name, const std::vector<std::string>& types) const;
    bool has(const std::string& name) const;

    double number(const std::string& name, double fallback) const;  // float or integer, one value
    std::vector<double> numbers(const std::string& name, const std::vector<std::string>& types) const;
    std::string text(const std::string& name, const std::string& fallback) const;
    std::vector<std::string> texts(const std::string& name) const;
    bool boolean(const std::string& name, bool fallback) const;
    std::optional<Vec3> vec3(const std::string& name) const;  // point3, vector3, normal, …

    // Reports every parameter no getter read: "'name' is not read by glint: <what> is rendered without it".
    void warn_unread(const std::string& what) const;

  private:
    const PbrtStatement& statement_;
    std::vector<SceneWarning>& warnings_;
};

// How a spectrum parameter is meant, which decides how a spectrum becomes RGB (pbrt-v4's SpectrumType).
enum class SpectrumUse {
    Albedo,      // a reflectance: kept in [0, 1]
    Unbounded,   // η, κ: any non-negative value
    Illuminant,  // a light's emission: blackbodies and sampled spectra scaled to luminance 1
};

// Named textures, converted as they are defined (pbrt-v4 requires a texture before its use).
struct Textures {
    std::map<std::string, Node> spectrum;             // the glint colour or texture map
    std::map<std::string, double> constant_float;     // float textures that are constants
    std::map<std::string, SourcePos> variable_float;  // float textures glint cannot take (warned at use)
};

// The colour of a spectrum or texture parameter as a glint value (a colour list or a texture map), or
// nothing if it is not given.
std::optional<Node> color_param(const Params& params, const std::string& name, SpectrumUse use,
                                const Textures& textures);
// One number of a float or float-texture parameter.
double float_param(const Params& params, const std::string& name, double fallback, const Textures& textures);

// `Texture "name" "spectrum"|"float" "class" …`: adds the converted texture to `textures`.
void define_texture(const Params& params, Textures& textures);

// A material statement (`Material "type"` or MakeNamedMaterial's "string type") as a glint material
// map, or nothing for pbrt's "interface" (no surface). `resolve_named` gives a named material's glint
// map, for mix.
std::optional<Node> convert_material(
    const Params& params, const std::string& type, const Textures& textures,
    const std::function<std::optional<Node>(const std::string&, const SourcePos&)>& resolve_named);

// A shape as glint object maps in the shape's own space (before its transform and material): usually
// one; none for a shape glint leaves out (with a warning). `reverse_orientation` (pbrt's flag) matters
// only to one-sided emitters: meshes are rewound, other shapes warn. `search_dir` resolves plymesh
// files; `scene_dir` is the imported scene's folder, which written paths are relative to.
struct ShapeContext {
    bool reverse_orientation = false;
    bool emits = false;
    std::string search_dir;
    std::string scene_dir;
    std::size_t values_left = 0;  // nodes the tree may still take: refuse a mesh beyond it
};
std::vector<Node> convert_shape(const Params& params, const std::string& type, const ShapeContext& context);

// Loop subdivision of a closed or open triangle mesh, `levels` times, with vertices moved to their
// limit positions (pbrt-v4's loopsubdiv). Positions are flat xyz triples; indices triples.
struct TriangleMesh {
    std::vector<double> positions;
    std::vector<std::size_t> indices;
};
TriangleMesh loop_subdivide(const TriangleMesh& control, int levels);

// The number of nodes in a tree (every scalar, list and map), as glint's loader counts them.
std::size_t count_nodes(const Node& node);

}  // namespace glint::pbrt
