#pragma once
// Decoding VTK XML DataArrays (ascii, inline base64 "binary", appended raw or
// base64; zlib-compressed or not; UInt32/UInt64 headers; either byte order).
// Shared by the .vtp/.vtu mesh reader and the .vti image reader.
#include <darkroom/data/formats/binary_values.h>
#include <darkroom/data/formats/xml_document.h>
#include <darkroom/export.h>

#include <string>
#include <vector>

namespace darkroom::mesh {

// How a file's binary data is encoded, from its <VTKFile> and <AppendedData>.
struct VtkXmlEncoding {
    std::string path;  // names the file in messages
    bool bigEndian = false;
    ValueType headerType = ValueType::UInt32;
    bool compressed = false;
    const VtkXmlDocument* doc = nullptr;
    bool appendedBase64 = false;
};

struct VtkArray {
    std::string name;
    int components = 1;
    std::vector<double> values;  // tuples * components, as stored
};

// Reads byte_order, header_type, compressor and the AppendedData encoding;
// throws darkroom::Error("path:line: ...") for unsupported values.
DARKROOM_API VtkXmlEncoding vtkXmlEncoding(const VtkXmlDocument& doc, const std::string& path);

// Decodes one <DataArray>; throws darkroom::Error naming path:line and the array.
// Binary data whose declared (uncompressed) size exceeds maxTuples x
// NumberOfComponents values, or limit(Limit::DecodedBytes), is refused before
// anything is inflated or allocated; kAnyTuples when the caller cannot know.
constexpr std::size_t kAnyTuples = std::size_t(-1);
DARKROOM_API VtkArray readVtkDataArray(const XmlElement& e, const VtkXmlEncoding& encoding, std::size_t maxTuples = kAnyTuples);

// A non-negative integer attribute (0 when absent); throws naming path:line.
DARKROOM_API std::size_t vtkCountAttribute(const XmlElement& e, const std::string& path, const char* key);

}  // namespace darkroom::mesh
