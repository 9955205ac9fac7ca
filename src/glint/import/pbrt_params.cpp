// Typed access to a pbrt statement's parameters (pbrt_convert.hpp).
#include <algorithm>

#include "glint/import/pbrt_convert.hpp"

namespace glint::pbrt {

const PbrtParam* Params::find(const std::string& name, const std::vector<std::string>& types) const {
    const PbrtParam* found = nullptr;
    for (const PbrtParam& param : statement_.params) {
        if (param.name == name) {
            found = &param;  // the last one given wins, as in pbrt
        }
    }
    if (!found) {
        return nullptr;
    }
    found->used = true;
    if (std::find(types.begin(), types.end(), found->type) == types.end()) {
        throw SceneError(found->pos, "'" + name + "' is given as " + found->type + "; " +
                                         statement_.directive + " '" +
                                         (statement_.strings.empty() ? "" : statement_.strings.front()) +
                                         "' takes it as " + join_words(types));
    }
    return found;
}

bool Params::has(const std::string& name) const {
    return std::any_of(statement_.params.begin(), statement_.params.end(),
                       [&](const PbrtParam& p) { return p.name == name; });
}

namespace {

// The one value of a parameter that takes one.
template <typename T>
T single(const PbrtParam& param, const std::vector<T>& values, const char* kind) {
    if (values.size() != 1) {
        throw SceneError(param.pos,
                         "'" + param.name + "' takes one " + kind + ", not " + std::to_string(values.size()));
    }
    return values.front();
}

}  // namespace

double Params::number(const std::string& name, double fallback) const {
    const PbrtParam* param = find(name, {"float", "integer"});
    return param ? single(*param, param->numbers, "number") : fallback;
}

std::vector<double> Params::numbers(const std::string& name, const std::vector<std::string>& types) const {
    const PbrtParam* param = find(name, types);
    return param ? param->numbers : std::vector<double>{};
}

std::string Params::text(const std::string& name, const std::string& fallback) const {
    const PbrtParam* param = find(name, {"string"});
    return param ? single(*param, param->strings, "string") : fallback;
}

std::vector<std::string> Params::texts(const std::string& name) const {
    const PbrtParam* param = find(name, {"string"});
    return param ? param->strings : std::vector<std::string>{};
}

bool Params::boolean(const std::string& name, bool fallback) const {
    const PbrtParam* param = find(name, {"bool"});
    return param ? static_cast<bool>(single(*param, param->booleans, "bool")) : fallback;
}

std::optional<Vec3> Params::vec3(const std::string& name) const {
    const PbrtParam* param = find(name, {"point3", "point", "vector3", "vector", "normal3", "normal"});
    if (!param) {
        return std::nullopt;
    }
    if (param->numbers.size() != 3) {
        throw SceneError(param->pos, "'" + name + "' takes one point (3 numbers), not " +
                                         std::to_string(param->numbers.size()) + " numbers");
    }
    return Vec3{param->numbers[0], param->numbers[1], param->numbers[2]};
}

void Params::warn_unread(const std::string& what) const {
    for (const PbrtParam& param : statement_.params) {
        if (!param.used) {
            warn(param.pos, "'" + param.name + "' is not read by glint: " + what + " is rendered without it");
        }
    }
}

std::size_t count_nodes(const Node& node) {
    std::size_t count = 1;
    for (const Node& item : node.items) {
        count += count_nodes(item);
    }
    return count;
}

}  // namespace glint::pbrt
