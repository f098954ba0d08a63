#include "poly_mesh.h"

#include <darkroom/error.h>

#include <cmath>
#include <string>

namespace darkroom::mesh {
namespace {

// A scalar as the scene sees it: a single component of (or the magnitude of)
// a reader array, still indexed by the mesh's own point or cell numbering.
struct Scalar {
    std::string name;
    ScalarField::Association association;
    std::vector<float> values;
};

void expand(const std::vector<DataArray>& arrays, ScalarField::Association assoc, std::size_t count,
            const std::string& source, std::vector<Scalar>& out) {
    const char* what = assoc == ScalarField::Association::Point ? "point" : "cell";
    for (const auto& a : arrays) {
        if (a.components < 1 || a.values.size() != count * std::size_t(a.components))
            throw Error(source + ": " + what + " array '" + a.name + "' has " + std::to_string(a.values.size()) +
                        " values, expected " + std::to_string(count) + " x " + std::to_string(a.components));
        if (a.components == 1) {
            out.push_back({a.name, assoc, a.values});
            continue;
        }
        // Several components: the magnitude under the array's own name (what
        // ParaView colours by) and each component as <name>_<i>.
        const std::size_t nc = std::size_t(a.components);
        Scalar mag{a.name, assoc, std::vector<float>(count)};
        for (std::size_t i = 0; i < count; ++i) {
            double s = 0;
            for (std::size_t c = 0; c < nc; ++c) s += double(a.values[i * nc + c]) * a.values[i * nc + c];
            mag.values[i] = float(std::sqrt(s));
        }
        out.push_back(std::move(mag));
        for (std::size_t c = 0; c < nc; ++c) {
            Scalar comp{a.name + "_" + std::to_string(c), assoc, std::vector<float>(count)};
            for (std::size_t i = 0; i < count; ++i) comp.values[i] = a.values[i * nc + c];
            out.push_back(std::move(comp));
        }
    }
}

void validate(const CellList& cells, const char* kind, const PolyMesh& m) {
    const std::size_t np = m.pointCount();
    for (std::size_t c = 0; c < cells.size(); ++c) {
        if (cells.cellIds[c] >= m.cellCount)
            throw Error(m.source + ": " + kind + " cell " + std::to_string(c) + " has cell id " +
                        std::to_string(cells.cellIds[c]) + " but there are " + std::to_string(m.cellCount) +
                        " cells");
        if (cells.offsets[c] > cells.offsets[c + 1] || cells.offsets[c + 1] > cells.connectivity.size())
            throw Error(m.source + ": " + kind + " cell " + std::to_string(c) + " has invalid offsets");
        for (std::uint32_t k = cells.offsets[c]; k < cells.offsets[c + 1]; ++k) {
            const std::uint32_t p = cells.connectivity[k];
            if (p == kStripRestart && &cells == &m.strips) continue;
            if (p >= np)
                throw Error(m.source + ": " + kind + " cell " + std::to_string(c) + " references point " +
                            std::to_string(p) + " but there are only " + std::to_string(np) +
                            " points (expected an index in [0, " + std::to_string(np) + "))");
        }
    }
}

// Gathers one object's geometry: which mesh point each new vertex copies, and
// which mesh cell each local cell is.
struct Part {
    Representation representation;
    std::vector<std::uint32_t> vertexSource;  // mesh point per object vertex
    std::vector<std::uint32_t> indices;
    std::vector<std::uint32_t> primitiveCell;  // local cell per primitive
    std::vector<std::uint32_t> cellIds;        // mesh cell per local cell
};

SceneObject finish(Part&& part, const PolyMesh& m, const std::vector<Scalar>& scalars, std::string name) {
    SceneObject o;
    o.name = std::move(name);
    o.representation = part.representation;
    o.vertices.resize(part.vertexSource.size() * 4);
    for (std::size_t i = 0; i < part.vertexSource.size(); ++i) {
        const std::size_t p = part.vertexSource[i];
        o.vertices[4 * i] = m.points[3 * p];
        o.vertices[4 * i + 1] = m.points[3 * p + 1];
        o.vertices[4 * i + 2] = m.points[3 * p + 2];
        o.vertices[4 * i + 3] = 0.f;
    }
    o.indices = std::move(part.indices);
    // An identity map is implied by an empty one; store it only when needed.
    bool identity = part.primitiveCell.size() == part.cellIds.size();
    for (std::size_t i = 0; identity && i < part.primitiveCell.size(); ++i) identity = part.primitiveCell[i] == i;
    if (!identity) o.primitiveCell = std::move(part.primitiveCell);
    for (const auto& s : scalars) {
        ScalarField f{s.name, s.association, {}};
        if (s.association == ScalarField::Association::Point) {
            f.values.resize(part.vertexSource.size());
            for (std::size_t i = 0; i < part.vertexSource.size(); ++i) f.values[i] = s.values[part.vertexSource[i]];
        } else {
            f.values.resize(part.cellIds.size());
            for (std::size_t i = 0; i < part.cellIds.size(); ++i) f.values[i] = s.values[part.cellIds[i]];
        }
        o.fields.push_back(std::move(f));
    }
    return o;
}

Part surfacePart(const PolyMesh& m) {
    Part part{Representation::Surface, {}, {}, {}, {}};
    std::uint32_t local = 0;
    for (std::size_t c = 0; c < m.polygons.size(); ++c, ++local) {
        const std::uint32_t* v = m.polygons.connectivity.data() + m.polygons.offsets[c];
        const std::size_t n = m.polygons.offsets[c + 1] - m.polygons.offsets[c];
        part.cellIds.push_back(m.polygons.cellIds[c]);
        // Fan triangulation: exact for convex polygons, which is what mesh
        // files hold in practice; every triangle maps back to its polygon.
        for (std::size_t k = 1; k + 1 < n; ++k) {
            part.indices.insert(part.indices.end(), {v[0], v[k], v[k + 1]});
            part.primitiveCell.push_back(local);
        }
    }
    for (std::size_t c = 0; c < m.strips.size(); ++c, ++local) {
        const std::uint32_t* v = m.strips.connectivity.data() + m.strips.offsets[c];
        const std::size_t n = m.strips.offsets[c + 1] - m.strips.offsets[c];
        part.cellIds.push_back(m.strips.cellIds[c]);
        std::size_t start = 0;  // first vertex of the current run (after a restart)
        for (std::size_t k = 0; k < n; ++k) {
            if (v[k] == kStripRestart) {
                start = k + 1;
                continue;
            }
            if (k < start + 2) continue;
            const std::uint32_t a = v[k - 2], b = v[k - 1], c2 = v[k];
            if (a == b || b == c2 || a == c2) continue;  // stitching triangles have no area
            // Every other triangle of a strip is flipped to keep one winding.
            if ((k - start) % 2 == 0)
                part.indices.insert(part.indices.end(), {a, b, c2});
            else
                part.indices.insert(part.indices.end(), {b, a, c2});
            part.primitiveCell.push_back(local);
        }
    }
    std::size_t used = 0;
    const std::vector<std::uint32_t> map = renumberByFirstUse(part.indices, m.pointCount(), used);
    part.vertexSource.resize(used);
    for (std::size_t p = 0; p < map.size(); ++p)
        if (map[p] != kStripRestart) part.vertexSource[map[p]] = static_cast<std::uint32_t>(p);
    return part;
}

// Segments join object vertices i and i+1, so each polyline gets its own
// consecutive copy of its points.
Part linePart(const PolyMesh& m) {
    Part part{Representation::Lines, {}, {}, {}, {}};
    for (std::size_t c = 0; c < m.lines.size(); ++c) {
        const std::uint32_t* v = m.lines.connectivity.data() + m.lines.offsets[c];
        const std::size_t n = m.lines.offsets[c + 1] - m.lines.offsets[c];
        const auto local = static_cast<std::uint32_t>(part.cellIds.size());
        part.cellIds.push_back(m.lines.cellIds[c]);
        const auto base = static_cast<std::uint32_t>(part.vertexSource.size());
        part.vertexSource.insert(part.vertexSource.end(), v, v + n);
        for (std::size_t k = 0; k + 1 < n; ++k) {
            part.indices.push_back(base + static_cast<std::uint32_t>(k));
            part.primitiveCell.push_back(local);
        }
    }
    return part;
}

Part vertexPart(const PolyMesh& m) {
    Part part{Representation::Points, {}, {}, {}, {}};
    for (std::size_t c = 0; c < m.vertices.size(); ++c) {
        const auto local = static_cast<std::uint32_t>(part.cellIds.size());
        part.cellIds.push_back(m.vertices.cellIds[c]);
        for (std::uint32_t k = m.vertices.offsets[c]; k < m.vertices.offsets[c + 1]; ++k) {
            part.vertexSource.push_back(m.vertices.connectivity[k]);
            part.primitiveCell.push_back(local);
        }
    }
    return part;
}

}  // namespace

std::vector<std::uint32_t> renumberByFirstUse(std::vector<std::uint32_t>& indices, std::size_t pointCount,
                                              std::size_t& used) {
    // One serial pass: first use is an order, and the indices of real
    // meshes are local enough that this runs at memory speed.
    std::vector<std::uint32_t> map(pointCount, kStripRestart);
    std::uint32_t next = 0;
    for (auto& i : indices) {
        if (map[i] == kStripRestart) map[i] = next++;
        i = map[i];
    }
    used = next;
    return map;
}

std::vector<SceneObject> buildSceneObjects(const PolyMesh& m, const std::string& name) {
    if (m.points.size() % 3 != 0) throw Error(m.source + ": point coordinates are not a multiple of 3");
    validate(m.vertices, "vertex", m);
    validate(m.lines, "line", m);
    validate(m.polygons, "polygon", m);
    validate(m.strips, "strip", m);
    std::vector<Scalar> scalars;
    expand(m.pointData, ScalarField::Association::Point, m.pointCount(), m.source, scalars);
    expand(m.cellData, ScalarField::Association::Cell, m.cellCount, m.source, scalars);

    const std::size_t cells = m.vertices.size() + m.lines.size() + m.polygons.size() + m.strips.size();
    std::vector<Part> parts;
    if (cells == 0) {
        // A bare point set (PLY or OBJ with vertices only): a point cloud.
        Part cloud{Representation::Points, {}, {}, {}, {}};
        cloud.vertexSource.resize(m.pointCount());
        for (std::size_t i = 0; i < m.pointCount(); ++i) cloud.vertexSource[i] = static_cast<std::uint32_t>(i);
        std::vector<Scalar> pointOnly;
        for (auto& s : scalars)
            if (s.association == ScalarField::Association::Point) pointOnly.push_back(std::move(s));
        scalars = std::move(pointOnly);
        parts.push_back(std::move(cloud));
    } else {
        if (m.polygons.size() + m.strips.size() > 0) parts.push_back(surfacePart(m));
        if (m.lines.size() > 0) parts.push_back(linePart(m));
        if (m.vertices.size() > 0) parts.push_back(vertexPart(m));
    }
    std::vector<SceneObject> out;
    const std::size_t count = parts.size();
    for (auto& p : parts) {
        const Representation r = p.representation;
        out.push_back(finish(std::move(p), m, scalars, count == 1 ? name : name + "/" + toString(r)));
    }
    return out;
}

}  // namespace darkroom::mesh
