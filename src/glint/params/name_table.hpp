// The one kind of table a scene's words are looked up in: each concept's name → constructor table
// (shapes, materials, lights, …) and each small enum a parameter names (a checker's `space`, a
// dielectric's `fresnel`, …). One type, so that every table lists its names, finds a name and reports
// an unknown one with a did-you-mean in the same way, at the word's position in the file.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "glint/params/params.hpp"

namespace glint {

// Rows in the order the user sees them (in error messages, --help and the preview's menus); `Entry` is
// any struct with a `std::string name` member, the word a scene writes. Two rows with the same name
// would make one unreachable: the constructor refuses them (std::logic_error, a programming error).
template <typename Entry>
class NameTable {
  public:
    NameTable(std::initializer_list<Entry> entries) : entries_(entries) {
        for (std::size_t i = 0; i < entries_.size(); ++i) {
            for (std::size_t j = 0; j < i; ++j) {
                if (entries_[i].name == entries_[j].name) {
                    throw std::logic_error("name table: '" + entries_[i].name + "' is listed twice");
                }
            }
        }
    }

    // The names in table order.
    std::vector<std::string> names() const {
        std::vector<std::string> names;
        names.reserve(entries_.size());
        for (const Entry& entry : entries_) {
            names.push_back(entry.name);
        }
        return names;
    }

    // The row named `name`, or nullptr.
    const Entry* find(std::string_view name) const {
        for (const Entry& entry : entries_) {
            if (entry.name == name) {
                return &entry;
            }
        }
        return nullptr;
    }

    // The row named `name`; otherwise a SceneError at `pos`:
    //   unknown <what> '<name>'; did you mean '<closest>'? (known: a, b, c)
    const Entry& lookup(const std::string& name, const std::string& what, const SourcePos& pos) const {
        if (const Entry* entry = find(name)) {
            return *entry;
        }
        throw SceneError(pos, unknown_name_message(what, name, names()));
    }

    // The row named by the word under `key` (required), with the error above at that word.
    const Entry& lookup(Params& params, const std::string& key, const std::string& what) const {
        return lookup(params.string(key), what, params.pos_of(key));
    }

    // The row named by the object's `type`: "unknown <concept> type 'sphre'; did you mean 'sphere'? …".
    const Entry& lookup_type(Params& params, const std::string& concept_name) const {
        return lookup(params, "type", concept_name + " type");
    }

    std::size_t size() const { return entries_.size(); }
    // The first row: the concept's default, for a concept that has one (a camera without a type).
    const Entry& front() const { return entries_.front(); }
    auto begin() const { return entries_.begin(); }
    auto end() const { return entries_.end(); }

  private:
    std::vector<Entry> entries_;
};

// A row of an EnumTable: the word and the value it stands for.
template <typename Enum>
struct EnumName {
    std::string name;
    Enum value;
};

// The words of a small enum, read with Params::enumeration. Several words may stand for one value (an
// alias); name_of gives the first, so list the name to write back first.
template <typename Enum>
class EnumTable : public NameTable<EnumName<Enum>> {
  public:
    using NameTable<EnumName<Enum>>::NameTable;

    // The first word of `value`; every value read through the table has one.
    const std::string& name_of(Enum value) const {
        for (const EnumName<Enum>& entry : *this) {
            if (entry.value == value) {
                return entry.name;
            }
        }
        throw std::logic_error("enum table: a value without a name");
    }
};

template <typename Enum>
Enum Params::enumeration(const std::string& key, const EnumTable<Enum>& table) {
    const std::string word = string(key);
    if (const EnumName<Enum>* entry = table.find(word)) {
        return entry->value;
    }
    fail_choice(key, word, table.names());
}

template <typename Enum>
Enum Params::enumeration(const std::string& key, const EnumTable<Enum>& table, Enum fallback) {
    return has(key) ? enumeration(key, table) : fallback;
}

// The one build step of every scene object: finds `params`' `type` in `table` (an unknown type is the
// positioned error of NameTable::lookup_type, naming `concept_name`), calls that row's create with
// `params` and then `args`, and reports any key that neither read (Params::finish). Returns what create
// returns. Keys the caller reads itself (a shape's `transform`, its `material`) must be read before
// this call, since finish() runs in it.
//   auto material = build_object(material_table(), params, "material", context);
template <typename Entry, typename... Args>
auto build_object(const NameTable<Entry>& table, Params& params, const std::string& concept_name,
                  Args&&... args) {
    const Entry& entry = table.lookup_type(params, concept_name);
    auto object = entry.create(params, std::forward<Args>(args)...);
    params.finish();
    return object;
}

// As above, for the map `node`, whose keys are named `what` in messages ("material 'glass'",
// "sphere.albedo").
template <typename Entry, typename... Args>
auto build_object(const NameTable<Entry>& table, const Node& node, const std::string& what,
                  const std::string& concept_name, Args&&... args) {
    Params params(node, what);
    return build_object(table, params, concept_name, std::forward<Args>(args)...);
}

}  // namespace glint
