// Parallel VTK XML files: the list of pieces, whole or in part, with the
// parts agreed between processes.
#include "parallel_vtk.h"

#include <darkroom/data/formats/text_cursor.h>
#include <darkroom/data/formats/xml_document.h>
#include "agreement.h"
#include "split_objects.h"

#include <darkroom/error.h>
#include <darkroom/scene/mesh_readers.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>

namespace darkroom::partition {

namespace fs = std::filesystem;

namespace {

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

std::string fieldList(const SceneObject& o) {
    std::string s;
    for (const auto& f : o.fields)
        s += (s.empty() ? "" : ", ") + f.name + (f.association == ScalarField::Association::Cell ? " (cell)" : "");
    return s.empty() ? "none" : s;
}

}  // namespace

bool isParallelVtk(const std::string& path) {
    const std::string ext = lowerExtension(path);
    return ext == ".pvtp" || ext == ".pvtu";
}

std::vector<std::string> parallelVtkPieces(const std::string& path) {
    const std::string data = mesh::readWholeFile(path, "mesh");
    const mesh::VtkXmlDocument doc = mesh::parseVtkXml(data, path);
    const mesh::XmlElement& root = *doc.root;
    auto fail = [&](const mesh::XmlElement& e, const std::string& what) -> void {
        throw Error(path + ":" + std::to_string(e.line) + ": " + what);
    };
    if (root.name != "VTKFile") fail(root, "expected <VTKFile> as the root element, got <" + root.name + ">");
    const std::string type = root.attributeOr("type", "");
    const std::string expected = lowerExtension(path) == ".pvtp" ? "PPolyData" : "PUnstructuredGrid";
    if (type != expected)
        fail(root, "a " + lowerExtension(path) + " file holds VTKFile type=\"" + expected + "\", got \"" + type + "\"");
    const mesh::XmlElement* dataset = root.child(type);
    if (!dataset) fail(root, "missing <" + type + "> element");
    const std::string ghosts = dataset->attributeOr("GhostLevel", "0");
    if (ghosts != "0")
        fail(*dataset, "GhostLevel=\"" + ghosts + "\": pieces with ghost cells would draw those cells twice; "
                       "write the pieces without ghost levels");
    std::vector<std::string> pieces;
    for (const auto& c : dataset->children) {
        if (c->name != "Piece") continue;
        const std::string* source = c->attribute("Source");
        if (!source || source->empty()) fail(*c, "<Piece> without a Source file");
        fs::path p(*source);
        if (p.is_relative()) p = fs::path(path).parent_path() / p;
        pieces.push_back(p.lexically_normal().string());
    }
    if (pieces.empty()) fail(*dataset, "no <Piece Source=\"...\"> element: the file names no pieces");
    return pieces;
}

void appendPart(SceneObject& into, const SceneObject& piece, const std::string& source) {
    if (into.representation != piece.representation)
        throw Error(source + ": cannot append a " + std::string(toString(piece.representation)) + " part to a " +
                    toString(into.representation) + " part");
    bool sameFields = into.fields.size() == piece.fields.size();
    for (std::size_t i = 0; sameFields && i < into.fields.size(); ++i)
        sameFields = into.fields[i].name == piece.fields[i].name &&
                     into.fields[i].association == piece.fields[i].association;
    if (!sameFields)
        throw Error(source + ": this piece's " + toString(piece.representation) + " part carries the fields " +
                    fieldList(piece) + " but the pieces before it carry " + fieldList(into) +
                    "; the pieces of one parallel file must carry the same arrays");
    const std::size_t vertexBase = into.vertexCount(), primitiveBase = into.primitiveCount();
    const std::size_t cellBase = cellCountOf(into);
    if (!into.primitiveCell.empty() || !piece.primitiveCell.empty()) {
        // A cell map is needed once either side is not the identity.
        if (into.primitiveCell.empty())
            for (std::size_t i = 0; i < primitiveBase; ++i) into.primitiveCell.push_back(std::uint32_t(i));
        const std::size_t n = piece.primitiveCount();
        for (std::size_t i = 0; i < n; ++i)
            into.primitiveCell.push_back(
                std::uint32_t(cellBase + (piece.primitiveCell.empty() ? i : piece.primitiveCell[i])));
    }
    into.vertices.insert(into.vertices.end(), piece.vertices.begin(), piece.vertices.end());
    for (auto i : piece.indices) into.indices.push_back(std::uint32_t(i + vertexBase));
    const std::size_t pieceCells = cellCountOf(piece);
    for (std::size_t f = 0; f < into.fields.size(); ++f) {
        auto& values = into.fields[f].values;
        if (into.fields[f].association == ScalarField::Association::Cell) values.resize(cellBase, kNaNFloat);
        values.insert(values.end(), piece.fields[f].values.begin(), piece.fields[f].values.end());
        if (into.fields[f].association == ScalarField::Association::Cell) values.resize(cellBase + pieceCells, kNaNFloat);
    }
}

std::vector<SceneObject> readParallelVtkPieces(const std::string& path, ProcessGroup* group,
                                               std::vector<std::string>* warnings) {
    const std::string stem = fs::path(path).stem().string();
    // What this process read, by representation; errors are carried to the
    // agreement so that every process fails together.
    std::map<Representation, SceneObject> parts;
    std::string error;
    try {
        const std::vector<std::string> pieces = parallelVtkPieces(path);
        const auto [first, last] = group ? blockOf(pieces.size(), group->rank(), group->size())
                                         : std::pair<std::size_t, std::size_t>{0, pieces.size()};
        for (std::size_t p = first; p < last; ++p) {
            for (SceneObject& part : readVtkXml(pieces[p], warnings)) {
                auto it = parts.find(part.representation);
                if (it == parts.end()) parts.emplace(part.representation, std::move(part));
                else appendPart(it->second, part, pieces[p]);
            }
        }
    } catch (const Error& e) {
        error = e.what();
    }
    std::vector<SceneObject> local;
    for (auto& [rep, part] : parts) local.push_back(std::move(part));
    std::vector<SceneObject> agreed = agreeParts(std::move(local), group, error, path);
    for (auto& part : agreed)
        part.name = agreed.size() == 1 ? stem : stem + "/" + toString(part.representation);
    return agreed;
}

}  // namespace darkroom::partition

namespace darkroom {

std::vector<SceneObject> readParallelVtk(const std::string& path, std::vector<std::string>* warnings) {
    return partition::readParallelVtkPieces(path, nullptr, warnings);
}

}  // namespace darkroom
