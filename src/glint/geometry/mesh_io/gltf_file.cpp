// glTF files through tinygltf, with glint's own file reading (sizes checked, no path expansion) and
// every accessor bounds-checked before its bytes are read: tinygltf parses the JSON and loads the
// buffers, but does not check that an accessor's count, stride and offset stay inside them.
#include "glint/geometry/mesh_io/gltf_file.hpp"

#include "glint/geometry/mesh_io/tinygltf.hpp"
#include "glint/image/image_io.hpp"
#include "glint/params/build_context.hpp"
#include "glint/params/params.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <mutex>

namespace glint {
namespace {

bool file_exists(const std::string& path, void*) {
    std::error_code error;
    return std::filesystem::is_regular_file(path, error);
}

// No expansion of `~` or variables: a file names what it names.
std::string expand_nothing(const std::string& path, void*) {
    return path;
}

bool read_whole_file(std::vector<unsigned char>* out, std::string* error, const std::string& path, void*) {
    std::error_code code;
    const std::uintmax_t size = std::filesystem::file_size(path, code);
    if (code || !std::filesystem::is_regular_file(path, code)) {
        *error += "cannot read '" + path + "'";
        return false;
    }
    if (size > kMaxGltfFileBytes) {
        *error += "'" + path + "' has " + std::to_string(size) + " bytes, more than the " +
                  std::to_string(kMaxGltfFileBytes) + " glint reads";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    out->resize(static_cast<std::size_t>(size));
    if (!in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size))) {
        *error += "cannot read '" + path + "'";
        return false;
    }
    return true;
}

bool write_nothing(std::string* error, const std::string&, const std::vector<unsigned char>&, void*) {
    *error += "glint does not write glTF files";
    return false;
}

// Images are kept encoded, as the bytes of their file: glint's own image reader decodes them when a
// texture asks (gltf_image_bytes). Images in files beside the model never reach here
// (TINYGLTF_NO_EXTERNAL_IMAGE): a texture reads their file itself.
bool keep_image_encoded(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                        const unsigned char* bytes, int size, void*) {
    if (size > 0) {
        image->image.assign(bytes, bytes + size);
        image->as_is = true;
    }
    return true;
}

struct CachedFile {
    std::string path;
    std::uintmax_t size = 0;
    std::filesystem::file_time_type modified;
    std::shared_ptr<const GltfFile> file;
};

std::mutex cache_mutex;
CachedFile cache;

[[noreturn]] void fail(const SourcePos& pos, const GltfFile& file, const std::string& message) {
    throw SceneError(pos, "glTF file '" + file.path + "': " + message);
}

// An accessor's elements, checked: `components` numbers of `component_type` each, inside its buffer
// view and buffer. Returns the address of element 0 and the stride between elements.
struct AccessorView {
    const unsigned char* first = nullptr;
    std::size_t stride = 0;
    std::size_t count = 0;
    int component_type = 0;
    bool normalized = false;
};

std::size_t component_bytes(int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;
    }
}

AccessorView view_of(const GltfFile& file, int index, int type, const char* what, const SourcePos& pos) {
    const tinygltf::Model& model = *file.model;
    const std::string name = std::string(what) + " accessor " + std::to_string(index);
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
        fail(pos, file, name + " does not exist");
    }
    const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
    if (accessor.sparse.isSparse) {
        fail(pos, file, name + " is sparse, which glint does not read");
    }
    if (accessor.type != type) {
        fail(pos, file, name + " has the wrong type");
    }
    const std::size_t element_bytes = component_bytes(accessor.componentType) *
                                      static_cast<std::size_t>(tinygltf::GetNumComponentsInType(type));
    if (element_bytes == 0) {
        fail(pos, file, name + " has an unknown component type");
    }
    if (accessor.bufferView < 0 ||
        static_cast<std::size_t>(accessor.bufferView) >= model.bufferViews.size()) {
        fail(pos, file, name + " has no buffer view");
    }
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
        fail(pos, file, name + "'s buffer view has no buffer");
    }
    const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    const std::size_t stride = view.byteStride ? view.byteStride : element_bytes;
    // The view lies in the buffer, and the accessor's last element in the view; every sum is checked
    // against overflow by keeping each term below the buffer's size first.
    const std::size_t size = buffer.size();
    const bool view_fits = view.byteOffset <= size && view.byteLength <= size - view.byteOffset;
    const bool accessor_fits =
        view_fits && accessor.byteOffset <= view.byteLength && stride >= element_bytes &&
        (accessor.count == 0 ||
         ((accessor.count - 1) <= (view.byteLength - accessor.byteOffset) / stride &&
          (accessor.count - 1) * stride + element_bytes <= view.byteLength - accessor.byteOffset));
    if (!accessor_fits) {
        fail(pos, file, name + " (" + std::to_string(accessor.count) + " elements) reaches past its buffer");
    }
    return {buffer.data() + view.byteOffset + accessor.byteOffset, stride, accessor.count,
            accessor.componentType, accessor.normalized};
}

