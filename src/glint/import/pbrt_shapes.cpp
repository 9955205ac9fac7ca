// pbrt-v4 shapes as glint objects, in the shape's own space (docs/import-pbrt.md, "Shapes").
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <utility>

#include "glint/import/pbrt_convert.hpp"
#include "glint/import/scene_tree.hpp"

namespace glint::pbrt {
namespace {

namespace tree = scene_tree;

const std::vector<std::string> kShapeTypes = {"sphere",  "disk",         "cylinder",   "trianglemesh",
                                              "plymesh", "bilinearmesh", "loopsubdiv", "curve"};

Vec3 vertex(const std::vector<double>& positions, std::size_t i) {
    return {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
}

// Whole-number vertex indices, each below `vertices`, `per_face` to a face.
std::vector<std::size_t> checked_indices(const Params& params, const std::string& name, std::size_t per_face,
                                         std::size_t vertices) {
    const PbrtParam* param = params.find(name, {"integer"});
    std::vector<std::size_t> indices;
    if (!param) {
        // pbrt-v4: a mesh of exactly one face may leave its indices out.
        if (vertices == per_face) {
            for (std::size_t i = 0; i < per_face; ++i) {
                indices.push_back(i);
            }
            return indices;
        }
        throw SceneError(params.pos(), "the mesh has " + std::to_string(vertices) +
                                           " vertices and no \"integer " + name + "\"");
    }
    if (param->numbers.size() % per_face != 0) {
        throw SceneError(param->pos, "'" + name + "' has " + std::to_string(param->numbers.size()) +
                                         " values, not a multiple of " + std::to_string(per_face));
    }
    indices.reserve(param->numbers.size());
    for (double index : param->numbers) {
        if (!(index >= 0 && index < static_cast<double>(vertices)) || index != std::floor(index)) {
            throw SceneError(param->pos, "'" + name + "' holds " + tree::number_text(index) +
                                             ", not a vertex index from 0 to " + std::to_string(vertices) +
                                             " - 1");
        }
        indices.push_back(static_cast<std::size_t>(index));
    }
    return indices;
}

// Per-vertex data (normals, uvs) of `arity` numbers each: all vertices or none.
std::vector<double> per_vertex(const Params& params, const std::string& name,
                               const std::vector<std::string>& types, std::size_t arity,
                               std::size_t vertices) {
    const PbrtParam* param = params.find(name, types);
    if (!param) {
        return {};
    }
    if (param->numbers.size() != arity * vertices) {
        throw SceneError(param->pos, "'" + name + "' has " + std::to_string(param->numbers.size() / arity) +
                                         " values for " + std::to_string(vertices) + " vertices");
    }
    return param->numbers;
}

// The faces turned the way pbrt-v4 has them face: with vertex normals, each triangle's geometric
// normal is turned to the side of its normals (pbrt's orientation is then the normals'); without, the
// winding decides, reversed by ReverseOrientation.
void orient_triangles(std::vector<std::size_t>& indices, const std::vector<double>& positions,
                      const std::vector<double>& normals, bool reverse) {
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        bool flip = reverse;
        if (!normals.empty()) {
            const Vec3 p0 = vertex(positions, indices[t]), p1 = vertex(positions, indices[t + 1]),
                       p2 = vertex(positions, indices[t + 2]);
            const Vec3 mean = vertex(normals, indices[t]) + vertex(normals, indices[t + 1]) +
                              vertex(normals, indices[t + 2]);
            flip = dot(cross(p1 - p0, p2 - p0), mean) < 0;
        }
        if (flip) {
            std::swap(indices[t + 1], indices[t + 2]);
        }
    }
}

std::vector<double> as_doubles(const std::vector<std::size_t>& indices) {
    return {indices.begin(), indices.end()};
}

// {type: mesh, positions, indices, normals, uvs}: an inline mesh, refused when the tree could not take it.
Node inline_mesh(const Params& params, const std::vector<double>& positions, std::vector<std::size_t> indices,
                 const std::vector<double>& normals, const std::vector<double>& uvs,
                 const ShapeContext& context) {
    const std::size_t nodes = positions.size() + indices.size() + normals.size() + uvs.size() + 16;
    if (nodes > context.values_left) {
        throw SceneError(params.pos(),
                         "this mesh takes the scene past glint's limit of 1 000 000 values: "
                         "large meshes belong in PLY files (Shape \"plymesh\")");
    }
    orient_triangles(indices, positions, normals, context.reverse_orientation);
    const SourcePos& pos = params.pos();
    Node mesh = tree::map({{"type", tree::text("mesh", pos)},
                           {"positions", tree::numbers(positions, pos)},
                           {"indices", tree::numbers(as_doubles(indices), pos)}},
                          pos);
    if (!normals.empty()) {
        tree::set(mesh, "normals", tree::numbers(normals, pos));
    }
    if (!uvs.empty()) {
        tree::set(mesh, "uvs", tree::numbers(uvs, pos));
    }
    return mesh;
}

std::vector<double> positions_of(const Params& params) {
    std::vector<double> positions = params.numbers("P", {"point3", "point"});
    if (positions.empty()) {
        throw SceneError(params.pos(), "the mesh has no vertices (\"point3 P\")");
    }
    return positions;
}

Node triangle_mesh(const Params& params, const ShapeContext& context) {
    const std::vector<double> positions = positions_of(params);
    const std::size_t vertices = positions.size() / 3;
    std::vector<std::size_t> indices = checked_indices(params, "indices", 3, vertices);
    const std::vector<double> normals = per_vertex(params, "N", {"normal", "normal3"}, 3, vertices);
    const std::vector<double> uvs = per_vertex(params, "uv", {"point2"}, 2, vertices);
    params.numbers("faceIndices", {"integer"});  // for Ptex, which glint does not read
    return inline_mesh(params, positions, std::move(indices), normals, uvs, context);
}

// Each bilinear patch (p00, p10, p01, p11) as the two triangles (p00, p10, p11) and (p00, p11, p01),
// which wind as the patch's ∂p/∂u × ∂p/∂v does and are exact where the patch is flat.
Node bilinear_mesh(const Params& params, const ShapeContext& context) {
    const std::vector<double> positions = positions_of(params);
    const std::size_t vertices = positions.size() / 3;
    const std::vector<std::size_t> patches = checked_indices(params, "indices", 4, vertices);
    const std::vector<double> normals = per_vertex(params, "N", {"normal", "normal3"}, 3, vertices);
    const std::vector<double> uvs = per_vertex(params, "uv", {"point2"}, 2, vertices);
    std::vector<std::size_t> indices;
    indices.reserve(patches.size() / 4 * 6);
    bool curved = false;
    for (std::size_t p = 0; p < patches.size(); p += 4) {
        const std::size_t v00 = patches[p], v10 = patches[p + 1], v01 = patches[p + 2], v11 = patches[p + 3];
        const Vec3 a = vertex(positions, v00), b = vertex(positions, v10), c = vertex(positions, v01),
                   d = vertex(positions, v11);
        const Vec3 n = cross(b - a, c - a);
        const double size = std::max({length(b - a), length(c - a), length(d - a)});
        curved = curved || std::abs(dot(normalize(n), d - a)) > 1e-6 * size;
        indices.insert(indices.end(), {v00, v10, v11, v00, v11, v01});
    }
    if (curved) {
        params.warn(params.pos(),
                    "glint splits each bilinear patch into two triangles: patches that are not "
                    "flat are approximated");
    }
    return inline_mesh(params, positions, std::move(indices), normals, uvs, context);
}

Node loop_subdivision(const Params& params, const ShapeContext& context) {
    const int levels = static_cast<int>(params.number("levels", 3));
    TriangleMesh control;
    control.positions = positions_of(params);
    control.indices = checked_indices(params, "indices", 3, control.positions.size() / 3);
    if (levels < 0 || levels > 8) {
        throw SceneError(params.pos(),
                         "'levels' must be from 0 to 8 (each level makes 4 times the triangles)");
    }
    // Each level multiplies the triangles by 4 and the positions by about 4: refuse before building.
    const std::size_t growth = std::size_t{1} << (2 * levels);
    if ((control.indices.size() + control.positions.size()) * growth > context.values_left) {
        throw SceneError(params.pos(), "subdivided " + std::to_string(levels) +
                                           " times this mesh takes the scene past glint's limit of 1 000 000 "
                                           "values");
    }
    TriangleMesh fine = loop_subdivide(control, levels);
    // Smooth shading: area-weighted vertex normals of the subdivided mesh (pbrt-v4 uses the limit
    // surface's normals, which these approach as the levels grow).
    std::vector<double> normals(fine.positions.size(), 0.0);
    for (std::size_t t = 0; t + 2 < fine.indices.size(); t += 3) {
        const Vec3 p0 = vertex(fine.positions, fine.indices[t]),
                   p1 = vertex(fine.positions, fine.indices[t + 1]),
                   p2 = vertex(fine.positions, fine.indices[t + 2]);
        const Vec3 n = cross(p1 - p0, p2 - p0);
        for (std::size_t k = 0; k < 3; ++k) {
            const std::size_t v = fine.indices[t + k];
            normals[3 * v] += n.x;
            normals[3 * v + 1] += n.y;
            normals[3 * v + 2] += n.z;
        }
    }
    if (context.reverse_orientation) {
        for (double& n : normals) {
            n = -n;
        }
    }
    return inline_mesh(params, fine.positions, std::move(fine.indices), normals, {}, context);
}

void warn_partial(const Params& params, double phimax, bool z_clipped, const std::string& shape) {
    if (phimax < 360 || z_clipped) {
        params.warn(params.pos(), "glint's " + shape + " is whole: phimax, zmin and zmax are left out");
    }
}

void warn_reversed_emitter(const Params& params, const ShapeContext& context, const std::string& shape) {
    if (context.reverse_orientation && context.emits) {
        params.warn(params.pos(),
                    "glint cannot turn a " + shape +
                        "'s normal inwards: ReverseOrientation is left out, and the light emits "
                        "outwards");
    }
}

}  // namespace

std::vector<Node> convert_shape(const Params& params, const std::string& type, const ShapeContext& context) {
    const SourcePos& pos = params.pos();
    std::vector<Node> shapes;
    if (type == "sphere") {
        const double radius = params.number("radius", 1);
        const double zmin = params.number("zmin", -radius), zmax = params.number("zmax", radius);
        warn_partial(params, params.number("phimax", 360), zmin > -radius || zmax < radius, "sphere");
        warn_reversed_emitter(params, context, "sphere");
        shapes.push_back(
            tree::map({{"type", tree::text("sphere", pos)}, {"radius", tree::number(radius, pos)}}, pos));
    } else if (type == "disk") {
        const double height = params.number("height", 0), radius = params.number("radius", 1);
        const double inner = params.number("innerradius", 0);
        warn_partial(params, params.number("phimax", 360), false, "disk");
        const Vec3 normal{0, 0, context.reverse_orientation ? -1.0 : 1.0};
        Node disk = tree::map({{"type", tree::text(inner > 0 ? "annulus" : "disk", pos)},
                               {"center", tree::vec3({0, 0, height}, pos)},
                               {"normal", tree::vec3(normal, pos)}},
                              pos);
        if (inner > 0) {
            tree::set(disk, "inner_radius", tree::number(inner, pos));
            tree::set(disk, "outer_radius", tree::number(radius, pos));
        } else {
            tree::set(disk, "radius", tree::number(radius, pos));
        }
        shapes.push_back(std::move(disk));
    } else if (type == "cylinder") {
        const double radius = params.number("radius", 1);
        const double zmin = params.number("zmin", -1), zmax = params.number("zmax", 1);
        warn_partial(params, params.number("phimax", 360), false, "cylinder");
        warn_reversed_emitter(params, context, "cylinder");
        shapes.push_back(tree::map({{"type", tree::text("cylinder", pos)},
                                    {"base", tree::vec3({0, 0, zmin}, pos)},
                                    {"top", tree::vec3({0, 0, zmax}, pos)},
                                    {"radius", tree::number(radius, pos)},
                                    {"capped", tree::boolean(false, pos)}},
                                   pos));
    } else if (type == "trianglemesh") {
        shapes.push_back(triangle_mesh(params, context));
    } else if (type == "bilinearmesh") {
        shapes.push_back(bilinear_mesh(params, context));
    } else if (type == "loopsubdiv") {
        shapes.push_back(loop_subdivision(params, context));
    } else if (type == "plymesh") {
        const std::string file = params.text("filename", "");
        if (file.empty()) {
            throw SceneError(pos, "a plymesh needs \"string filename\"");
        }
        if (params.has("displacement")) {
            params.find("displacement", {"texture", "float"});
            params.number("edgelength", 1);
            params.warn(pos, "glint does not displace meshes: 'displacement' is left out");
        }
        warn_reversed_emitter(params, context, "PLY mesh");
        shapes.push_back(
            tree::map({{"type", tree::text("mesh", pos)}, {"file", tree::text(file, pos)}}, pos));
    } else if (type == "curve") {
        params.warn(pos, "glint has no curves: this shape is left out");
        for (const PbrtParam& param : params.statement().params) {
            param.used = true;
        }
    } else {
        throw SceneError(pos, unknown_name_message("shape", type, kShapeTypes));
    }
    if (params.has("alpha")) {
        params.find("alpha", {"float", "texture"});
        params.warn(pos, "glint has no alpha cut-outs: 'alpha' is left out and the shape is solid");
    }
    params.warn_unread("the shape");
    return shapes;
}

// Loop's subdivision (Charles Loop, 1987) with Warren's weights, as pbrt-v4's loopsubdiv: each level
// puts a vertex on every edge and splits every triangle into four, then the last level's vertices are
// moved to their limit positions. Boundary edges and vertices follow the cubic B-spline of the
// boundary, so open meshes keep their border curves.
TriangleMesh loop_subdivide(const TriangleMesh& control, int levels) {
    TriangleMesh mesh = control;
    using Edge = std::pair<std::size_t, std::size_t>;
    const auto edge_of = [](std::size_t a, std::size_t b) { return a < b ? Edge{a, b} : Edge{b, a}; };
    // Warren's β: the weight of each of the n neighbours when a vertex of valence n is moved.
    const auto beta = [](std::size_t n) { return n == 3 ? 3.0 / 16 : 3.0 / (8.0 * static_cast<double>(n)); };

    // The neighbours of each vertex, and which of them are across a boundary edge (an edge of one face).
    struct Ring {
        std::vector<std::size_t> neighbours;
        std::vector<std::size_t> boundary_neighbours;
    };
    const auto rings_of = [&](const TriangleMesh& m, std::map<Edge, std::vector<std::size_t>>& opposite) {
        opposite.clear();
        for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
            for (std::size_t k = 0; k < 3; ++k) {
                const std::size_t a = m.indices[t + k], b = m.indices[t + (k + 1) % 3],
                                  c = m.indices[t + (k + 2) % 3];
                opposite[edge_of(a, b)].push_back(c);
            }
        }
        std::vector<Ring> rings(m.positions.size() / 3);
        for (const auto& [edge, across] : opposite) {
            rings[edge.first].neighbours.push_back(edge.second);
            rings[edge.second].neighbours.push_back(edge.first);
            if (across.size() == 1) {
                rings[edge.first].boundary_neighbours.push_back(edge.second);
                rings[edge.second].boundary_neighbours.push_back(edge.first);
            }
        }
        return rings;
    };
    const auto add = [](std::vector<double>& out, const Vec3& p) { out.insert(out.end(), {p.x, p.y, p.z}); };
    // A vertex moved by a mask: `centre` of itself and `side` for each of its two boundary neighbours
    // on a boundary; else by `interior_weight(n)` for each of its n neighbours. A vertex where several
    // boundaries meet (non-manifold) stays where it is.
    const auto moved = [](const std::vector<double>& positions, std::size_t v, const Ring& ring,
                          double centre, double side,
                          const std::function<double(std::size_t)>& interior_weight) {
        const Vec3 p = vertex(positions, v);
        if (ring.boundary_neighbours.size() == 2) {
            return centre * p + side * (vertex(positions, ring.boundary_neighbours[0]) +
                                        vertex(positions, ring.boundary_neighbours[1]));
        }
        if (!ring.boundary_neighbours.empty() || ring.neighbours.empty()) {
            return p;
        }
        const double w = interior_weight(ring.neighbours.size());
        Vec3 sum{0, 0, 0};
        for (std::size_t q : ring.neighbours) {
            sum = sum + vertex(positions, q);
        }
        return (1 - static_cast<double>(ring.neighbours.size()) * w) * p + w * sum;
    };

