#pragma once
// The capture scene file (YAML): objects (from mesh files or generators, each
// drawn as surface, lines or points, with the scalar fields to keep), cameras
// (a phi/theta grid or an explicit list) and the channels to store.
// Format and conventions: docs/scene-format.md.
#include <darkroom/camera.h>
#include <darkroom/capture_backend.h>
#include <darkroom/export.h>
#include <darkroom/scene.h>

#include <cstdint>
#include <map>
#include <optional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace darkroom {

// One camera of the sampling grid with the database parameters it stands for
// (e.g. {{"phi", 30}, {"theta", 45}}), in column order.
struct CameraSample {
    std::vector<std::pair<std::string, double>> parameters;
    Camera camera;
};

// How the normal channels (N.x, N.y, N.z) are made (`channels: normals`,
// `featureAngle`; docs/scene-format.md, "Normals").
struct NormalsOptions {
    // Smooth: surfaces carry vertex normals (vertex_normals.h) that the
    // capture interpolates across each triangle: isosurfaces the field's
    // gradient, meshes whose file has normals those, other meshes the
    // angle-weighted average of their triangles', split at edges sharper
    // than featureAngle. Geometric: each triangle's own normal (facets).
    // Tubes and spheres have their exact normals either way.
    enum class Style : std::uint8_t { Smooth, Geometric };
    Style style = Style::Smooth;
    double featureAngle = 30;  // degrees
};

// What a caller asks of loading beyond what the file says.
struct SceneLoadOptions {
    // Prepare the normal channels even if the file's channels leave them
    // off (the Capture node's `normals` input), in the file's style.
    bool normals = false;
    // One step of a time series (time_series.h): per object (its index in
    // the scene file's `objects`), the file it draws instead of its `file:`
    // (a glob, .pvd or database, which alone cannot be loaded).
    std::map<std::size_t, std::string> stepFiles;
    // Frame the cameras (and size default radii) on these bounds rather than
    // the scene's own: the union of a series' steps, so cameras stay put.
    std::optional<Bounds> framing;
};

struct SceneDescription {
    std::string path;  // the scene file
    std::shared_ptr<Scene> scene;
    std::vector<CameraSample> cameras;
    CaptureRequest request;
    NormalsOptions normals;  // how request.normals are made
    std::string backend = "embree";
    // Objects marked `store: pointList`: not ray traced; `darkroom capture`
    // writes each as a CSV point list beside every entry (column FILE_<name>)
    // for the Spheres node to draw post hoc. Each vertex is a sphere.
    std::vector<SceneObject> pointLists;
    std::vector<std::string> warnings;  // e.g. cells a reader skipped
    // The mesh and volume files the objects were read from, each once, in
    // the order first read (`darkroom capture --resume` compares them).
    std::vector<std::string> inputFiles;
};

// Parses the scene file and loads every object it names. Throws darkroom::Error
// naming file:line:column (YAML problems) or the mesh file (reader problems).
DARKROOM_API SceneDescription loadSceneFile(const std::string& path, const SceneLoadOptions& options = {});
DARKROOM_API SceneDescription parseSceneFile(const std::string& yamlText, const std::string& sourceName,
                                             const std::string& baseDir, const SceneLoadOptions& options = {});

// The Cinema/ParaView orbit: the camera sits at `distance` from `target` in
// direction cos(theta)(cos(phi) F + sin(phi) R) + sin(theta) U, where U is the
// unit `up`, F the reference front (X x U, i.e. +Z for up +Y, -Y for up +Z) and
// R = U x F (+X for up +Y); phi = azimuth about U, theta = elevation, degrees.
// The camera looks at the target; its up is the elevation-rotated U, so the
// poles (theta = +-90) are well defined. Resolution and projection are copied
// from `prototype`.
DARKROOM_API Camera orbitCamera(const Camera& prototype, const Vec3& target, double distance, double phiDegrees,
                                double thetaDegrees, const Vec3& up);

// Grid angles for a count: phi -180 + 360 i / n (i < n); theta 0 for one
// sample, else -90 + 180 i / (n - 1) (both poles included).
DARKROOM_API std::vector<double> phiAngles(int count);
DARKROOM_API std::vector<double> thetaAngles(int count);

// Distance at which a sphere of `radius` just fills the prototype's view
// (perspective: tangent to the narrower field of view; orthographic: 2 radius).
DARKROOM_API double fittingDistance(const Camera& prototype, double radius);

}  // namespace darkroom