// Component c of element i, as a double (normalized integers scaled to [0, 1] or [−1, 1]).
double component(const AccessorView& view, std::size_t i, std::size_t c) {
    const unsigned char* at = view.first + i * view.stride + c * component_bytes(view.component_type);
    switch (view.component_type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float value;
            std::memcpy(&value, at, 4);
            return value;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return view.normalized ? at[0] / 255.0 : at[0];
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const auto value = static_cast<signed char>(at[0]);
            return view.normalized ? std::max(value / 127.0, -1.0) : value;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t value;
            std::memcpy(&value, at, 2);
            return view.normalized ? value / 65535.0 : value;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            std::int16_t value;
            std::memcpy(&value, at, 2);
            return view.normalized ? std::max(value / 32767.0, -1.0) : value;
        }
        default: {
            std::uint32_t value;
            std::memcpy(&value, at, 4);
            return value;
        }
    }
}

}  // namespace

std::shared_ptr<const GltfFile> load_gltf_file(const std::filesystem::path& path,
                                               const SourcePos& mentioned_at) {
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error || !std::filesystem::is_regular_file(path, error)) {
        throw SceneError(mentioned_at, "cannot read the glTF file '" + path.string() + "'");
    }
    if (size > kMaxGltfFileBytes) {
        throw SceneError(mentioned_at, "the glTF file '" + path.string() + "' has " + std::to_string(size) +
                                           " bytes, more than the " + std::to_string(kMaxGltfFileBytes) +
                                           " glint reads");
    }
    const std::filesystem::file_time_type modified = std::filesystem::last_write_time(path, error);
    {
        const std::lock_guard lock(cache_mutex);
        if (cache.file && cache.path == path.string() && cache.size == size && cache.modified == modified) {
            return cache.file;
        }
    }
    std::vector<unsigned char> bytes;
    std::string read_error;
    if (!read_whole_file(&bytes, &read_error, path.string(), nullptr)) {
        throw SceneError(mentioned_at, read_error);
    }
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&file_exists, &expand_nothing, &read_whole_file, &write_nothing, nullptr});
    loader.SetImageLoader(&keep_image_encoded, nullptr);
    auto model = std::make_shared<tinygltf::Model>();
    std::string errors, warnings;
    const std::string base_dir = path.parent_path().empty() ? "." : path.parent_path().string();
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    const bool ok = binary ? loader.LoadBinaryFromMemory(model.get(), &errors, &warnings, bytes.data(),
                                                         static_cast<unsigned int>(bytes.size()), base_dir)
                           : loader.LoadASCIIFromString(model.get(), &errors, &warnings,
                                                        reinterpret_cast<const char*>(bytes.data()),
                                                        static_cast<unsigned int>(bytes.size()), base_dir);
    if (!ok) {
        std::string reason = errors.empty() ? std::string("tinygltf gives no reason") : errors;
        while (!reason.empty() && (reason.back() == '\n' || reason.back() == ' ')) {
            reason.pop_back();
        }
        throw SceneError(mentioned_at, "cannot read the glTF file '" + path.string() + "': " + reason);
    }
    auto file = std::make_shared<GltfFile>();
    file->path = path.string();
    file->model = std::move(model);
    file->source = SourceFile::from_text(path.string(),
                                         binary ? std::string() : std::string(bytes.begin(), bytes.end()));
    const std::lock_guard lock(cache_mutex);
    cache = {path.string(), size, modified, file};
    return file;
}

