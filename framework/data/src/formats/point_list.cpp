// Point lists as CSV (see darkroom/data/formats/point_list.h).
#include <darkroom/data/cinema/csv.h>
#include <darkroom/data/formats/point_list.h>
#include <darkroom/error.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace darkroom {

PointList readPointListCsv(const std::string& path) {
    CsvReadOptions strict;
    strict.strict = true;
    const CsvTable t = readCsvFile(path, strict);
    auto column = [&](const char* name) -> long {
        const auto it = std::find(t.header.begin(), t.header.end(), name);
        return it == t.header.end() ? -1 : long(it - t.header.begin());
    };
    const long cx = column("x"), cy = column("y"), cz = column("z"), cr = column("radius");
    if (cx < 0 || cy < 0 || cz < 0) {
        std::string have;
        for (const auto& h : t.header) have += (have.empty() ? "" : ", ") + h;
        throw Error(fmt::format("{}:1: a point list needs columns x, y and z (and optionally radius and fields); "
                                "the header has {}",
                                path, have));
    }
    PointList p;
    std::vector<std::size_t> fieldColumns;
    for (std::size_t c = 0; c < t.header.size(); ++c)
        if (long(c) != cx && long(c) != cy && long(c) != cz && long(c) != cr) {
            fieldColumns.push_back(c);
            p.fields.push_back({t.header[c], ScalarField::Association::Point, {}});
        }
    std::size_t skipped = 0;
    int firstSkipped = 0;
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
        const auto& row = t.rows[r];
        auto number = [&](std::size_t c) {
            const std::string& cell = row[c];
            if (cell.empty()) return std::numeric_limits<double>::quiet_NaN();
            double v;
            if (!parseCsvNumber(cell, v))
                throw Error(fmt::format("{}:{}: column '{}' holds '{}'; expected a number", path, t.rowLines[r],
                                        t.header[c], cell));
            return v;
        };
        const Vec3 c{number(std::size_t(cx)), number(std::size_t(cy)), number(std::size_t(cz))};
        if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
            if (!skipped++) firstSkipped = t.rowLines[r];
            continue;
        }
        double radius = cr >= 0 ? number(std::size_t(cr)) : std::numeric_limits<double>::quiet_NaN();
        if (radius < 0)
            throw Error(fmt::format("{}:{}: radius {} is negative; expected a radius in world units (or an empty cell)",
                                    path, t.rowLines[r], radius));
        p.centers.push_back(c);
        if (cr >= 0) p.radii.push_back(float(radius));
        for (std::size_t f = 0; f < fieldColumns.size(); ++f) p.fields[f].values.push_back(float(number(fieldColumns[f])));
    }
    if (skipped)
        p.warnings.push_back(fmt::format("{}:{}: {} point(s) without a finite x, y, z skipped (first here)", path,
                                         firstSkipped, skipped));
    return p;
}

namespace {

// For a lines object, the polyline of each vertex (0, 1, ... in order of
// first use; -1 for a vertex on no segment): segment k joins vertices
// indices[k] and indices[k] + 1, so a run of segments each starting where
// the last ended is one polyline. Empty for other objects.
std::vector<long> lineNumbers(const SceneObject& object) {
    if (object.representation != Representation::Lines) return {};
    std::vector<long> line(object.vertexCount(), -1);
    long current = -1;
    std::size_t previousEnd = std::size_t(-1);
    for (const std::uint32_t start : object.indices) {
        if (std::size_t(start) + 1 >= line.size()) continue;
        if (start != previousEnd || line[start] < 0) line[start] = ++current;
        line[start + 1] = line[start];
        previousEnd = std::size_t(start) + 1;
    }
    return line;
}

}  // namespace

std::string pointListCsv(const SceneObject& object) {
    std::vector<const ScalarField*> fields;
    for (const ScalarField& f : object.fields)
        if (f.values.size() == object.vertexCount()) fields.push_back(&f);
    // A lines object keeps its polylines: consecutive rows with one `line`
    // value are joined by a segment (readers that do not know the column
    // see a field).
    const std::vector<long> line = lineNumbers(object);
    if (!line.empty())
        for (const ScalarField* f : fields)
            if (f->name == "line")
                throw Error("the lines object '" + object.name + "' has a field named 'line', the column its point list "
                            "joins lines by; rename the field");
    std::string out = "x,y,z,radius";
    if (!line.empty()) out += ",line";
    for (const ScalarField* f : fields) out += "," + quoteCsvCell(f->name);
    out += "\n";
    for (std::size_t v = 0; v < object.vertexCount(); ++v) {
        // Shortest text that reads back to the same float.
        for (int k = 0; k < 4; ++k) out += fmt::format("{}{}", k ? "," : "", object.vertices[4 * v + std::size_t(k)]);
        if (!line.empty()) out += line[v] < 0 ? std::string(",") : fmt::format(",{}", line[v]);
        for (const ScalarField* f : fields) {
            const float x = f->values[v];
            out += "," + (std::isnan(x) ? std::string() : fmt::format("{}", x));
        }
        out += "\n";
    }
    return out;
}

}  // namespace darkroom
