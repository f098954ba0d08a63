#pragma once
// A PLY file's header: its format and its elements with their properties,
// read once and shared by the general reader (ply_reader.cpp) and the direct
// reader of binary triangle meshes (ply_triangles.h).
#include <darkroom/data/formats/binary_values.h>
#include <darkroom/data/formats/text_cursor.h>

#include <cstddef>
#include <string>
#include <vector>

namespace darkroom::ply {

using mesh::ValueType;

struct Property {
    std::string name;
    bool isList = false;
    ValueType countType = ValueType::UInt8;
    ValueType type = ValueType::Float32;
};

struct Element {
    std::string name;
    std::size_t count = 0;
    std::vector<Property> properties;
    int line = 0;  // of its 'element' line, for messages

    // Bytes of one binary instance; 0 when it holds a list (its size varies).
    std::size_t fixedSize() const;
};

struct Header {
    bool ascii = false, bigEndian = false;
    std::vector<Element> elements;
};

// Reads the header from `cur` (at the start of the file) and leaves `cur` at
// the first byte of the body. Throws InputError naming `path` and the line.
Header readHeader(const std::string& path, mesh::TextCursor& cur);

// Checked once the header is read, before anything is allocated: the
// vertices have x, y and z, and every count fits in the `bytesLeft` bytes of
// the body.
void checkElements(const std::string& path, const Header& header, std::size_t bytesLeft);

// Refuses an element whose count the `bytesLeft` bytes cannot hold.
void checkCount(const std::string& path, const Header& header, const Element& e, std::size_t bytesLeft);

}  // namespace darkroom::ply
