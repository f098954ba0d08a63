#include <darkroom/error.h>
#include <darkroom/scene/mesh_readers.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace darkroom {

std::vector<SceneObject> readMesh(const std::string& path, std::vector<std::string>* warnings) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".ply") return readPly(path);
    if (ext == ".obj") return readObj(path);
    if (ext == ".off") return readOff(path);
    if (ext == ".stl") return readStl(path);
    if (ext == ".vtk") return readVtkLegacy(path);
    if (ext == ".vtp" || ext == ".vtu") return readVtkXml(path, warnings);
    if (ext == ".pvtp" || ext == ".pvtu") return readParallelVtk(path, warnings);
    throw Error(path + ": unknown mesh format '" + ext + "' (expected .ply, .obj, .off, .stl, .vtk, .vtp, .vtu, .pvtp or .pvtu)");
}

}  // namespace darkroom
