#include "glint/params/params.hpp"

#include <charconv>
#include <cmath>

namespace glint {

double node_number(const Node& node, const std::string& what) {
    if (!node.is_scalar()) {
        throw SceneError(node.pos, what + " must be a number, not " + node.describe());
    }
    const std::string& s = node.scalar;
    double value = 0;
    const char* begin = s.data();
    const char* end = s.data() + s.size();
    if (begin != end && *begin == '+') {
        ++begin;
    }
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (ec != std::errc() || ptr != end || s.empty()) {
        throw SceneError(node.pos, what + " must be a number, not '" + s + "'");
    }
    if (!std::isfinite(value)) {
        throw SceneError(node.pos, what + " must be a finite number, not '" + s + "'");
    }
    return value;
}

std::int64_t node_integer(const Node& node, const std::string& what) {
    const double value = node_number(node, what);
    if (value != std::floor(value) || std::abs(value) > 9.0e15) {
        throw SceneError(node.pos, what + " must be a whole number, not '" + node.scalar + "'");
    }
    return static_cast<std::int64_t>(value);
}

std::string node_string(const Node& node, const std::string& what) {
    if (!node.is_scalar()) {
        throw SceneError(node.pos, what + " must be a word or a string, not " + node.describe());
    }
    return node.scalar;
}

Vec3 node_vec3(const Node& node, const std::string& what) {
    if (!node.is_sequence() || node.items.size() != 3) {
        throw SceneError(node.pos,
                         what + " must be a list of three numbers [x, y, z], not " + node.describe());
    }
    return {node_number(node.items[0], what + "[0]"), node_number(node.items[1], what + "[1]"),
            node_number(node.items[2], what + "[2]")};
}

Rgb node_color(const Node& node, const std::string& what) {
    if (node.is_scalar()) {
        return Rgb(node_number(node, what));
    }
    if (!node.is_sequence() || node.items.size() != 3) {
        throw SceneError(
            node.pos, what + " must be a colour: [r, g, b] or one number for grey, not " + node.describe());
    }
    return {node_number(node.items[0], what + "[0]"), node_number(node.items[1], what + "[1]"),
            node_number(node.items[2], what + "[2]")};
}

namespace {
thread_local AskedKeyRecorder* active_recorder = nullptr;
}  // namespace

AskedKeyRecorder::AskedKeyRecorder() : outer_(active_recorder) {
    active_recorder = this;
}

AskedKeyRecorder::~AskedKeyRecorder() {
    active_recorder = outer_;
}

void Params::ask(const std::string& key) {
    asked_.insert(key);
    if (active_recorder) {
        active_recorder->asks_.push_back({map_->pos, map_->keys, key});
    }
}

Params::Params(const Node& map, std::string what) : map_(&map), what_(std::move(what)) {
    if (!map.is_map()) {
        throw SceneError(map.pos, what_ + " must be a map of keys and values, not " + map.describe());
    }
}

SourcePos Params::pos_of(const std::string& key) const {
    const Node* n = map_->find(key);
    return n ? n->pos : map_->pos;
}

void Params::fail(const std::string& key, const std::string& message) const {
    throw SceneError(pos_of(key), message);
}

void Params::fail(const std::string& message) const {
    throw SceneError(map_->pos, message);
}

const Node* Params::node(const std::string& key) {
    ask(key);
    const Node* n = map_->find(key);
    if (n) {
        read_.insert(key);
    }
    return n;
}

const Node& Params::require(const std::string& key) {
    const Node* n = node(key);
    if (!n) {
        // A missing key is often a misspelt one: point at the misspelling instead.
        for (size_t i = 0; i < map_->keys.size(); ++i) {
            if (closest_match(map_->keys[i], {key}) == key) {
                throw SceneError(map_->key_positions[i], "unknown key '" + map_->keys[i] + "' in " + what_ +
                                                             "; did you mean '" + key + "'?");
            }
        }
        throw SceneError(map_->pos, what_ + " needs '" + key + "'");
    }
    return *n;
}

Params Params::child(const std::string& key) {
    return Params(require(key), what_ + "." + key);
}

double Params::number(const std::string& key) {
    return node_number(require(key), what_ + "." + key);
}
std::int64_t Params::integer(const std::string& key) {
    return node_integer(require(key), what_ + "." + key);
}
std::string Params::string(const std::string& key) {
    return node_string(require(key), what_ + "." + key);
}
Vec3 Params::vec3(const std::string& key) {
    return node_vec3(require(key), what_ + "." + key);
}
Rgb Params::color(const std::string& key) {
    return node_color(require(key), what_ + "." + key);
}
bool Params::boolean(const std::string& key) {
    const Node& n = require(key);
    const std::string s = node_string(n, what_ + "." + key);
    if (s == "true" || s == "yes" || s == "on") {
        return true;
    }
    if (s == "false" || s == "no" || s == "off") {
        return false;
    }
    throw SceneError(n.pos, what_ + "." + key + " must be true or false, not '" + s + "'");
}

double Params::number(const std::string& key, double fallback) {
    return has(key) ? number(key) : fallback;
}
std::int64_t Params::integer(const std::string& key, std::int64_t fallback) {
    return has(key) ? integer(key) : fallback;
}
std::string Params::string(const std::string& key, const std::string& fallback) {
    return has(key) ? string(key) : fallback;
}
Vec3 Params::vec3(const std::string& key, const Vec3& fallback) {
    return has(key) ? vec3(key) : fallback;
}
Rgb Params::color(const std::string& key, const Rgb& fallback) {
    return has(key) ? color(key) : fallback;
}
bool Params::boolean(const std::string& key, bool fallback) {
    return has(key) ? boolean(key) : fallback;
}

double Params::positive(const std::string& key) {
    const double v = number(key);
    if (!(v > 0)) {
        fail(key, what_ + "." + key + " must be greater than zero, not " + map_->find(key)->scalar);
    }
    return v;
}

double Params::positive(const std::string& key, double fallback) {
    return has(key) ? positive(key) : fallback;
}

double Params::non_negative(const std::string& key, double fallback) {
    const double v = number(key, fallback);
    if (v < 0) {
        fail(key, what_ + "." + key + " must be zero or more, not " + map_->find(key)->scalar);
    }
    return v;
}

std::int64_t Params::positive_integer(const std::string& key, std::int64_t fallback) {
    const std::int64_t v = integer(key, fallback);
    if (v <= 0) {
        fail(key,
             what_ + "." + key + " must be a whole number greater than zero, not " + map_->find(key)->scalar);
    }
    return v;
}

Rgb Params::non_negative_color(const std::string& key, const Rgb& fallback) {
    const Rgb c = color(key, fallback);
    if (c.r < 0 || c.g < 0 || c.b < 0) {
        fail(key, what_ + "." + key + " must not be negative");
    }
    return c;
}

Vec3 Params::direction(const std::string& key) {
    const Vec3 v = vec3(key);
    if (length_squared(v) == 0 || !is_finite(normalize(v))) {
        fail(key, what_ + "." + key + " must be a non-zero vector");
    }
    return normalize(v);
}

Vec3 Params::direction(const std::string& key, const Vec3& fallback) {
    return has(key) ? direction(key) : fallback;
}

void Params::fail_choice(const std::string& key, const std::string& word,
                         const std::vector<std::string>& choices) const {
    std::string message = what_ + "." + key + " is '" + word + "'";
    const std::string guess = closest_match(word, choices);
    if (!guess.empty()) {
        message += "; did you mean '" + guess + "'?";
    }
    fail(key, message + " (expected one of: " + join_words(choices) + ")");
}

void Params::finish() const {
    for (size_t i = 0; i < map_->keys.size(); ++i) {
        const std::string& key = map_->keys[i];
        if (read_.count(key)) {
            continue;
        }
        const std::vector<std::string> known(asked_.begin(), asked_.end());
        std::string message = "unknown key '" + key + "' in " + what_;
        const std::string guess = closest_match(key, known);
        if (!guess.empty()) {
            message += "; did you mean '" + guess + "'?";
        }
        message += " (expected one of: " + join_words(known) + ")";
        throw SceneError(map_->key_positions[i], message);
    }
}

}  // namespace glint
