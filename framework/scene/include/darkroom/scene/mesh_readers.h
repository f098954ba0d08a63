#pragma once
// Mesh file readers for capture scenes. Each returns the file's geometry as
// SceneObjects ready for a capture backend: a file may hold a surface part
// (polygons, fan-triangulated, and triangle strips), a lines part (polylines
// split into segments) and a vertices part (points drawn as spheres), named
// "<name>/surface", "<name>/lines", "<name>/points" when there are several, or
// just "<name>" (the file's stem by default). Vertex radii are 0; the scene file sets them.
//
// Data arrays become ScalarFields: point data per vertex, cell data per cell
// with SceneObject::primitiveCell mapping triangles/segments back to their cell.
// A multi-component array `v` becomes `v` (the magnitude) and `v_0`, `v_1`, ...
// Every problem throws darkroom::Error naming the file and the line (text) or
// element (binary) and what was expected. See docs/scene-format.md.
#include <darkroom/export.h>
#include <darkroom/scene.h>

#include <cstddef>
#include <string>
#include <vector>

namespace darkroom {

// Dispatches on the extension: .ply, .obj, .off, .stl, .vtk, .vtp, .vtu, .pvtp, .pvtu (case-insensitive).
// `warnings`, when given, receives notes about skipped content (e.g. 3D cells).
DARKROOM_API std::vector<SceneObject> readMesh(const std::string& path,
                                               std::vector<std::string>* warnings = nullptr);

DARKROOM_API std::vector<SceneObject> readPly(const std::string& path);

// How readPly reads a binary PLY of triangles. The defaults are readMesh's;
// tests and benchmarks compare the two ways, which give the same objects.
struct PlyReadOptions {
    // true: straight into the surface's arrays, a window of the file at a
    // time, decoded in parallel; false: the general reader (serial, the whole
    // file in memory, then an intermediate mesh), as for every other PLY.
    bool direct = true;
    std::size_t windowBytes = std::size_t(32) << 20;
};
DARKROOM_API std::vector<SceneObject> readPly(const std::string& path, const PlyReadOptions& options);
DARKROOM_API std::vector<SceneObject> readObj(const std::string& path);
// ASCII OFF and its COFF, NOFF, CNOFF, STOFF variants (binary OFF is refused).
DARKROOM_API std::vector<SceneObject> readOff(const std::string& path);
// ASCII and binary STL, told apart by the file's size; identical positions
// become one vertex (numbered in first use).
DARKROOM_API std::vector<SceneObject> readStl(const std::string& path);
DARKROOM_API std::vector<SceneObject> readVtkLegacy(const std::string& path);
// How readVtkLegacy reads a BINARY POLYDATA of triangles (float or double
// points, 1-component point SCALARS at most), as PlyReadOptions for PLY:
// directly by default, or with the general reader; both give the same objects.
struct VtkLegacyReadOptions {
    bool direct = true;
    std::size_t windowBytes = std::size_t(32) << 20;
};
DARKROOM_API std::vector<SceneObject> readVtkLegacy(const std::string& path, const VtkLegacyReadOptions& options);
DARKROOM_API std::vector<SceneObject> readVtkXml(const std::string& path,
                                                 std::vector<std::string>* warnings = nullptr);
// A parallel VTK XML file (.pvtp, or .pvtu of 2D cells): every piece it names,
// read with readVtkXml, each part appended to the part of the same
// representation in piece order (so primitive ids run piece after piece).
// See scene_partition.h for reading only some pieces on each of several processes.
DARKROOM_API std::vector<SceneObject> readParallelVtk(const std::string& path,
                                                      std::vector<std::string>* warnings = nullptr);

}  // namespace darkroom
