// Typed, checked access to one object of a scene (a sphere, a material, the camera, …).
//
// Every getter records the key it read. finish() then reports any key nobody read, with a
// did-you-mean, so that a misspelt `radious: 1` is an error rather than a silent default.
// Every error is a SceneError pointing at the offending value.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "glint/core/color.hpp"
#include "glint/core/vec.hpp"
#include "glint/params/node.hpp"

namespace glint {

template <typename Enum>
class EnumTable;

class Params {
  public:
    // `what` names the object in messages, e.g. "sphere" or "camera".
    Params(const Node& map, std::string what);

    const std::string& what() const { return what_; }
    const SourcePos& pos() const { return map_->pos; }
    const Node& map() const { return *map_; }
    // Whether `key` is present. Asking counts as knowing the key, for did-you-mean suggestions.
    bool has(const std::string& key) {
        ask(key);
        return map_->find(key) != nullptr;
    }
    // Position of the value under `key` (of the object itself when the key is absent).
    SourcePos pos_of(const std::string& key) const;

    // Required values: a missing key is an error.
    double number(const std::string& key);
    std::int64_t integer(const std::string& key);
    std::string string(const std::string& key);
    Vec3 vec3(const std::string& key);
    Rgb color(const std::string& key);  // [r, g, b] or one number for grey
    bool boolean(const std::string& key);

    // Optional values with a default.
    double number(const std::string& key, double fallback);
    std::int64_t integer(const std::string& key, std::int64_t fallback);
    std::string string(const std::string& key, const std::string& fallback);
    Vec3 vec3(const std::string& key, const Vec3& fallback);
    Rgb color(const std::string& key, const Rgb& fallback);
    bool boolean(const std::string& key, bool fallback);

    // Checked numbers: the error names the range that was expected.
    double positive(const std::string& key);
    double positive(const std::string& key, double fallback);
    double non_negative(const std::string& key, double fallback);
    std::int64_t positive_integer(const std::string& key, std::int64_t fallback);
    Rgb non_negative_color(const std::string& key, const Rgb& fallback);
    // A vector that is turned into a direction: the zero vector is an error.
    Vec3 direction(const std::string& key);
    Vec3 direction(const std::string& key, const Vec3& fallback);
    // One of a small enum's words, by its EnumTable (defined, with these two, in params/name_table.hpp).
    // Any other word is an error at it with a did-you-mean and the list of words.
    template <typename Enum>
    Enum enumeration(const std::string& key, const EnumTable<Enum>& table);
    template <typename Enum>
    Enum enumeration(const std::string& key, const EnumTable<Enum>& table, Enum fallback);

    // The raw node under `key` (marking it read), or nullptr.
    const Node* node(const std::string& key);
    // A nested object; a missing key or a non-map is an error.
    Params child(const std::string& key);

    // Reports the first key that no getter read.
    void finish() const;

    [[noreturn]] void fail(const std::string& key, const std::string& message) const;
    [[noreturn]] void fail(const std::string& message) const;

  private:
    // Notes that a getter asked for `key` (for finish() and any AskedKeyRecorder).
    void ask(const std::string& key);
    const Node& require(const std::string& key);
    // The error for `word` under `key` when only `choices` are allowed:
    //   <what>.<key> is '<word>'; did you mean '<closest>'? (expected one of: a, b, c)
    [[noreturn]] void fail_choice(const std::string& key, const std::string& word,
                                  const std::vector<std::string>& choices) const;

    const Node* map_;
    std::string what_;
    std::set<std::string> read_;   // keys whose values were used
    std::set<std::string> asked_;  // every key a getter asked for, present or not
};

// A test hook (tests/docs checks that every key a constructor asks for is documented): while a
// recorder lives, every key that a Params on the same thread asks for is appended to it with the map
// asked, whether the key was present or not and whether a default was used. The map is told by its
// position and keys rather than its address, since a builder may ask a copy (the integrator map
// built from `render.integrator`). Recorders nest; with none alive, asking costs one load more.
class AskedKeyRecorder {
  public:
    struct Ask {
        SourcePos map_pos;                  // where the map asked begins
        std::vector<std::string> map_keys;  // the keys it has
        std::string key;                    // the key asked
    };

    AskedKeyRecorder();
    ~AskedKeyRecorder();
    AskedKeyRecorder(const AskedKeyRecorder&) = delete;
    AskedKeyRecorder& operator=(const AskedKeyRecorder&) = delete;

    const std::vector<Ask>& asks() const { return asks_; }

  private:
    friend class Params;
    AskedKeyRecorder* outer_;  // the recorder this one hides, restored at destruction
    std::vector<Ask> asks_;
};

// Scalar conversions with positioned errors, usable on any node.
double node_number(const Node& node, const std::string& what);
std::int64_t node_integer(const Node& node, const std::string& what);
std::string node_string(const Node& node, const std::string& what);
Vec3 node_vec3(const Node& node, const std::string& what);
Rgb node_color(const Node& node, const std::string& what);

}  // namespace glint