void forget_gltf_files() {
    const std::lock_guard lock(cache_mutex);
    cache = {};
}

namespace {
const tinygltf::Mesh& mesh_of(const GltfFile& file, int mesh_index, const SourcePos& pos) {
    const tinygltf::Model& model = *file.model;
    if (mesh_index < 0 || static_cast<std::size_t>(mesh_index) >= model.meshes.size()) {
        fail(pos, file,
             "it has no mesh " + std::to_string(mesh_index) + " (it has " +
                 std::to_string(model.meshes.size()) + ")");
    }
    return model.meshes[static_cast<std::size_t>(mesh_index)];
}
}  // namespace

int gltf_primitive_count(const GltfFile& file, int mesh, const SourcePos& pos) {
    return static_cast<int>(mesh_of(file, mesh, pos).primitives.size());
}

MeshData gltf_primitive_mesh(const GltfFile& file, int mesh_index, int primitive_index,
                             const SourcePos& pos) {
    const tinygltf::Mesh& mesh = mesh_of(file, mesh_index, pos);
    if (primitive_index < 0 || static_cast<std::size_t>(primitive_index) >= mesh.primitives.size()) {
        fail(pos, file,
             "mesh " + std::to_string(mesh_index) + " has no primitive " + std::to_string(primitive_index));
    }
    const tinygltf::Primitive& primitive = mesh.primitives[static_cast<std::size_t>(primitive_index)];
    const auto attribute = [&](const char* name) {
        const auto found = primitive.attributes.find(name);
        return found == primitive.attributes.end() ? -1 : found->second;
    };
    if (attribute("POSITION") < 0) {
        fail(pos, file,
             "mesh " + std::to_string(mesh_index) + " primitive " + std::to_string(primitive_index) +
                 " has no POSITION");
    }
    const MeshLimits limits;
    const AccessorView positions = view_of(file, attribute("POSITION"), TINYGLTF_TYPE_VEC3, "POSITION", pos);
    if (positions.count > limits.max_vertices) {
        fail(pos, file,
             "a primitive has more than " + mesh_io::limit_text(limits.max_vertices) + " vertices");
    }
    MeshData data;
    data.positions.reserve(positions.count);
    for (std::size_t i = 0; i < positions.count; ++i) {
        const Vec3 p{component(positions, i, 0), component(positions, i, 1), component(positions, i, 2)};
        if (!(max_component(abs(p)) <= kMaxMeshCoordinate)) {
            fail(pos, file, "POSITION " + std::to_string(i) + " is not finite or beyond float's range");
        }
        data.positions.push_back(p);
    }
    if (attribute("NORMAL") >= 0) {
        const AccessorView normals = view_of(file, attribute("NORMAL"), TINYGLTF_TYPE_VEC3, "NORMAL", pos);
        if (normals.count == positions.count) {
            for (std::size_t i = 0; i < normals.count; ++i) {
                data.normals.push_back(
                    {component(normals, i, 0), component(normals, i, 1), component(normals, i, 2)});
            }
        }
    }
    if (attribute("TEXCOORD_0") >= 0) {
        const AccessorView uvs =
            view_of(file, attribute("TEXCOORD_0"), TINYGLTF_TYPE_VEC2, "TEXCOORD_0", pos);
        if (uvs.count == positions.count) {
            for (std::size_t i = 0; i < uvs.count; ++i) {
                data.uvs.push_back({component(uvs, i, 0), 1 - component(uvs, i, 1)});
            }
        }
    }
    if (attribute("TANGENT") >= 0) {
        const AccessorView tangents = view_of(file, attribute("TANGENT"), TINYGLTF_TYPE_VEC4, "TANGENT", pos);
        if (tangents.count == positions.count) {
            for (std::size_t i = 0; i < tangents.count; ++i) {
                data.tangents.push_back({component(tangents, i, 0), component(tangents, i, 1),
                                         component(tangents, i, 2), component(tangents, i, 3)});
            }
        }
    }
    // The corners: the indices, or the vertices in order.
    std::vector<std::uint32_t> corners;
    if (primitive.indices >= 0) {
        const AccessorView indices = view_of(file, primitive.indices, TINYGLTF_TYPE_SCALAR, "indices", pos);
        if (indices.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            indices.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            indices.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
            fail(pos, file, "indices must be unsigned integers");
        }
        if (indices.count > 3 * limits.max_triangles) {
            fail(pos, file,
                 "a primitive has more than " + mesh_io::limit_text(limits.max_triangles) + " triangles");
        }
        corners.reserve(indices.count);
        for (std::size_t i = 0; i < indices.count; ++i) {
            const double index = component(indices, i, 0);
            if (index >= static_cast<double>(positions.count)) {
                fail(pos, file,
                     "index " + std::to_string(i) + " is " +
                         std::to_string(static_cast<std::uint64_t>(index)) + ", but there are " +
                         std::to_string(positions.count) + " vertices");
            }
            corners.push_back(static_cast<std::uint32_t>(index));
        }
    } else {
        for (std::size_t i = 0; i < positions.count; ++i) {
            corners.push_back(static_cast<std::uint32_t>(i));
        }
    }
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        for (std::size_t i = 0; i + 2 < corners.size(); i += 3) {
            data.triangles.push_back({corners[i], corners[i + 1], corners[i + 2]});
        }
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t i = 0; i + 2 < corners.size(); ++i) {  // every other triangle turns back
            data.triangles.push_back(i % 2 == 0 ? std::array{corners[i], corners[i + 1], corners[i + 2]}
                                                : std::array{corners[i + 1], corners[i], corners[i + 2]});
        }
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
            data.triangles.push_back({corners[0], corners[i], corners[i + 1]});
        }
    } else {
        fail(pos, file,
             "mesh " + std::to_string(mesh_index) + " primitive " + std::to_string(primitive_index) +
                 " is made of points or lines, not triangles");
    }
    return data;
}

}  // namespace glint

