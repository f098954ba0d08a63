#include "legacy_layout.h"

#include "legacy_lines.h"
#include "legacy_types.h"

#include <darkroom/data/formats/text_cursor.h>

#include <limits>

namespace darkroom::vtk_legacy {
namespace {

using mesh::ValueType;

bool isFloat(ValueType t) { return t == ValueType::Float32 || t == ValueType::Float64; }

// Follows the general reader (vtk_legacy_reader.cpp) keyword by keyword;
// every check it makes is made here too, and whatever it would do
// differently from reading plain triangles, or refuse, ends the scan with
// nothing: the general reader then reads the file, or words the error.
class Scanner {
public:
    explicit Scanner(const windowed::FileRangeReader& file) : file_(file) {}

    std::optional<TriangleLayout> scan() {
        std::optional<std::uint64_t> at = header();
        while (at) {
            const std::optional<Line> line = lineAt(file_, *at, true);
            if (!line || !line->complete) return std::nullopt;
            if (line->atEnd) return finished();
            at = keyword(*line);
        }
        return std::nullopt;
    }

private:
    // The four header lines; where the body starts.
    std::optional<std::uint64_t> header() const {
        const auto first = lineAt(file_, 0, false);
        if (!first || !first->complete || first->text.substr(0, 5) != "# vtk") return std::nullopt;
        const auto title = lineAt(file_, first->end, false);
        if (!title || !title->complete) return std::nullopt;
        const auto format = lineAt(file_, title->end, false);
        if (!format || !format->complete || format->tokens != std::vector<std::string>{"BINARY"}) return std::nullopt;
        const auto dataset = lineAt(file_, format->end, true);
        if (!dataset || dataset->atEnd || !dataset->complete ||
            dataset->tokens != std::vector<std::string>{"DATASET", "POLYDATA"})
            return std::nullopt;
        return dataset->end;
    }

    // Where the next keyword line may start, or nothing.
    std::optional<std::uint64_t> keyword(const Line& line) {
        const std::string& k = line.tokens[0];
        if (k == "POINTS") return points(line);
        if (k == "POLYGONS") return polygons(line);
        if (k == "POINT_DATA") return pointData(line);
        if (k == "SCALARS") return scalars(line);
        return std::nullopt;  // VERTICES, LINES, TRIANGLE_STRIPS, CELL_DATA, FIELD, METADATA, ...
    }

    // The general reader's count(): a non-negative integer that the rest of
    // the file, after its line, could hold a byte of each of.
    std::optional<std::uint64_t> count(const std::string& token, const Line& line) const {
        long long n = 0;
        if (!mesh::parseInteger(token, n) || n < 0) return std::nullopt;
        if (std::uint64_t(n) > file_.size() - line.end + 1) return std::nullopt;
        return std::uint64_t(n);
    }

    // An array from `offset`, if the file holds it whole.
    std::optional<ArrayAt> array(std::uint64_t offset, std::uint64_t count, ValueType type) const {
        if (count > (file_.size() - offset) / mesh::sizeOf(type)) return std::nullopt;
        return ArrayAt{offset, count, type};
    }

    std::optional<std::uint64_t> points(const Line& line) {
        if (seenPoints_ || line.tokens.size() != 3) return std::nullopt;
        const auto n = count(line.tokens[1], line);
        const auto type = legacyType(line.tokens[2]);
        if (!n || !type || !isFloat(*type)) return std::nullopt;
        const auto points = array(line.end, 3 * *n, *type);
        if (!points) return std::nullopt;
        seenPoints_ = true;
        layout_.pointCount = *n;
        layout_.points = *points;
        return points->offset + points->bytes();
    }

