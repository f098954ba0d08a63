// .npy parsing: the magic, the version-dependent header length, the Python
// dict literal holding 'descr', 'fortran_order' and 'shape', then the values
// converted to float32 in C order.
#include <darkroom/error.h>
#include <darkroom/data/formats/npy.h>
#include <darkroom/limits.h>

#include <fmt/format.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>

namespace darkroom {

namespace {

// A cursor over the header dict, which numpy writes as a Python literal:
// {'descr': '<f4', 'fortran_order': False, 'shape': (1024, 1024), }
class DictParser {
public:
    DictParser(std::string_view text, const std::string& where) : s_(text), where_(where) {}

    NpyHeader parse() {
        NpyHeader h;
        bool haveDescr = false, haveOrder = false, haveShape = false;
        expect('{');
        for (;;) {
            skipSpace();
            if (peek() == '}') break;
            const std::string key = quoted();
            expect(':');
            skipSpace();
            if (key == "descr") {
                if (peek() == '[')
                    fail("'descr' is a structured dtype (a list of fields); only plain numeric arrays are read");
                h.descr = quoted();
                haveDescr = true;
            } else if (key == "fortran_order") {
                h.fortranOrder = boolean();
                haveOrder = true;
            } else if (key == "shape") {
                h.shape = tuple();
                haveShape = true;
            } else {
                fail("unexpected key '" + key + "' (expected descr, fortran_order and shape)");
            }
            skipSpace();
            if (peek() == ',') ++i_;
            else if (peek() != '}') fail("expected ',' or '}' after the value of '" + key + "'");
        }
        if (!haveDescr || !haveOrder || !haveShape)
            fail("the header lacks 'descr', 'fortran_order' or 'shape'");
        return h;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw Error(fmt::format("{}: malformed .npy header: {} (header: {})", where_, what,
                                s_.substr(0, 120)));
    }
    char peek() const { return i_ < s_.size() ? s_[i_] : '\0'; }
    void skipSpace() {
        while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n')) ++i_;
    }
    void expect(char c) {
        skipSpace();
        if (peek() != c) fail(fmt::format("expected '{}' at offset {}", c, i_));
        ++i_;
    }
    std::string quoted() {
        skipSpace();
        const char q = peek();
        if (q != '\'' && q != '"') fail(fmt::format("expected a quoted string at offset {}", i_));
        const std::size_t end = s_.find(q, i_ + 1);
        if (end == std::string_view::npos) fail("unterminated string");
        std::string out(s_.substr(i_ + 1, end - i_ - 1));
        i_ = end + 1;
        return out;
    }
    bool boolean() {
        if (s_.substr(i_, 4) == "True") return i_ += 4, true;
        if (s_.substr(i_, 5) == "False") return i_ += 5, false;
        fail("'fortran_order' must be True or False");
    }
    std::vector<std::size_t> tuple() {
        expect('(');
        std::vector<std::size_t> out;
        for (;;) {
            skipSpace();
            if (peek() == ')') break;
            std::size_t v = 0;
            bool any = false;
            while (peek() >= '0' && peek() <= '9') {
                if (v > (std::numeric_limits<std::size_t>::max() - 9) / 10) fail("a dimension is too large");
                v = v * 10 + std::size_t(s_[i_++] - '0');
                any = true;
            }
            if (peek() == 'L') ++i_;  // Python 2 longs
            if (!any) fail("'shape' must be a tuple of non-negative integers");
            out.push_back(v);
            skipSpace();
            if (peek() == ',') ++i_;
            else if (peek() != ')') fail("expected ',' or ')' in 'shape'");
        }
        ++i_;
        return out;
    }

