// pbrt-v4 materials, textures and spectrum parameters as glint's (docs/import-pbrt.md, "Materials").
#include <algorithm>
#include <cmath>

#include "glint/import/pbrt_convert.hpp"
#include "glint/import/pbrt_spectra.hpp"
#include "glint/import/scene_tree.hpp"

namespace glint::pbrt {
namespace {

namespace tree = scene_tree;
using pbrt_spectra::ComplexIor;

constexpr std::size_t kMaxTextureValues = 10'000;
constexpr std::size_t kMaxTextureNesting = 32;

std::size_t nesting(const Node& node) {
    std::size_t deepest = 0;
    for (const Node& item : node.items) {
        deepest = std::max(deepest, nesting(item));
    }
    return deepest + 1;
}

const std::vector<std::string> kSpectrumTypes = {"rgb", "color", "blackbody", "spectrum", "texture"};

Rgb rgb_of(const PbrtParam& param) {
    if (param.numbers.size() != 3) {
        throw SceneError(param.pos, "'" + param.name + "' takes one colour (3 numbers), not " +
                                        std::to_string(param.numbers.size()) + " numbers");
    }
    return {param.numbers[0], param.numbers[1], param.numbers[2]};
}

Rgb grey(double v) {
    return {v, v, v};
}

// A named spectrum (pbrt-v4's util/spectrum.cpp names) as RGB for `use`.
Rgb named_spectrum(const Params& params, const PbrtParam& param, SpectrumUse use) {
    const std::string& name = param.strings.front();
    if (name.rfind("stdillum-", 0) == 0 || name.rfind("illum-", 0) == 0) {
        if (name != "stdillum-D65") {
            params.warn(param.pos, "the illuminant '" + name +
                                       "' is rendered white (as D65, the white of glint's sRGB)");
        }
        return grey(1);
    }
    if (const std::optional<double> ior = pbrt_spectra::named_glass_ior(name)) {
        if (use != SpectrumUse::Unbounded) {
            throw SceneError(param.pos, "'" + name + "' is an index of refraction, not a colour");
        }
        return grey(*ior);
    }
    if (name.rfind("metal-", 0) == 0 && name.size() > 6) {
        const std::size_t dash = name.rfind('-');
        const std::optional<ComplexIor> metal = pbrt_spectra::named_metal(name.substr(6, dash - 6));
        const std::string part = name.substr(dash + 1);
        if (metal && (part == "eta" || part == "k")) {
            if (use != SpectrumUse::Unbounded) {
                throw SceneError(param.pos, "'" + name + "' is an optical constant, not a colour");
            }
            return part == "eta" ? metal->eta : metal->k;
        }
    }
    throw SceneError(param.pos, unknown_name_message("named spectrum", name,
                                                     pbrt_spectra::known_spectrum_names(), "glint knows"));
}

// The RGB of a spectrum-valued parameter that is not a texture.
Rgb spectrum_rgb(const Params& params, const PbrtParam& param, SpectrumUse use) {
    if (param.type == "rgb" || param.type == "color") {
        return rgb_of(param);
    }
    if (param.type == "blackbody") {
        const double kelvin = param.numbers.front();
        if (!(kelvin > 0)) {
            throw SceneError(param.pos, "a blackbody's temperature must be above 0 K");
        }
        const Rgb c = pbrt_spectra::blackbody_rgb(kelvin);
        return {std::max(c.r, 0.0), std::max(c.g, 0.0), std::max(c.b, 0.0)};
    }
    if (param.type == "float") {
        return grey(param.numbers.front());
    }
    if (!param.strings.empty()) {
        return named_spectrum(params, param, use);
    }
    if (use == SpectrumUse::Unbounded) {
        params.warn(param.pos, "the spectrum of '" + param.name +
                                   "' is sampled at 630, 532 and 465 nm (red, "
                                   "green, blue)");
        return pbrt_spectra::sampled_spectrum_at_rgb_wavelengths(param.numbers);
    }
    params.warn(param.pos, "the spectrum of '" + param.name +
                               "' is reduced to RGB (CIE 1931 under an "
                               "equal-energy white)");
    return pbrt_spectra::sampled_spectrum_rgb(param.numbers, use == SpectrumUse::Illuminant);
}

// A reflectance outside [0, 1] in RGB: clamped, as glint's materials take no other (pbrt-v4 refuses
// RGB reflectances above 1 too).
Rgb clamp_albedo(const Params& params, const PbrtParam& param, Rgb c) {
    if (std::max({c.r, c.g, c.b}) > 1 || std::min({c.r, c.g, c.b}) < 0) {
        params.warn(param.pos, "'" + param.name + "' is a reflectance: its channels are clamped to [0, 1]");
        c = {std::clamp(c.r, 0.0, 1.0), std::clamp(c.g, 0.0, 1.0), std::clamp(c.b, 0.0, 1.0)};
    }
    return c;
}

// A texture parameter that names a texture.
const std::string& texture_name(const PbrtParam& param) {
    if (param.strings.size() != 1) {
        throw SceneError(param.pos, "'" + param.name + "' names one texture");
    }
    return param.strings.front();
}

// A colour that is a constant as a number (what glint takes where pbrt has a float texture).
std::optional<Rgb> constant_color(const Node& node) {
    if (node.is_sequence() && node.items.size() == 3) {
        return Rgb{std::stod(node.items[0].scalar), std::stod(node.items[1].scalar),
                   std::stod(node.items[2].scalar)};
    }
    return std::nullopt;
}

// pbrt-v4's roughness as glint's: pbrt's microfacet α is √roughness when `remaproughness` (its
// default) and the roughness itself otherwise; glint's α is roughness², so glint's roughness is √α.
double glint_roughness(const Params& params, double roughness, bool remap) {
    const double alpha = remap ? std::sqrt(std::max(roughness, 0.0)) : std::max(roughness, 0.0);
    double r = std::sqrt(alpha);
    if (r > 1) {
        params.warn(params.pos(), "the roughness is beyond glint's range: rendered at 1 (the roughest)");
        r = 1;
    }
    return r;
}

// A surface's roughness as one number: uroughness and vroughness (pbrt's anisotropy) averaged.
double isotropic_roughness(const Params& params, const std::string& prefix, const Textures& textures) {
    const double roughness = float_param(params, prefix + "roughness", 0, textures);
    const double u = float_param(params, prefix + "uroughness", roughness, textures);
    const double v = float_param(params, prefix + "vroughness", roughness, textures);
    if (u != v) {
        params.warn(params.pos(),
                    "glint's microfacets are isotropic: uroughness and vroughness are averaged");
    }
    return 0.5 * (u + v);
}

// A dielectric's index: a float, a named glass, or a spectrum (glint has no dispersion: one value).
double dielectric_ior(const Params& params, const std::string& name) {
    const PbrtParam* param = params.find(name, {"float", "spectrum", "rgb"});
    if (!param) {
        return 1.5;
    }
    if (param->type == "float") {
        return param->numbers.front();
    }
    const Rgb ior = spectrum_rgb(params, *param, SpectrumUse::Unbounded);
    if (ior.r != ior.g || ior.g != ior.b) {
        params.warn(param->pos, "glint's dielectrics do not disperse: '" + name + "' is taken at 532 nm");
    }
    return ior.g;
}

// η or κ of a conductor, per channel.
Rgb conductor_constant(const Params& params, const std::string& name, const Rgb& fallback) {
    const PbrtParam* param = params.find(name, {"float", "rgb", "color", "spectrum"});
    return param ? spectrum_rgb(params, *param, SpectrumUse::Unbounded) : fallback;
}

// A conductor's reflectance at normal incidence: `reflectance` if given (pbrt-v4 then makes the
// conductor reflect exactly that at normal incidence), else from η and κ by the Fresnel equations.
Node conductor_color(const Params& params, const std::string& prefix, const Textures& textures) {
    if (std::optional<Node> reflectance = color_param(params, "reflectance", SpectrumUse::Albedo, textures)) {
        return *reflectance;
    }
    const ComplexIor copper = *pbrt_spectra::named_metal("Cu");  // pbrt-v4's default conductor
    const ComplexIor ior{conductor_constant(params, prefix + "eta", copper.eta),
                         conductor_constant(params, prefix + "k", copper.k)};
    return tree::color(pbrt_spectra::conductor_reflectance(ior), params.pos());
}

Node metal(const Params& params, const std::string& prefix, const Textures& textures) {
    const bool remap = params.boolean("remaproughness", true);
    const double roughness = isotropic_roughness(params, prefix, textures);
    const SourcePos& pos = params.pos();
    return tree::map({{"type", tree::text("metal", pos)},
                      {"reflectance", conductor_color(params, prefix, textures)},
                      {"roughness", tree::number(glint_roughness(params, roughness, remap), pos)}},
                     pos);
}

Node matte(const Params& params, const char* reflectance_key, double fallback, const Textures& textures) {
    std::optional<Node> albedo = color_param(params, reflectance_key, SpectrumUse::Albedo, textures);
    const SourcePos& pos = params.pos();
    return tree::map(
        {{"type", tree::text("matte", pos)}, {"albedo", albedo ? *albedo : tree::number(fallback, pos)}},
        pos);
}

const std::vector<std::string> kMaterialTypes = {"diffuse",
                                                 "coateddiffuse",
                                                 "dielectric",
                                                 "thindielectric",
                                                 "conductor",
                                                 "coatedconductor",
                                                 "diffusetransmission",
                                                 "mix",
                                                 "interface",
                                                 "measured",
                                                 "hair",
                                                 "subsurface"};

}  // namespace

std::optional<Node> color_param(const Params& params, const std::string& name, SpectrumUse use,
                                const Textures& textures) {
    const PbrtParam* param = params.find(name, kSpectrumTypes);
    if (!param) {
        return std::nullopt;
    }
    if (param->type == "texture") {
        const std::string& texture = texture_name(*param);
        const auto found = textures.spectrum.find(texture);
        if (found == textures.spectrum.end()) {
            std::vector<std::string> names;
            for (const auto& [known, node] : textures.spectrum) {
                names.push_back(known);
            }
            throw SceneError(param->pos, unknown_name_message("spectrum texture", texture, names, "defined"));
        }
        return found->second;
    }
    Rgb c = spectrum_rgb(params, *param, use);
    if (use == SpectrumUse::Albedo) {
        c = clamp_albedo(params, *param, c);
    }
    return tree::color(c, param->pos);
}

double float_param(const Params& params, const std::string& name, double fallback, const Textures& textures) {
    const PbrtParam* param = params.find(name, {"float", "texture"});
    if (!param) {
        return fallback;
    }
    if (param->type == "float") {
        return param->numbers.front();
    }
    const std::string& texture = texture_name(*param);
    if (const auto constant = textures.constant_float.find(texture);
        constant != textures.constant_float.end()) {
        return constant->second;
    }
    if (textures.variable_float.count(texture) == 0) {
        throw SceneError(param->pos, "no float texture named '" + texture + "' is defined before this");
    }
    params.warn(param->pos, "glint takes '" + name + "' as a number: the texture '" + texture +
                                "' is left out (" + scene_tree::number_text(fallback) + " is used)");
    return fallback;
}

void define_texture(const Params& params, Textures& textures) {
    const PbrtStatement& statement = params.statement();
    const std::string& name = statement.strings[0];
    const std::string& kind = statement.strings[1];
    const std::string& type = statement.strings[2];
    const SourcePos& pos = statement.pos;
    if (kind != "spectrum" && kind != "float") {
        throw SceneError(pos, "a texture is \"spectrum\" or \"float\", not \"" + kind + "\"");
    }
    if (textures.spectrum.count(name) != 0 || textures.constant_float.count(name) != 0 ||
        textures.variable_float.count(name) != 0) {
        throw SceneError(pos, "texture '" + name + "' is defined again (pbrt-v4 refuses that too)");
    }
    const std::string what = "texture '" + name + "'";
    if (kind == "float") {
        // glint's materials take numbers where pbrt takes float textures: only constants carry over.
        if (type == "constant") {
            textures.constant_float[name] = params.number("value", 1);
        } else {
            textures.variable_float[name] = pos;
            params.warn(pos, "glint has no float textures: '" + name + "' (" + type +
                                 ") is replaced by a constant where it is used");
            for (const PbrtParam& param : statement.params) {
                param.used = true;  // all of it is left out, and said so above
            }
        }
        params.warn_unread(what);
        return;
    }
    Node node;
    if (type == "constant") {
        std::optional<Node> value = color_param(params, "value", SpectrumUse::Albedo, textures);
        node = value ? *value : tree::number(1, pos);
    } else if (type == "imagemap") {
        const std::string file = params.text("filename", "");
        if (file.empty()) {
            throw SceneError(pos, "an imagemap texture needs \"string filename\"");
        }
        node = tree::map({{"type", tree::text("image", pos)}, {"file", tree::text(file, pos)}}, pos);
        const double uscale = params.number("uscale", 1), vscale = params.number("vscale", 1);
        const double udelta = params.number("udelta", 0), vdelta = params.number("vdelta", 0);
        if (uscale != 1 || vscale != 1 || udelta != 0 || vdelta != 0) {
            params.warn(pos,
                        "glint's image textures are not scaled or shifted in (u, v): uscale, vscale, "
                        "udelta and vdelta are left out");
        }
        if (params.number("scale", 1) != 1 || params.boolean("invert", false)) {
            params.warn(pos,
                        "glint's image textures are not scaled or inverted: 'scale' and 'invert' are "
                        "left out");
        }
        const std::string encoding = params.text("encoding", "sRGB");
        if (encoding != "sRGB") {
            params.warn(pos, "glint decodes 8-bit images as sRGB and float images as linear: encoding '" +
                                 encoding + "' is left out");
        }
        params.text("filter", "bilinear");  // glint filters bilinearly; pbrt's default is the same
        params.text("wrap", "repeat");      // glint repeats, pbrt's default
    } else if (type == "checkerboard") {
        const double dimension = params.number("dimension", 2);
        if (dimension != 2 && dimension != 3) {
            throw SceneError(pos, "a checkerboard's dimension is 2 or 3");
        }
        std::optional<Node> even = color_param(params, "tex1", SpectrumUse::Albedo, textures);
        std::optional<Node> odd = color_param(params, "tex2", SpectrumUse::Albedo, textures);
        const double uscale = params.number("uscale", 1), vscale = params.number("vscale", 1);
        if (uscale != vscale) {
            params.warn(pos, "glint's checker has square cells: vscale is taken equal to uscale");
        }
        if (dimension == 3) {
            params.warn(pos, "a 3-D checkerboard is laid in world space, not in the texture's own space");
        }
        node = tree::map({{"type", tree::text("checker", pos)},
                          {"space", tree::text(dimension == 3 ? "solid" : "uv", pos)},
                          {"scale", tree::number(dimension == 3 ? 1 : uscale, pos)},
                          {"even", even ? *even : tree::number(1, pos)},
                          {"odd", odd ? *odd : tree::number(0, pos)}},
                         pos);
    } else if (type == "scale" || type == "mix" || type == "directionmix") {
        // glint has no texture arithmetic: a constant result is computed, else the first texture is kept.
        const char* first_key = type == "scale" ? "tex" : "tex1";
        std::optional<Node> first = color_param(params, first_key, SpectrumUse::Albedo, textures);
        Node base = first ? *first : tree::number(1, pos);
        if (type == "scale") {
            const double scale = float_param(params, "scale", 1, textures);
            const std::optional<Rgb> constant = constant_color(base);
            if (constant) {
                base = tree::color({constant->r * scale, constant->g * scale, constant->b * scale}, pos);
            } else if (scale != 1) {
                params.warn(pos, "glint cannot scale a texture: '" + name + "' is its texture unscaled");
            }
        } else {
            params.warn(pos, "glint cannot blend textures: '" + name + "' is its first texture ('tex1')");
            for (const PbrtParam& param : statement.params) {
                param.used = true;
            }
        }
        node = base;
    } else if (type == "fbm" || type == "wrinkled" || type == "windy" || type == "marble") {
        params.warn(pos, "the procedural texture '" + type + "' is rendered as glint's turbulence noise");
        for (const PbrtParam& param : statement.params) {
            param.used = true;
        }
        node = tree::map({{"type", tree::text("noise", pos)}}, pos);
    } else {
        params.warn(pos, "glint has no '" + type + "' texture: '" + name + "' is rendered as grey 0.5");
        for (const PbrtParam& param : statement.params) {
            param.used = true;
        }
        node = tree::number(0.5, pos);
    }
    // A texture made of textures (a checkerboard of checkerboards …) doubles with each level: bounded,
    // and kept within the nesting glint's scene files allow.
    if (count_nodes(node) > kMaxTextureValues || nesting(node) > kMaxTextureNesting) {
        throw SceneError(pos, "texture '" + name + "' nests more than " + std::to_string(kMaxTextureNesting) +
                                  " levels or takes more than " + std::to_string(kMaxTextureValues) +
                                  " values");
    }
    params.warn_unread(what);
    textures.spectrum[name] = std::move(node);
}

std::optional<Node> convert_material(
    const Params& params, const std::string& type, const Textures& textures,
    const std::function<std::optional<Node>(const std::string&, const SourcePos&)>& resolve_named) {
    const SourcePos& pos = params.pos();
    std::optional<Node> material;
    // Parameters of every material that glint has nothing for; named so they are reported.
    if (type == "diffuse") {
        material = matte(params, "reflectance", 0.5, textures);
    } else if (type == "coateddiffuse") {
        std::optional<Node> diffuse = color_param(params, "reflectance", SpectrumUse::Albedo, textures);
        const double roughness = isotropic_roughness(params, "", textures);
        params.boolean("remaproughness", true);
        if (roughness > 0) {
            params.warn(pos, "glint's plastic has a smooth coat: the coat's roughness is left out");
        }
        params.number("thickness", 0.01);  // matters only with a coat 'albedo', reported if given
        params.number("maxdepth", 10);     // pbrt's stochastic layering: glint's plastic is analytic
        params.number("nsamples", 1);
        material = tree::map({{"type", tree::text("plastic", pos)},
                              {"diffuse", diffuse ? *diffuse : tree::number(0.5, pos)},
                              {"ior", tree::number(dielectric_ior(params, "eta"), pos)}},
                             pos);
    } else if (type == "dielectric" || type == "thindielectric") {
        const double ior = dielectric_ior(params, "eta");
        if (type == "dielectric" && isotropic_roughness(params, "", textures) > 0) {
            params.warn(pos, "glint's dielectric is smooth: the roughness is left out");
        }
        params.boolean("remaproughness", true);
        if (type == "thindielectric") {
            params.warn(pos, "glint has no thin dielectric: rendered as a solid dielectric");
        }
        material = tree::map({{"type", tree::text("dielectric", pos)}, {"ior", tree::number(ior, pos)}}, pos);
    } else if (type == "conductor") {
        material = metal(params, "", textures);
    } else if (type == "coatedconductor") {
        params.warn(pos, "glint has no coated conductor: rendered as the bare conductor, without its coat");
        dielectric_ior(params, "interface.eta");
        isotropic_roughness(params, "interface.", textures);
        material = metal(params, "conductor.", textures);
    } else if (type == "diffusetransmission") {
        params.warn(pos, "glint's matte transmits nothing: the transmission is left out");
        material = matte(params, "reflectance", 0.25, textures);
    } else if (type == "mix") {
        const std::vector<std::string> names = params.texts("materials");
        if (names.size() != 2) {
            throw SceneError(pos, "a mix material names two materials (\"string materials\" [\"a\" \"b\"])");
        }
        const double amount = float_param(params, "amount", 0.5, textures);
        const std::string& chosen = names[amount > 0.5 ? 1 : 0];
        params.warn(pos, "glint cannot mix materials: rendered as '" + chosen + "', the one of more weight");
        material = resolve_named(chosen, pos);
    } else if (type == "interface" || type == "none" || type.empty()) {
        material = std::nullopt;
    } else if (type == "measured" || type == "hair" || type == "subsurface") {
        params.warn(pos, "glint has no '" + type + "' material: rendered as grey matte (0.5)");
        for (const PbrtParam& param : params.statement().params) {
            param.used = true;
        }
        material = tree::map({{"type", tree::text("matte", pos)}, {"albedo", tree::number(0.5, pos)}}, pos);
    } else {
        throw SceneError(pos, unknown_name_message("material type", type, kMaterialTypes));
    }
    params.warn_unread("the material");
    return material;
}

}  // namespace glint::pbrt