    std::optional<std::uint64_t> polygons(const Line& line) {
        if (!seenPoints_ || seenPolygons_ || line.tokens.size() != 3) return std::nullopt;
        const auto a = count(line.tokens[1], line), b = count(line.tokens[2], line);
        if (!a || !b) return std::nullopt;
        // The general reader looks at the very next line for the 5.1 layout.
        const auto next = lineAt(file_, line.end, false);
        if (!next) return std::nullopt;
        const auto offsets = startsWith(*next, "OFFSETS");
        if (!offsets) return std::nullopt;
        seenPolygons_ = true;
        if (*offsets) return offsetsAndConnectivity(*next, *a, *b);
        // The classic layout: b ints, 4 per triangle.
        if (*a == 0 || *b / 4 != *a || *b % 4 != 0) return std::nullopt;
        const auto cells = array(line.end, *b, ValueType::Int32);
        if (!cells) return std::nullopt;
        layout_.triangleCount = *a;
        layout_.cells = *cells;
        return cells->offset + cells->bytes();
    }

    // VTK 5.1: `OFFSETS type`, a offsets, `CONNECTIVITY type`, b indices.
    std::optional<std::uint64_t> offsetsAndConnectivity(const Line& line, std::uint64_t a, std::uint64_t b) {
        if (!line.complete || line.tokens.size() != 2 || a < 2 || b / 3 != a - 1 || b % 3 != 0) return std::nullopt;
        const auto offsetType = legacyType(line.tokens[1]);
        if (!offsetType || isFloat(*offsetType)) return std::nullopt;
        const auto offsets = array(line.end, a, *offsetType);
        if (!offsets) return std::nullopt;
        const auto header = lineAt(file_, offsets->offset + offsets->bytes(), true);
        if (!header || header->atEnd || !header->complete || header->tokens.size() != 2 ||
            header->tokens[0] != "CONNECTIVITY")
            return std::nullopt;
        const auto indexType = legacyType(header->tokens[1]);
        if (!indexType || isFloat(*indexType)) return std::nullopt;
        const auto connectivity = array(header->end, b, *indexType);
        if (!connectivity) return std::nullopt;
        layout_.offsetsLayout = true;
        layout_.triangleCount = a - 1;
        layout_.offsets = *offsets;
        layout_.connectivity = *connectivity;
        return connectivity->offset + connectivity->bytes();
    }

    std::optional<std::uint64_t> pointData(const Line& line) {
        if (!seenPoints_ || seenPointData_ || line.tokens.size() != 2) return std::nullopt;
        const auto n = count(line.tokens[1], line);
        // Another count is an error of the general reader's (arrays that do not match the points).
        if (!n || *n != layout_.pointCount) return std::nullopt;
        seenPointData_ = true;
        return line.end;
    }

    // `SCALARS name type [1]`, an optional `LOOKUP_TABLE` line, a value per point.
    std::optional<std::uint64_t> scalars(const Line& line) {
        const auto& t = line.tokens;
        if (!seenPointData_ || t.size() < 3 || t.size() > 4) return std::nullopt;
        if (t.size() == 4) {
            const auto components = count(t[3], line);
            if (!components || *components != 1) return std::nullopt;
        }
        const auto type = legacyType(t[2]);
        if (!type || !isFloat(*type)) return std::nullopt;
        const auto next = lineAt(file_, line.end, false);
        if (!next) return std::nullopt;
        const auto table = startsWith(*next, "LOOKUP_TABLE");
        if (!table || (*table && !next->complete)) return std::nullopt;
        const auto values = array(*table ? next->end : line.end, layout_.pointCount, *type);
        if (!values) return std::nullopt;
        layout_.pointScalars.emplace_back(t[1], *values);
        return values->offset + values->bytes();
    }

    std::optional<TriangleLayout> finished() const {
        // Indices are 32-bit, and kStripRestart marks a dropped point.
        constexpr std::uint64_t kMax = std::numeric_limits<std::uint32_t>::max();
        if (!seenPolygons_ || layout_.pointCount >= kMax || layout_.triangleCount > kMax / 3) return std::nullopt;
        return layout_;
    }

    const windowed::FileRangeReader& file_;
    TriangleLayout layout_;
    bool seenPoints_ = false, seenPolygons_ = false, seenPointData_ = false;
};

}  // namespace

std::optional<TriangleLayout> scanTriangleLayout(const windowed::FileRangeReader& file) { return Scanner(file).scan(); }

}  // namespace darkroom::vtk_legacy
