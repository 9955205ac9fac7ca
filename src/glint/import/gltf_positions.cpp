// The positions of a glTF file's JSON, and tinygltf's reasons placed in it (gltf_positions.hpp).
#include "glint/import/gltf_positions.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <utility>

namespace glint {
namespace {

// A .glb: a 12-byte header, then chunks of (length, type, data); the JSON chunk comes first.
constexpr std::size_t kGlbJsonOffset = 20;

std::uint32_t little_endian_u32(const char* bytes) {
    std::uint32_t value = 0;
    for (std::size_t i = 0; i < 4; ++i) {
        value |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])) << (8 * i);
    }
    return value;
}

// A file's JSON text, as a SourceFile: a .gltf whole; of a .glb its JSON chunk alone (not the
// binary chunk after it, which may be most of the file), under the name "model.glb (JSON chunk)".
// Nothing when the file cannot be read, or is a .glb without a whole JSON chunk (tinygltf says
// what is wrong with it).
std::shared_ptr<const SourceFile> read_json_text(const std::filesystem::path& path) {
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error || size > kMaxGltfFileBytes) {
        return nullptr;
    }
    std::ifstream in(path, std::ios::binary);
    std::string header(std::min<std::size_t>(static_cast<std::size_t>(size), kGlbJsonOffset), '\0');
    if (!in.read(header.data(), static_cast<std::streamsize>(header.size()))) {
        return nullptr;
    }
    if (header.size() < 4 || header.compare(0, 4, "glTF") != 0) {
        std::string text(static_cast<std::size_t>(size), '\0');
        text.replace(0, header.size(), header);
        if (!in.read(text.data() + header.size(), static_cast<std::streamsize>(size - header.size()))) {
            return nullptr;
        }
        return SourceFile::from_text(path.string(), text);
    }
    if (header.size() < kGlbJsonOffset || header.compare(16, 4, "JSON") != 0) {
        return nullptr;
    }
    const std::uint32_t length = little_endian_u32(header.data() + 12);
    if (length > size - kGlbJsonOffset) {
        return nullptr;
    }
    std::string text(length, '\0');
    if (!in.read(text.data(), static_cast<std::streamsize>(length))) {
        return nullptr;
    }
    return SourceFile::from_text(path.string() + " (JSON chunk)", text);
}

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

// The words of tinygltf's reasons and the sections they name, longer words first where one contains
// another ("bufferview" before "buffer"), and a section named by what its elements hold ("animation
// channels target node") before what they point at.
constexpr std::array<std::pair<const char*, const char*>, 18> kSections = {{
    {"accessor", "/accessors"},
    {"bufferview", "/bufferViews"},
    {"bytestride", "/bufferViews"},
    {"buffer", "/buffers"},
    {"animation", "/animations"},
    {"camera", "/cameras"},
    {"orthographic", "/cameras"},
    {"perspective", "/cameras"},
    {"image", "/images"},
    {"texture", "/textures"},
    {"sampler", "/samplers"},
    {"material", "/materials"},
    {"primitive", "/meshes"},
    {"mesh", "/meshes"},
    {"skin", "/skins"},
    {"light", "/extensions/KHR_lights_punctual/lights"},
    {"node", "/nodes"},
    {"asset", "/asset"},
}};

// The section the first of kSections' words in `text` names, or "" when none.
std::string section_named(const std::string& text) {
    const std::string lowered = lower(text);
    for (const auto& [word, section] : kSections) {
        if (lowered.find(word) != std::string::npos) {
            return section;
        }
    }
    return "";
}

// The digits after `at` in `text`, as an index, or nothing.
std::optional<std::size_t> index_after(const std::string& text, std::size_t at) {
    std::size_t index = 0, digits = 0;
    while (at + digits < text.size() && std::isdigit(static_cast<unsigned char>(text[at + digits])) &&
           digits < 9) {
        index = 10 * index + static_cast<std::size_t>(text[at + digits] - '0');
        ++digits;
    }
    return digits > 0 ? std::optional(index) : std::nullopt;
}

// The pointer of what tinygltf's `reason` is about, as gltf_positions.hpp says; "" when it names nothing.
std::string pointer_of_reason(const std::string& reason, const JsonPositions& positions) {
    for (const auto& [word, section] :
         {std::pair{"image[", "/images/"}, std::pair{"accessor[", "/accessors/"}}) {
        if (const std::size_t at = reason.find(word); at != std::string::npos) {
            if (const std::optional<std::size_t> index = index_after(reason, at + std::strlen(word))) {
                return section + std::to_string(*index);
            }
        }
    }
    constexpr std::string_view kMissing = "' property is missing in ";
    if (const std::size_t missing = reason.find(kMissing); missing != std::string::npos && missing > 0) {
        const std::size_t quote = reason.rfind('\'', missing - 1);
        const std::size_t parent_end = reason.find_first_of(".\n", missing + kMissing.size());
        const std::string section =
            section_named(reason.substr(missing + kMissing.size(), parent_end - (missing + kMissing.size())));
        if (quote != std::string::npos && !section.empty()) {
            const std::string property = json_pointer_token(reason.substr(quote + 1, missing - quote - 1));
            for (std::size_t i = 0; positions.contains(section + "/" + std::to_string(i)); ++i) {
                const std::string element = section + "/" + std::to_string(i);
                if (!positions.contains(element + "/" + property)) {
                    return element;
                }
            }
            return section;
        }
    }
    return section_named(reason);
}

}  // namespace

PositionedGltf load_positioned_gltf(const std::filesystem::path& path, const SourcePos& whole_file) {
    std::shared_ptr<const GltfFile> file;
    try {
        file = load_gltf_file(path, whole_file);
    } catch (const SceneError& error) {
        // Read again, to place the reason: malformed JSON throws from JsonPositions.
        const std::shared_ptr<const SourceFile> source = read_json_text(path);
        if (!source) {
            throw;
        }
        std::optional<JsonPositions> positions;
        try {
            positions.emplace(source, whole_file);
        } catch (const SceneError& malformed) {
            throw SceneError(malformed.position(),
                             "cannot read the glTF file '" + path.string() + "': " + malformed.message());
        }
        // tinygltf's reason, after load_gltf_file's "cannot read the glTF file '<path>': " (whose path
        // might hold any word).
        const std::string prefix = "cannot read the glTF file '" + path.string() + "': ";
        const std::string reason =
            error.message().rfind(prefix, 0) == 0 ? error.message().substr(prefix.size()) : "";
        const std::string pointer = pointer_of_reason(reason, *positions);
        throw SceneError(pointer.empty() ? error.position() : positions->at(pointer), error.message());
    }
    if (file->source && !file->source->text.empty()) {  // a .gltf: its text is kept for positions
        return {file, JsonPositions(file->source, whole_file)};
    }
    const std::shared_ptr<const SourceFile> source = read_json_text(path);
    if (!source) {  // tinygltf read it, so this is a file changed since: no positions, no harm
        return {file, JsonPositions(whole_file)};
    }
    return {file, JsonPositions(source, whole_file)};
}

}  // namespace glint
