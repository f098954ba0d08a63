#include "ply_header.h"

#include <darkroom/data/formats/number_text.h>
#include <darkroom/error.h>
#include <darkroom/limits.h>

#include <algorithm>
#include <optional>

namespace darkroom::ply {
namespace {

// Refuses a header line: "<path>:<line>: <what>".
struct LineError {
    const std::string& path;
    int line;
    [[noreturn]] void operator()(const std::string& what) const {
        throw InputError(path + ":" + std::to_string(line) + ": " + what);
    }
};

std::optional<ValueType> plyType(std::string_view s) {
    if (s == "char" || s == "int8") return ValueType::Int8;
    if (s == "uchar" || s == "uint8") return ValueType::UInt8;
    if (s == "short" || s == "int16") return ValueType::Int16;
    if (s == "ushort" || s == "uint16") return ValueType::UInt16;
    if (s == "int" || s == "int32") return ValueType::Int32;
    if (s == "uint" || s == "uint32") return ValueType::UInt32;
    if (s == "float" || s == "float32") return ValueType::Float32;
    if (s == "double" || s == "float64") return ValueType::Float64;
    return std::nullopt;
}

Property property(const std::vector<std::string_view>& t, const LineError& bad) {
    if (t.size() == 5 && t[1] == "list") {
        const auto ct = plyType(t[2]), vt = plyType(t[3]);
        if (!ct || !vt) bad("unknown PLY type in list property '" + std::string(t[4]) + "'");
        return {std::string(t[4]), true, *ct, *vt};
    }
    if (t.size() == 3) {
        const auto vt = plyType(t[1]);
        if (!vt)
            bad("unknown PLY type '" + std::string(t[1]) +
                "' (expected char, uchar, short, ushort, int, uint, float, double or int8..float64)");
        return {std::string(t[2]), false, ValueType::UInt8, *vt};
    }
    bad("expected 'property <type> <name>' or 'property list <count type> <type> <name>'");
}

void format(const std::vector<std::string_view>& t, Header& h, const LineError& bad) {
    if (t.size() != 3) bad("expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
    if (t[1] == "ascii") h.ascii = true;
    else if (t[1] == "binary_little_endian") h.bigEndian = false;
    else if (t[1] == "binary_big_endian") h.bigEndian = true;
    else bad("unknown PLY format '" + std::string(t[1]) + "', expected ascii, binary_little_endian or binary_big_endian");
}

}  // namespace

std::size_t Element::fixedSize() const {
    std::size_t n = 0;
    for (const auto& p : properties) {
        if (p.isList) return 0;
        n += mesh::sizeOf(p.type);
    }
    return n;
}

Header readHeader(const std::string& path, mesh::TextCursor& cur) {
    const std::string_view magic = cur.restOfLine();
    if (magic != "ply") throw Error(path + ":1: missing PLY header: expected 'ply' on the first line");
    Header h;
    bool sawFormat = false;
    for (;;) {
        if (cur.atEnd()) cur.fail("unexpected end of file in the PLY header, expected 'end_header'");
        const int line = cur.line();
        const auto t = mesh::splitBlanks(cur.restOfLine());
        const LineError bad{path, line};
        if (t.empty()) continue;
        if (t[0] == "comment" || t[0] == "obj_info") continue;
        if (t[0] == "end_header") break;
        if (t[0] == "format") {
            format(t, h, bad);
            sawFormat = true;
        } else if (t[0] == "element") {
            long long n = 0;
            if (t.size() != 3 || !mesh::parseInteger(t[2], n) || n < 0) bad("expected 'element <name> <count>'");
            for (const auto& e : h.elements)
                if (e.name == t[1] && (e.name == "vertex" || e.name == "face" || e.name == "tristrips"))
                    bad("a second 'element " + e.name + "' (the first is on line " + std::to_string(e.line) +
                        "); expected one");
            h.elements.push_back({std::string(t[1]), std::size_t(n), {}, line});
        } else if (t[0] == "property") {
            if (h.elements.empty()) bad("'property' before any 'element'");
            h.elements.back().properties.push_back(property(t, bad));
        } else {
            bad("unexpected '" + std::string(t[0]) + "' in the PLY header");
        }
    }
    if (!sawFormat) cur.fail("PLY header without a 'format' line");
    return h;
}

void checkElements(const std::string& path, const Header& header, std::size_t bytesLeft) {
    const Element* vertex = nullptr;
    for (const auto& e : header.elements) {
        checkCount(path, header, e, bytesLeft);
        if (e.name == "vertex") vertex = &e;
    }
    if (!vertex) throw InputError(path + ": no 'element vertex' in the PLY header; expected vertices with x, y, z");
    for (const char* axis : {"x", "y", "z"}) {
        bool found = false;
        for (const auto& p : vertex->properties) found |= !p.isList && p.name == axis;
        if (!found)
            throw InputError(path + ":" + std::to_string(vertex->line) + ": 'element vertex' has no scalar property '" +
                             axis + "'; expected x, y and z");
    }
    // Points and fields are float32: 4 bytes per scalar property.
    checkBytes(Limit::DecodedBytes, std::uint64_t(vertex->count) * 4 * std::max<std::size_t>(vertex->properties.size(), 3),
               path, "'element vertex' of " + std::to_string(vertex->count) + " vertices");
}

// Each instance takes at least its fixed-size bytes (binary) or 2 characters
// per property, and at least one (a line end) in all (ASCII).
void checkCount(const std::string& path, const Header& header, const Element& e, std::size_t bytesLeft) {
    std::size_t least = 0;
    for (const auto& p : e.properties) least += header.ascii ? 2 : mesh::sizeOf(p.isList ? p.countType : p.type);
    if (header.ascii) least = std::max<std::size_t>(least, 1);
    if (least > 0 && e.count > bytesLeft / least)
        throw InputError(path + ":" + std::to_string(e.line) + ": element '" + e.name + "' declares " +
                         std::to_string(e.count) + " entries but the " + std::to_string(bytesLeft) +
                         " bytes left in the file hold at most " + std::to_string(bytesLeft / least) +
                         " (truncated?)");
}

}  // namespace darkroom::ply
