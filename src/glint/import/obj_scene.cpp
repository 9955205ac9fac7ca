// The OBJ importer: one glint mesh object per material the OBJ file uses (a mesh takes the faces under
// one `usemtl` through `obj_material`), each with its MTL material mapped as docs/importers.md says;
// a camera that frames the model and, when nothing emits, a white sky — both reported as warnings,
// since the file does not say them.
#include "glint/import/obj_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "glint/core/bounds.hpp"
#include "glint/core/math.hpp"
#include "glint/geometry/mesh_io/mesh_data.hpp"
#include "glint/import/scene_tree.hpp"

namespace glint {
namespace {

namespace tree = scene_tree;

// A number for a message: three significant digits.
std::string short_number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

bool black(const Rgb& c) {
    return c.r <= 0 && c.g <= 0 && c.b <= 0;
}
double max_of(const Rgb& c) {
    return std::max({c.r, c.g, c.b});
}

// A colour a reflectance may take: each channel clamped to [0, 1], with a warning when one was beyond.
Rgb reflectance(const MtlMaterial::Stated<Rgb>& stated, const char* what,
                std::vector<SceneWarning>& warnings) {
    Rgb c = stated.value;
    if (max_of(c) > 1) {
        warnings.push_back({stated.pos, std::string(what) +
                                            " above 1 clamped to 1: a surface reflects at most "
                                            "the light it receives"});
        c = {std::min(c.r, 1.0), std::min(c.g, 1.0), std::min(c.b, 1.0)};
    }
    return c;
}

}  // namespace

Node material_from_mtl(const MtlMaterial& mtl, const std::filesystem::path& base_dir,
                       const std::filesystem::path& scene_dir, std::vector<SceneWarning>& warnings) {
    const SourcePos& pos = mtl.pos;
    for (const auto& [keyword, at] : mtl.ignored) {
        warnings.push_back({at, "'" + keyword + "' is not read by glint: material '" + mtl.name +
                                    "' is rendered without it"});
    }
    const int illum = mtl.illum.given() ? mtl.illum.value : 2;
    // Emission: an emissive surface (which reflects nothing in glint).
    if (mtl.ke.given() && !black(mtl.ke.value)) {
        if (mtl.kd.given() && !black(mtl.kd.value)) {
            warnings.push_back(
                {mtl.kd.pos, "material '" + mtl.name +
                                 "' emits (Ke): glint's emissive surfaces reflect nothing, so Kd "
                                 "is left out"});
        }
        return tree::map(
            {{"type", tree::text("emissive", pos)}, {"radiance", tree::color(mtl.ke.value, mtl.ke.pos)}},
            pos);
    }
    // Glass: the transparent illumination models, or a dissolve below 1 with a refractive index.
    const bool transparent_illum = illum == 4 || illum == 6 || illum == 7 || illum == 9;
    if (transparent_illum || (mtl.d.given() && mtl.d.value < 1 && mtl.ni.given() && mtl.ni.value > 1)) {
        double ior = mtl.ni.given() ? mtl.ni.value : 1.5;
        if (!(ior > 1 && ior <= 10)) {
            warnings.push_back({mtl.ni.given() ? mtl.ni.pos : pos,
                                "material '" + mtl.name + "' is glass with Ni " + short_number(ior) +
                                    ", outside (1, 10]: rendered with 1.5"});
            ior = 1.5;
        }
        return tree::map({{"type", tree::text("dielectric", pos)}, {"ior", tree::number(ior, pos)}}, pos);
    }
    if (mtl.d.given() && mtl.d.value < 1) {
        warnings.push_back({mtl.d.pos, "material '" + mtl.name +
                                           "': a dissolve below 1 without a refractive index (Ni > 1) is "
                                           "rendered opaque"});
    }
    const Rgb kd = mtl.kd.given() ? reflectance(mtl.kd, "Kd", warnings) : Rgb{0.8, 0.8, 0.8};
    const Rgb ks = mtl.ks.given() ? reflectance(mtl.ks, "Ks", warnings) : Rgb{0, 0, 0};
    // The diffuse colour: map_Kd replaces Kd (MTL multiplies them; most exporters write Kd 1 with it).
    Node diffuse = tree::color(kd, mtl.kd.given() ? mtl.kd.pos : pos);
    if (mtl.map_kd.given()) {
        if (mtl.kd.given() && (kd.r != 1 || kd.g != 1 || kd.b != 1)) {
            warnings.push_back({mtl.kd.pos, "material '" + mtl.name +
                                                "': map_Kd is used alone; MTL multiplies it by this Kd, "
                                                "glint does not"});
        }
        diffuse = tree::map(
            {{"type", tree::text("image", mtl.map_kd.pos)},
             {"file",
              tree::text(tree::path_relative_to(base_dir / mtl.map_kd.value, scene_dir), mtl.map_kd.pos)}},
            mtl.map_kd.pos);
    }
    // A mirror: illum 3 and 5 (ray-traced reflection) with a black diffuse colour.
    if ((illum == 3 || illum == 5) && !black(ks) && black(kd) && !mtl.map_kd.given()) {
        return tree::map({{"type", tree::text("mirror", pos)}, {"reflectance", tree::color(ks, mtl.ks.pos)}},
                         pos);
    }
    if (illum == 0 || illum == 1 || black(ks)) {
        if (illum >= 3 && !black(ks)) {
            warnings.push_back({mtl.illum.pos, "material '" + mtl.name + "': illum " + std::to_string(illum) +
                                                   " is rendered as diffuse"});
        }
        return tree::map({{"type", tree::text("matte", pos)}, {"albedo", std::move(diffuse)}}, pos);
    }
    // A texture with a specular colour: Phong needs kd + ks ≤ 1 everywhere on the texture, which a map
    // cannot promise; plastic (the map under a clear coat) conserves energy for any map.
    if (mtl.map_kd.given()) {
        warnings.push_back({mtl.ks.pos, "material '" + mtl.name +
                                            "': Ks with map_Kd is rendered as plastic, the map under a clear "
                                            "coat of index 1.5 (Ks and Ns are not used)"});
        return tree::map({{"type", tree::text("plastic", pos)}, {"diffuse", std::move(diffuse)}}, pos);
    }
    // Diffuse and glossy: normalised Phong, ks scaled down where kd + ks would exceed 1 (energy).
    Rgb specular = ks;
    if (max_of(kd) + max_of(ks) > 1) {
        const double keep = std::max(0.0, 1 - max_of(kd)) / max_of(ks);
        specular = {ks.r * keep, ks.g * keep, ks.b * keep};
        warnings.push_back(
            {mtl.ks.pos, "material '" + mtl.name +
                             "': Kd + Ks exceeds 1, which reflects more light than arrives; Ks "
                             "scaled to " +
                             short_number(max_of(specular))});
    }
    const double exponent = mtl.ns.given() ? std::clamp(mtl.ns.value, 1e-3, 1e6) : 32.0;
    return tree::map({{"type", tree::text("phong", pos)},
                      {"diffuse", std::move(diffuse)},
                      {"specular", tree::color(specular, mtl.ks.pos)},
                      {"exponent", tree::number(exponent, mtl.ns.given() ? mtl.ns.pos : pos)}},
                     pos);
}

SceneDesc import_obj_scene(const std::filesystem::path& path, const ImportOptions&) {
    SceneDesc desc;
    desc.base_dir = path.parent_path();
    const SourcePos whole_file = tree::file_position(path.string());
    ObjMaterialUse use;
    const MeshData mesh = load_obj(path, {}, whole_file, &use);

    // The materials of every library, by name (a later library's material of the same name wins, as
    // a later newmtl does in most readers).
    std::map<std::string, MtlMaterial> library;
    std::map<std::string, std::filesystem::path> library_dir;
    for (const ObjMaterialUse::Named& file : use.libraries) {
        const std::filesystem::path mtl_path = desc.base_dir / file.name;
        std::error_code error;
        if (!std::filesystem::is_regular_file(mtl_path, error)) {
            desc.warnings.push_back({file.pos, "material library '" + file.name +
                                                   "' not found: its materials are rendered grey"});
            continue;
        }
        for (MtlMaterial& material : load_mtl(mtl_path, file.pos)) {
            library_dir[material.name] = mtl_path.parent_path();
            library[material.name] = std::move(material);
        }
    }

    // An object per material used; faces before any usemtl are grey (glint's default material).
    const std::string obj_file = path.filename().generic_string();
    std::vector<Node> objects;
    const bool any_unnamed = std::find(use.triangle_material.begin(), use.triangle_material.end(),
                                       ObjMaterialUse::kNoMaterial) != use.triangle_material.end();
    bool emits = false;
    if (use.materials.empty()) {
        objects.push_back(
            tree::map({{"type", tree::text("mesh", whole_file)}, {"file", tree::text(obj_file, whole_file)}},
                      whole_file));
    } else if (any_unnamed) {
        objects.push_back(tree::map({{"type", tree::text("mesh", whole_file)},
                                     {"file", tree::text(obj_file, whole_file)},
                                     {"obj_material", tree::text("", whole_file)}},
                                    whole_file));
    }
    for (const ObjMaterialUse::Named& used : use.materials) {
        Node object = tree::map({{"type", tree::text("mesh", used.pos)},
                                 {"file", tree::text(obj_file, used.pos)},
                                 {"obj_material", tree::text(used.name, used.pos)}},
                                used.pos);
        const auto found = library.find(used.name);
        if (found == library.end()) {
            if (!use.libraries.empty()) {
                desc.warnings.push_back(
                    {used.pos, "material '" + used.name + "' is in no material library: rendered grey"});
            }
        } else {
            Node material =
                material_from_mtl(found->second, library_dir[used.name], desc.base_dir, desc.warnings);
            emits = emits || material.find("type")->scalar == "emissive";
            tree::set(object, "material", std::move(material));
        }
        objects.push_back(std::move(object));
    }

    // The camera: looking at the model's bounding sphere from +z, framing it in a 40° field of view.
    Bounds3 bounds;
    for (const Vec3& p : mesh.positions) {
        bounds.grow(p);
    }
    desc.warnings.push_back({whole_file, "an OBJ file has no camera: glint looks at the model from +z"});
    desc.root =
        tree::map({{"render", tree::map({{"integrator", tree::text("path", whole_file)}}, whole_file)},
                   {"camera", tree::framing_camera(bounds, whole_file)},
                   {"objects", tree::list(std::move(objects), whole_file)}},
                  whole_file);
    if (!emits) {
        desc.warnings.push_back({whole_file,
                                 "nothing in the OBJ file emits light: glint lights it by a white sky "
                                 "(an environment of radiance 1)"});
        tree::set(desc.root, "lights", tree::list({tree::white_sky(whole_file)}, whole_file));
    }
    return desc;
}

}  // namespace glint