namespace glint {

const std::vector<unsigned char>& gltf_image_bytes(const GltfFile& file, int image, const SourcePos& pos) {
    const tinygltf::Model& model = *file.model;
    if (image < 0 || static_cast<std::size_t>(image) >= model.images.size()) {
        fail(pos, file,
             "it has no image " + std::to_string(image) + " (it has " + std::to_string(model.images.size()) +
                 ")");
    }
    const tinygltf::Image& stored = model.images[static_cast<std::size_t>(image)];
    if (!stored.as_is || stored.image.empty()) {
        fail(pos, file,
             "image " + std::to_string(image) + " is not stored in the file" +
                 (stored.uri.empty() ? std::string() : " (it is the file '" + stored.uri + "')"));
    }
    return stored.image;
}

Image read_image_keys(Params& params, const BuildContext& context, bool srgb) {
    const std::string file = params.string("file");
    const std::filesystem::path path = context.resolve(file);
    Image image;
    try {
        if (params.has("gltf_image")) {
            // An image stored inside a glTF model: its encoded bytes, decoded by the same reader.
            const std::int64_t index = params.integer("gltf_image");
            if (index < 0 || index > std::numeric_limits<int>::max()) {
                params.fail("gltf_image", "gltf_image must be a whole number ≥ 0");
            }
            const auto model = load_gltf_file(path, params.pos_of("file"));
            image =
                decode_image(gltf_image_bytes(*model, static_cast<int>(index), params.pos_of("gltf_image")),
                             path.string() + " image " + std::to_string(index), srgb);
        } else {
            image = read_image(path, srgb);
        }
    } catch (const SceneError&) {
        throw;
    } catch (const std::exception& e) {
        // The reader's message starts with the file's path.
        params.fail("file", std::string("cannot read texture image: ") + e.what());
    }
    if (image.width <= 0 || image.height <= 0) {
        params.fail("file", "texture image '" + path.string() + "' has no pixels");
    }
    return image;
}

}  // namespace glint
