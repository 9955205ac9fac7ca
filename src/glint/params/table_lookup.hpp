// Finding a scene object's `type` in its concept's name → constructor table.
#pragma once

#include <string>
#include <vector>

#include "glint/params/params.hpp"

namespace glint {

// The entry of `table` named by the object's `type` key, or a positioned error listing the known names
// (with a did-you-mean). `Entry` is any table row with a `name` member.
template <typename Entry>
const Entry& lookup_type(const std::vector<Entry>& table, Params& params, const std::string& concept_name) {
    const std::string type = params.string("type");
    std::vector<std::string> names;
    for (const Entry& entry : table) {
        if (entry.name == type) {
            return entry;
        }
        names.push_back(entry.name);
    }
    params.fail("type", unknown_name_message(concept_name + " type", type, names));
}

}  // namespace glint
