// Decoding of VTK XML DataArrays, shared by the mesh reader (.vtp, .vtu) and
// the image reader (.vti, framework/data/src/formats/vti_reader.cpp).
#include <darkroom/data/formats/vtk_data_array.h>

#include <darkroom/data/formats/base64.h>
#include <darkroom/data/formats/number_text.h>
#include <darkroom/data/formats/text_cursor.h>

#include <darkroom/error.h>
#include <darkroom/limits.h>

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <limits>

namespace darkroom::mesh {

namespace {

// Sequential access to the bytes behind one binary DataArray.
class ByteSource {
public:
    virtual ~ByteSource() = default;
    virtual bool read(std::size_t n, std::string& out, std::string& error) = 0;
};

class RawSource : public ByteSource {
public:
    explicit RawSource(std::string_view bytes) : bytes_(bytes) {}
    bool read(std::size_t n, std::string& out, std::string& error) override {
        if (bytes_.size() - pos_ < n) {
            error = "appended data ends early (truncated): " + std::to_string(n) + " more bytes expected";
            return false;
        }
        out.append(bytes_.substr(pos_, n));
        pos_ += n;
        return true;
    }

private:
    std::string_view bytes_;
    std::size_t pos_ = 0;
};

class Base64Source : public ByteSource {
public:
    explicit Base64Source(std::string_view text) : stream_(text) {}
    bool read(std::size_t n, std::string& out, std::string& error) override { return stream_.read(n, out, error); }

private:
    Base64Stream stream_;
};

std::size_t headerWord(const VtkXmlEncoding& f_, ByteSource& src, const std::string& where) {
    std::string b, err;
    if (!src.read(sizeOf(f_.headerType), b, err)) throw Error(where + err);
    const double v = loadValue(f_.headerType, b.data(), f_.bigEndian);
    // Read through a double: a UInt64 word near 2^64 (or a negative signed
    // one) would not convert to size_t (undefined behaviour, found by the vti
    // fuzz harness). No real block is anywhere near 2^62 bytes.
    if (!(v >= 0.0) || v >= 4.611686018427387904e18)
        throw InputError(where + "a block header declares " + numberText(v) + " bytes; expected a byte count");
    return std::size_t(v);
}

// What a block may declare: the bytes its array needs, and the decoded-bytes limit.
struct BlockLimit {
    std::uint64_t maxBytes;    // tuples x components x type size; UINT64_MAX when unknown
    std::size_t valueSize;     // bytes of one stored value (decoded to an 8-byte double)
};

void checkDeclared(std::uint64_t bytes, const BlockLimit& lim, const std::string& where, const char* what) {
    if (bytes > lim.maxBytes)
        throw InputError(where + what + " declares " + std::to_string(bytes) + " bytes but the array needs at most " +
                         std::to_string(lim.maxBytes));
    // Decoded twice over: the raw bytes, then one double per value.
    const std::uint64_t values = bytes / lim.valueSize;
    checkBytes(Limit::DecodedBytes, std::max<std::uint64_t>(bytes, values * sizeof(double)),
               where.substr(0, where.size() - 2), std::string(what) + " decoded");
}

// The bytes of one binary block: header + data, or header + zlib blocks.
// Every declared size is checked before anything is inflated or allocated.
std::string block(const VtkXmlEncoding& f_, ByteSource& src, const std::string& where, const BlockLimit& lim) {
    std::string out, err;
    if (!f_.compressed) {
        const std::size_t n = headerWord(f_, src, where);
        checkDeclared(n, lim, where, "binary data");
        if (!src.read(n, out, err)) throw Error(where + err);
        return out;
    }
    const std::size_t nb = headerWord(f_, src, where), bs = headerWord(f_, src, where), last = headerWord(f_, src, where);
    if (nb > (1u << 24)) throw InputError(where + "implausible zlib block count " + std::to_string(nb));
    // Uncompressed total: nb - 1 full blocks and the last (bs when `last` is 0).
    std::uint64_t total = 0;
    if (nb > 0) {
        const std::uint64_t lastSize = last != 0 ? last : bs;
        if (bs != 0 && std::uint64_t(nb - 1) > (std::numeric_limits<std::uint64_t>::max() - lastSize) / bs)
            throw InputError(where + "zlib header declares an impossible uncompressed size");
        total = std::uint64_t(nb - 1) * bs + lastSize;
    }
    checkDeclared(total, lim, where, "zlib data");
    std::vector<std::size_t> sizes(nb);
    for (auto& s : sizes) s = headerWord(f_, src, where);
    out.reserve(std::size_t(total));
    for (std::size_t i = 0; i < nb; ++i) {
        const std::size_t raw = (i + 1 == nb && last != 0) ? last : bs;
        // Deflate expands at most ~1032:1; anything more is a corrupt header.
        if (raw / 1032 > sizes[i] + 1) throw Error(where + "zlib block " + std::to_string(i) + " claims an impossible size");
        std::string comp;
        if (!src.read(sizes[i], comp, err)) throw Error(where + err);
        const std::size_t at = out.size();
        out.resize(at + raw);
        uLongf len = uLongf(raw);
        const int rc = uncompress(reinterpret_cast<Bytef*>(out.data() + at), &len,
                                  reinterpret_cast<const Bytef*>(comp.data()), uLong(comp.size()));
        if (rc != Z_OK || len != raw)
            throw Error(where + "zlib block " + std::to_string(i) + " is corrupt (" +
                        (rc == Z_OK ? "wrong size" : std::string(zError(rc))) + ")");
    }
    return out;
}

}  // namespace

VtkArray readVtkDataArray(const XmlElement& e, const VtkXmlEncoding& f_, std::size_t maxTuples) {
    VtkArray a;
    a.name = e.attributeOr("Name", "");
    const std::string where = f_.path + ":" + std::to_string(e.line) + ": DataArray '" + a.name + "': ";
    const std::string typeName = e.attributeOr("type", "");
    const auto type = vtkXmlType(typeName);
    if (!type) throw Error(where + "unsupported type '" + typeName + "' (expected Float32, Float64, Int8..Int64 or UInt8..UInt64)");
    a.components = e.attribute("NumberOfComponents") ? int(vtkCountAttribute(e, f_.path, "NumberOfComponents")) : 1;
    if (a.components < 1) throw Error(where + "NumberOfComponents must be at least 1");
    const std::string format = e.attributeOr("format", "ascii");
    BlockLimit lim{std::numeric_limits<std::uint64_t>::max(), sizeOf(*type)};
    if (maxTuples != kAnyTuples) {
        // tuples x components x type size, saturating.
        const std::uint64_t perTuple = std::uint64_t(a.components) * sizeOf(*type);
        if (maxTuples <= std::numeric_limits<std::uint64_t>::max() / perTuple) lim.maxBytes = maxTuples * perTuple;
    }
    if (format == "ascii") {
        const std::string_view text = e.text;
        std::size_t i = 0;
        while (i < text.size()) {
            while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
            const std::size_t b = i;
            while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
            if (i == b) break;
            double v = 0;
            if (!parseDouble(text.substr(b, i - b), v))
                throw Error(where + "expected a number, got '" + std::string(text.substr(b, std::min<std::size_t>(i - b, 40))) + "'");
            a.values.push_back(v);
        }
        return a;
    }
    std::string bytes;
    if (format == "binary") {
        Base64Source src(e.text);
        bytes = block(f_, src, where, lim);
    } else if (format == "appended") {
        if (!f_.doc->appendedElement) throw Error(where + "format is appended but the file has no <AppendedData>");
        const std::size_t offset = vtkCountAttribute(e, f_.path, "offset");
        if (offset > f_.doc->appended.size()) throw Error(where + "offset " + std::to_string(offset) + " lies beyond the appended data");
        const std::string_view rest = f_.doc->appended.substr(offset);
        if (f_.appendedBase64) {
            Base64Source src(rest);
            bytes = block(f_, src, where, lim);
        } else {
            RawSource src(rest);
            bytes = block(f_, src, where, lim);
        }
    } else {
        throw Error(where + "unknown format '" + format + "' (expected ascii, binary or appended)");
    }
    const std::size_t sz = sizeOf(*type);
    if (bytes.size() % sz != 0) throw Error(where + "byte count " + std::to_string(bytes.size()) + " is not a multiple of " + typeName);
    a.values.resize(bytes.size() / sz);
    for (std::size_t i = 0; i < a.values.size(); ++i) a.values[i] = loadValue(*type, bytes.data() + i * sz, f_.bigEndian);
    return a;
}

std::size_t vtkCountAttribute(const XmlElement& e, const std::string& path, const char* key) {
    const std::string* v = e.attribute(key);
    long long n = 0;
    if (!v) return 0;
    if (!parseInteger(*v, n) || n < 0)
        throw Error(path + ":" + std::to_string(e.line) + ": " + key + " must be a non-negative integer, got '" + *v + "'");
    return std::size_t(n);
}

VtkXmlEncoding vtkXmlEncoding(const VtkXmlDocument& doc, const std::string& path) {
    VtkXmlEncoding f;
    f.path = path;
    f.doc = &doc;
    const XmlElement& root = *doc.root;
    const auto fail = [&](const XmlElement& e, const std::string& what) {
        throw Error(path + ":" + std::to_string(e.line) + ": " + what);
    };
    const std::string order = root.attributeOr("byte_order", "LittleEndian");
    if (order != "LittleEndian" && order != "BigEndian") fail(root, "byte_order must be LittleEndian or BigEndian");
    f.bigEndian = order == "BigEndian";
    const std::string ht = root.attributeOr("header_type", "UInt32");
    if (ht == "UInt64") f.headerType = ValueType::UInt64;
    else if (ht != "UInt32") fail(root, "header_type must be UInt32 or UInt64, got '" + ht + "'");
    if (const std::string* c = root.attribute("compressor")) {
        if (*c != "vtkZLibDataCompressor")
            fail(root, "unsupported compressor '" + *c + "' (only vtkZLibDataCompressor is read)");
        f.compressed = true;
    }
    if (doc.appendedElement) {
        const std::string enc = doc.appendedElement->attributeOr("encoding", "raw");
        if (enc != "raw" && enc != "base64") fail(*doc.appendedElement, "AppendedData encoding must be raw or base64");
        f.appendedBase64 = enc == "base64";
    }
    return f;
}

}  // namespace darkroom::mesh