    std::string_view s_;
    const std::string& where_;
    std::size_t i_ = 0;
};

enum class Kind { Float, Signed, Unsigned, Bool };

struct DType {
    Kind kind;
    std::size_t size;
    bool bigEndian;
};

DType parseDescr(const std::string& d, const std::string& where) {
    const auto bad = [&]() -> DType {
        throw Error(fmt::format("{}: unsupported dtype '{}'; expected a numeric dtype such as '<f4', "
                                "'<f8', '|u1', '<i4' (either byte order)",
                                where, d));
    };
    if (d.size() < 3) return bad();
    const char order = d[0];
    if (order != '<' && order != '>' && order != '|' && order != '=') return bad();
    DType t{};
    switch (d[1]) {
        case 'f': t.kind = Kind::Float; break;
        case 'i': t.kind = Kind::Signed; break;
        case 'u': t.kind = Kind::Unsigned; break;
        case 'b': t.kind = Kind::Bool; break;
        default: return bad();
    }
    const std::string size = d.substr(2);
    if (size == "1") t.size = 1;
    else if (size == "2") t.size = 2;
    else if (size == "4") t.size = 4;
    else if (size == "8") t.size = 8;
    else return bad();
    if (t.kind == Kind::Float && t.size < 4) return bad();  // half floats: not written by any Cinema tool
    if (t.kind == Kind::Bool && t.size != 1) return bad();
    // '=' is the writer's native order; every numpy platform that writes Cinema data is little-endian.
    t.bigEndian = order == '>';
    return t;
}

float convert(const unsigned char* p, const DType& t) {
    unsigned char b[8];
    std::memcpy(b, p, t.size);
    const bool swap = t.size > 1 && t.bigEndian != (std::endian::native == std::endian::big);
    if (swap)
        for (std::size_t i = 0; i < t.size / 2; ++i) std::swap(b[i], b[t.size - 1 - i]);
    switch (t.kind) {
        case Kind::Float:
            if (t.size == 4) { float v; std::memcpy(&v, b, 4); return v; }
            { double v; std::memcpy(&v, b, 8); return float(v); }
        case Kind::Bool: return b[0] ? 1.f : 0.f;
        case Kind::Unsigned:
            switch (t.size) {
                case 1: return b[0];
                case 2: { std::uint16_t v; std::memcpy(&v, b, 2); return v; }
                case 4: { std::uint32_t v; std::memcpy(&v, b, 4); return float(v); }
                default: { std::uint64_t v; std::memcpy(&v, b, 8); return float(v); }
            }
        case Kind::Signed:
            switch (t.size) {
                case 1: { std::int8_t v; std::memcpy(&v, b, 1); return v; }
                case 2: { std::int16_t v; std::memcpy(&v, b, 2); return v; }
                case 4: { std::int32_t v; std::memcpy(&v, b, 4); return float(v); }
                default: { std::int64_t v; std::memcpy(&v, b, 8); return float(v); }
            }
    }
    return 0;
}

// The number of values; refused when it (times 16, room for any dtype's bytes) overflows.
std::size_t product(const std::vector<std::size_t>& shape, const std::string& where) {
    std::size_t n = 1;
    for (std::size_t d : shape)
        if (d != 0 && n > std::numeric_limits<std::size_t>::max() / 16 / d) {
            std::string text;
            for (std::size_t k : shape) text += (text.empty() ? "" : ", ") + std::to_string(k);
            throw InputError(fmt::format("{}: shape ({}) holds more values than can be addressed; expected an "
                                         "array that fits in memory",
                                         where, text));
        } else {
            n *= d;
        }
    for (std::size_t d : shape)
        if (d == 0) return 0;
    return n;
}

}  // namespace

std::size_t NpyArray::count() const {
    std::size_t n = 1;
    for (std::size_t d : shape) n *= d;
    return n;
}

NpyHeader parseNpyHeader(std::string_view bytes, const std::string& where) {
    if (bytes.size() < 10 || bytes.substr(0, 6) != "\x93NUMPY")
        throw Error(fmt::format("{}: not a .npy array (expected the magic \\x93NUMPY at the start)", where));
    const auto major = static_cast<unsigned char>(bytes[6]);
    std::size_t length = 0, offset = 0;
    if (major == 1) {
        length = static_cast<unsigned char>(bytes[8]) | (std::size_t(static_cast<unsigned char>(bytes[9])) << 8);
        offset = 10;
    } else if (major == 2 || major == 3) {
        if (bytes.size() < 12) throw Error(fmt::format("{}: .npy header is truncated", where));
        for (int i = 3; i >= 0; --i) length = (length << 8) | static_cast<unsigned char>(bytes[8 + i]);
        offset = 12;
    } else {
        throw Error(fmt::format("{}: unsupported .npy version {}.{} (expected 1.0, 2.0 or 3.0)", where,
                                major, static_cast<unsigned char>(bytes[7])));
    }
    if (bytes.size() - offset < length)
        throw Error(fmt::format("{}: .npy header claims {} bytes but the member has only {}", where, length,
                                bytes.size() - offset));
    NpyHeader h = DictParser(bytes.substr(offset, length), where).parse();
    const DType t = parseDescr(h.descr, where);  // validates
    h.dataOffset = offset + length;
    product(h.shape, where);  // refuses a shape whose size overflows
    h.dataBytes = product(h.shape, where) * t.size;
    return h;
}

NpyArray parseNpy(std::string_view bytes, const std::string& where) {
    const NpyHeader h = parseNpyHeader(bytes, where);
    const DType t = parseDescr(h.descr, where);
    NpyArray a;
    a.descr = h.descr;
    a.shape = h.shape;
    a.fortranOrder = h.fortranOrder;
    const std::size_t n = product(h.shape, where);
    checkBytes(Limit::DecodedBytes, std::uint64_t(n) * sizeof(float), where, "decoded array");
    const std::size_t have = bytes.size() - h.dataOffset;
    if (have < n * t.size)
        throw Error(fmt::format("{}: data is truncated: shape needs {} values of {} bytes ({}), the member "
                                "holds {} bytes",
                                where, n, t.size, n * t.size, have));
    a.values.resize(n);
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data() + h.dataOffset);
    if (!h.fortranOrder || h.shape.size() < 2) {
        for (std::size_t i = 0; i < n; ++i) a.values[i] = convert(data + i * t.size, t);
        return a;
    }
    // Fortran order: the first index varies fastest. Walk the file order with a
    // multi-index and scatter each value to its C-order position.
    const std::size_t dims = h.shape.size();
    std::vector<std::size_t> index(dims, 0), cStride(dims, 1);
    for (std::size_t d = dims - 1; d > 0; --d) cStride[d - 1] = cStride[d] * h.shape[d];
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t c = 0;
        for (std::size_t d = 0; d < dims; ++d) c += index[d] * cStride[d];
        a.values[c] = convert(data + i * t.size, t);
        for (std::size_t d = 0; d < dims && ++index[d] == h.shape[d]; ++d) index[d] = 0;
    }
    return a;
}