    std::map<Edge, std::vector<std::size_t>> opposite;
    for (int level = 0; level < levels; ++level) {
        const std::vector<Ring> rings = rings_of(mesh, opposite);
        TriangleMesh next;
        // Even vertices: the old ones, moved.
        for (std::size_t v = 0; v < rings.size(); ++v) {
            add(next.positions, moved(mesh.positions, v, rings[v], 0.75, 0.125, beta));
        }
        // Odd vertices: one on each edge.
        std::map<Edge, std::size_t> edge_vertex;
        for (const auto& [edge, across] : opposite) {
            const Vec3 a = vertex(mesh.positions, edge.first), b = vertex(mesh.positions, edge.second);
            Vec3 p = 0.5 * (a + b);
            if (across.size() == 2) {
                p = 0.375 * (a + b) +
                    0.125 * (vertex(mesh.positions, across[0]) + vertex(mesh.positions, across[1]));
            }
            edge_vertex[edge] = next.positions.size() / 3;
            add(next.positions, p);
        }
        // Four triangles for each, wound as the old one.
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const std::size_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
            const std::size_t ab = edge_vertex[edge_of(a, b)], bc = edge_vertex[edge_of(b, c)],
                              ca = edge_vertex[edge_of(c, a)];
            next.indices.insert(next.indices.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        mesh = std::move(next);
    }
    // The limit positions: interior vertices by Loop's limit mask γ = 1 / (n + 3 / (8β)), boundary
    // vertices by pbrt's mask (1/5, 3/5, 1/5) along the boundary.
    const std::vector<Ring> rings = rings_of(mesh, opposite);
    std::vector<double> limit;
    limit.reserve(mesh.positions.size());
    const auto gamma = [&](std::size_t n) { return 1 / (static_cast<double>(n) + 3 / (8 * beta(n))); };
    for (std::size_t v = 0; v < rings.size(); ++v) {
        add(limit, moved(mesh.positions, v, rings[v], 0.6, 0.2, gamma));
    }
    mesh.positions = std::move(limit);
    return mesh;
}

}  // namespace glint::pbrt