std::string encodeNpy(const NpyArray& array) {
    std::string shape = "(";
    for (std::size_t i = 0; i < array.shape.size(); ++i)
        shape += (i ? ", " : "") + std::to_string(array.shape[i]);
    shape += array.shape.size() == 1 ? ",)" : ")";  // Python's one-element tuple
    const bool fortran = array.fortranOrder && array.shape.size() >= 2;
    std::string dict = std::string("{'descr': '<f4', 'fortran_order': ") + (fortran ? "True" : "False") +
                       ", 'shape': " + shape + ", }";
    // numpy pads the header with spaces so that the data starts 64-byte aligned.
    const std::size_t total = 10 + dict.size() + 1;
    dict.append((64 - total % 64) % 64, ' ');
    dict += '\n';
    std::string out = "\x93NUMPY";
    out += char(1);
    out += char(0);
    out += char(dict.size() & 0xff);
    out += char(dict.size() >> 8);
    out += dict;
    const std::size_t at = out.size();
    out.resize(at + array.values.size() * 4);
    // Fortran order (first index fastest) when asked, so readers of both layouts can be tested.
    const std::size_t dims = array.shape.size();
    std::vector<std::size_t> index(dims, 0), cStride(dims, 1);
    for (std::size_t d = dims; d > 1; --d) cStride[d - 2] = cStride[d - 1] * array.shape[d - 1];
    for (std::size_t i = 0; i < array.values.size(); ++i) {
        std::size_t from = i;
        if (fortran) {
            from = 0;
            for (std::size_t d = 0; d < dims; ++d) from += index[d] * cStride[d];
            for (std::size_t d = 0; d < dims && ++index[d] == array.shape[d]; ++d) index[d] = 0;
        }
        std::uint32_t v = std::bit_cast<std::uint32_t>(array.values[from]);
        for (int b = 0; b < 4; ++b) out[at + i * 4 + b] = char((v >> (8 * b)) & 0xff);
    }
    return out;
}

}  // namespace darkroom
