// The capture scene file: YAML in, SceneDescription out. Every problem is a
// darkroom::InputError at "scene.yaml:line:column" (1-based); reader and
// generator errors are prefixed with the object that asked for them.
#include "generator_seam.h"
#include "normals/scene_normals.h"
#include "object_style.h"
#include "partition/agreement.h"
#include "partition/parallel_vtk.h"
#include "partition/split_objects.h"
#include <darkroom/data/formats/text_cursor.h>
#include <darkroom/core/yaml_guard.h>

#include <darkroom/error.h>
#include <darkroom/input_file.h>
#include <darkroom/strings.h>
#include <darkroom/scene/camera_bounds.h>
#include <darkroom/scene/generators.h>
#include <darkroom/scene/mesh_readers.h>
#include <darkroom/scene/scene_file.h>
#include <darkroom/scene/scene_partition.h>
#include <darkroom/scene/time_series.h>
#include <darkroom/scene/volume.h>

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>

namespace darkroom::scene_detail {
GeneratorParameterFilter generatorParameterFilter = nullptr;
}  // namespace darkroom::scene_detail

namespace darkroom {
namespace {

class Parser {
public:
    // With a group, the scene is loaded over several processes
    // (scene_partition.h): parallel files are read piece-wise and the bounds
    // that cameras and default radii depend on are agreed.
    Parser(std::string source, std::string baseDir, ProcessGroup* group = nullptr, SceneLoadOptions options = {})
        : source_(std::move(source)), baseDir_(std::move(baseDir)), group_(group), options_(options) {}

    // Per object of the parsed scene: whether it holds only this process's
    // pieces (a parallel file read over a group) rather than the whole object.
    const std::vector<bool>& pieceWise() const { return pieceWise_; }

    SceneDescription parse(const YAML::Node& root) {
        SceneDescription d;
        d.path = source_;
        d.scene = std::make_shared<Scene>();
        if (!root.IsMap()) fail(root, "expected a map with 'objects', 'cameras' and 'channels'");
        checkKeys(root, {"version", "objects", "cameras", "channels", "backend", "series"}, "the scene file");
        seriesKey(root["series"]);
        if (root["version"] && number(root["version"], "version") != 1.0) fail(root["version"], "unsupported version, expected 1");
        const YAML::Node objects = root["objects"];
        if (!objects) fail(root, "missing 'objects' (a list of objects to draw)");
        if (!objects.IsSequence() || objects.size() == 0) fail(objects, "'objects' must be a non-empty list");
        // Known before the objects load: isosurfaces then keep their gradient.
        const bool normalsOn = normalsChannel(root["channels"], d.normals);
        vertexNormals_ = (normalsOn || options_.normals) && d.normals.style == NormalsOptions::Style::Smooth;
        for (std::size_t i = 0; i < objects.size(); ++i) {
            objectIndex_ = i;
            loadObject(objects[i], *d.scene, d.warnings, d.pointLists);
        }
        defaultRadii(*d.scene);
        defaultPointListRadii(*d.scene, d.pointLists);
        if (root["backend"]) d.backend = text(root["backend"], "backend");
        d.request = channels(root["channels"], *d.scene, normalsOn);
        if (vertexNormals_) scenefile::attachShadingNormals(*d.scene, shading_, d.normals.featureAngle);
        d.cameras = cameras(root["cameras"], *d.scene);
        for (const auto& c : d.cameras) checkRayOrigin(root["cameras"] ? root["cameras"] : root, c);
        d.inputFiles = inputFiles_;
        return d;
    }

private:
    std::string where(const YAML::Node& n) const {
        const YAML::Mark m = n.Mark();
        if (m.line < 0) return source_;
        return source_ + ":" + std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1);
    }
    [[noreturn]] void fail(const YAML::Node& n, const std::string& what) const {
        throw InputError(where(n) + ": " + what);
    }

    void checkKeys(const YAML::Node& map, std::initializer_list<const char*> allowed, const std::string& what) const {
        for (const auto& kv : map) {
            const std::string key = kv.first.Scalar();
            if (std::none_of(allowed.begin(), allowed.end(), [&](const char* a) { return key == a; })) {
                std::string list;
                for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
                const std::string near = nearestName(key, std::vector<std::string>(allowed.begin(), allowed.end()));
                fail(kv.first, "unknown key '" + key + "' in " + what +
                                   (near.empty() ? std::string() : "; did you mean '" + near + "'?") + " (expected " +
                                   list + ")");
            }
        }
    }

    // `series: {ranks: auto | steps | partition}`: how mpirun shares a time
    // series (time_series.h); checked here too, so a scene without a series
    // is told of a bad value as well.
    void seriesKey(const YAML::Node& n) const {
        if (!n) return;
        if (!n.IsMap()) fail(n, "'series' must be a map (ranks)");
        checkKeys(n, {"ranks"}, "series");
        if (const YAML::Node r = n["ranks"]) {
            const std::string v = text(r, "ranks");
            if (v != "auto" && v != "steps" && v != "partition")
                fail(r, "ranks must be auto, steps (each rank captures whole steps of a time series) or partition "
                        "(every rank holds a part of every step)");
        }
    }

    std::string text(const YAML::Node& n, const std::string& what) const {
        if (!n.IsScalar()) fail(n, what + " must be a single value");
        return n.Scalar();
    }
    double number(const YAML::Node& n, const std::string& what) const {
        double v = 0;
        if (!n.IsScalar() || !mesh::parseDouble(n.Scalar(), v) || !std::isfinite(v))
            fail(n, what + " must be a number" + (n.IsScalar() ? ", got '" + n.Scalar() + "'" : ""));
        return v;
    }
    int integer(const YAML::Node& n, const std::string& what, long long lo, long long hi) const {
        long long v = 0;
        if (!n.IsScalar() || !mesh::parseInteger(n.Scalar(), v) || v < lo || v > hi)
            fail(n, what + " must be an integer from " + std::to_string(lo) + " to " + std::to_string(hi) +
                        (n.IsScalar() ? ", got '" + n.Scalar() + "'" : ""));
        return int(v);
    }
    bool boolean(const YAML::Node& n, const std::string& what) const {
        const std::string s = n.IsScalar() ? n.Scalar() : std::string();
        if (s == "true" || s == "yes" || s == "on") return true;
        if (s == "false" || s == "no" || s == "off") return false;
        fail(n, what + " must be true or false");
    }
    Vec3 vec3(const YAML::Node& n, const std::string& what) const {
        if (!n.IsSequence() || n.size() != 3) fail(n, what + " must be a list of 3 numbers [x, y, z]");
        return {number(n[0], what), number(n[1], what), number(n[2], what)};
    }
    std::vector<std::string> names(const YAML::Node& n, const std::string& what) const {
        if (!n.IsSequence()) fail(n, what + " must be a list of names");
        std::vector<std::string> out;
        for (const auto& x : n) out.push_back(text(x, what));
        return out;
    }

    // The volume representation an object asks for (boundary, isosurface with
    // contourBy and isosurfaces, slice with planes), or nullopt for surface,
    // lines and points. Keys that belong to another representation are errors.
    std::optional<VolumeRepresentation> volumeRepresentation(const YAML::Node& o) const {
        const YAML::Node r = o["representation"];
        const std::string s = r ? text(r, "representation") : std::string();
        std::optional<VolumeRepresentation> v;
        if (s == "boundary" || s == "isosurface" || s == "slice") {
            v.emplace();
            v->kind = s == "boundary" ? VolumeRepresentation::Kind::Boundary
                      : s == "isosurface" ? VolumeRepresentation::Kind::Isosurface
                                          : VolumeRepresentation::Kind::Slice;
        }
        const bool iso = v && v->kind == VolumeRepresentation::Kind::Isosurface;
        const bool slice = v && v->kind == VolumeRepresentation::Kind::Slice;
        for (const char* key : {"contourBy", "isosurfaces"})
            if (o[key] && !iso) fail(o[key], std::string("'") + key + "' only applies to representation: isosurface");
        if (o["planes"] && !slice) fail(o["planes"], "'planes' only applies to representation: slice");
        if (iso) {
            if (!o["contourBy"]) fail(r, "representation isosurface needs 'contourBy' (the point field to contour)");
            if (!o["isosurfaces"]) fail(r, "representation isosurface needs 'isosurfaces' (a list of values)");
            v->contourBy = text(o["contourBy"], "contourBy");
            const YAML::Node values = o["isosurfaces"];
            if (values.IsScalar()) v->isovalues.push_back(number(values, "isosurfaces"));
            else if (values.IsSequence() && values.size() > 0)
                for (const auto& x : values) v->isovalues.push_back(number(x, "an isosurface value"));
            else fail(values, "'isosurfaces' must be a value or a non-empty list of values");
        }
        if (slice) {
            const YAML::Node planes = o["planes"];
            if (!planes) fail(r, "representation slice needs 'planes' (a list of {origin: [x, y, z], normal: [x, y, z]})");
            if (!planes.IsSequence() || planes.size() == 0)
                fail(planes, "'planes' must be a non-empty list of {origin: [x, y, z], normal: [x, y, z]}");
            for (const auto& pl : planes) {
                if (!pl.IsMap()) fail(pl, "each plane must be a map {origin: [x, y, z], normal: [x, y, z]}");
                checkKeys(pl, {"origin", "normal"}, "a slice plane");
                SlicePlane plane;
                if (pl["origin"]) plane.origin = vec3(pl["origin"], "origin");
                if (!pl["normal"]) fail(pl, "a slice plane needs a 'normal'");
                plane.normal = vec3(pl["normal"], "normal");
                if (!(length(plane.normal) > 0)) fail(pl["normal"], "a plane's normal must not be zero");
                v->planes.push_back(plane);
            }
        }
        return v;
    }

    // A volume file read once per scene, however many objects draw it.
    const VolumeMesh& volume(const std::string& path, std::vector<std::string>& warnings) const {
        auto& slot = volumes_[path];
        if (!slot) slot = std::make_shared<VolumeMesh>(readVolume(path, &warnings));
        return *slot;
    }

    std::vector<SceneObject> loadParts(const YAML::Node& o, const std::string& name, std::vector<std::string>& warnings,
                                       const std::optional<VolumeRepresentation>& volumeRep) const {
        const bool hasFile = bool(o["file"]), hasGenerator = bool(o["generator"]);
        if (hasFile == hasGenerator) fail(o, "object '" + name + "' needs exactly one of 'file' or 'generator'");
        if (o["parameters"] && !hasGenerator) fail(o["parameters"], "'parameters' only apply to a 'generator' object");
        if (volumeRep && hasGenerator)
            fail(o["representation"], "representation " + std::string(toString(volumeRep->kind)) +
                                          " needs a volume file (.vtu with 3D cells or .vti), not a generator");
        try {
            if (hasFile) {
                std::filesystem::path p = stepFile(o, name);
                if (p.is_relative()) p = std::filesystem::path(baseDir_) / p;
                const std::string path = p.lexically_normal().string();
                if (std::find(inputFiles_.begin(), inputFiles_.end(), path) == inputFiles_.end())
                    inputFiles_.push_back(path);
                // Volumes: the chosen representation, or their boundary as ParaView's Surface shows it.
                std::string ext = p.extension().string();
                for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
                if (volumeRep || ext == ".vti" || ext == ".vtu") {
                    if (volumeRep && ext != ".vti" && ext != ".vtu")
                        fail(o["representation"], "representation " + std::string(toString(volumeRep->kind)) +
                                                      " needs a volume file (.vtu with 3D cells or .vti)");
                    const VolumeMesh& vol = volume(path, warnings);
                    // A boundary of a file of surfaces is those surfaces (as ParaView's Extract Surface).
                    if (vol.volumeCellCount() > 0 || (volumeRep && volumeRep->kind == VolumeRepresentation::Kind::Boundary)) {
                        VolumeRepresentation r = volumeRep.value_or(VolumeRepresentation{});
                        r.gradientNormals = vertexNormals_;
                        return {volumeSurface(vol, r, name)};
                    }
                    if (volumeRep)
                        fail(o["representation"], "representation " + std::string(toString(volumeRep->kind)) +
                                                      " needs 3D cells, and '" + path + "' has none");
                }
                // A point list is not ray traced, so not shared out: every
                // process reads it whole and the lead writes it whole.
                if (group_ && !loadingPointList_ && partition::isParallelVtk(path)) {
                    loadedPieceWise_ = true;
                    return partition::readParallelVtkPieces(path, group_, &warnings);
                }
                return readMesh(path, &warnings);
            }
            std::map<std::string, std::string> params;
            if (const YAML::Node ps = o["parameters"]) {
                if (!ps.IsMap()) fail(ps, "'parameters' must be a map of name: value");
                for (const auto& kv : ps) {
                    std::string v;
                    if (kv.second.IsSequence())  // lists are passed on as "a,b,c"
                        for (const auto& x : kv.second) v += (v.empty() ? "" : ",") + text(x, "a parameter value");
                    else
                        v = text(kv.second, "parameter '" + kv.first.Scalar() + "'");
                    params[kv.first.Scalar()] = v;
                }
            }
            const std::string generator = text(o["generator"], "generator");
            if (scene_detail::generatorParameterFilter) scene_detail::generatorParameterFilter(generator, params);
            return generate(generator, params, GenerateOptions{vertexNormals_});
        } catch (const Error& e) {
            const YAML::Node at = hasFile ? o["file"] : o["generator"];
            const std::string msg = e.what();
            if (msg.rfind(source_ + ":", 0) == 0) throw;  // already located in this file
            fail(at, "object '" + name + "': " + msg);
        }
    }

    // The file an object draws: its `file:`, or this step's file of the
    // series it names (time_series.h), which only a series capture loads.
    std::string stepFile(const YAML::Node& o, const std::string& name) const {
        const std::string value = text(o["file"], "file");
        const bool series = isSeriesFile(value, baseDir_);
        if (o["time"] && !series)
            fail(o["time"], "'time' only applies to a time series (a glob pattern in 'file')");
        if (!series) return value;
        if (const auto f = options_.stepFiles.find(objectIndex_); f != options_.stepFiles.end()) return f->second;
        fail(o["file"], "object '" + name + "': '" + value + "' is a time series (a glob pattern, a .pvd or a " +
                            "Cinema database); `darkroom capture` captures it step by step, here one mesh file is " +
                            "expected");
    }

    void loadObject(const YAML::Node& o, Scene& scene, std::vector<std::string>& warnings,
                    std::vector<SceneObject>& pointLists) {
        if (!o.IsMap()) fail(o, "each object must be a map (with 'file' or 'generator')");
        checkKeys(o, {"name", "file", "generator", "parameters", "representation", "contourBy", "isosurfaces", "planes",
                      "radius", "fields", "translate", "scale", "store", "time"},
                  "an object");
        bool asPointList = false;
        if (const YAML::Node st = o["store"]) {
            const std::string s = text(st, "store");
            if (s == "pointList") asPointList = true;
            else if (s != "geometry") fail(st, "store must be geometry (ray traced, the default) or pointList (kept as "
                                               "a CSV point list beside each entry), got '" + s + "'");
        }
        std::string name;
        if (o["name"]) name = text(o["name"], "name");
        else if (o["file"]) name = std::filesystem::path(text(o["file"], "file")).stem().string();
        else if (o["generator"]) name = text(o["generator"], "generator");
        const std::optional<VolumeRepresentation> volumeRep = volumeRepresentation(o);
        loadedPieceWise_ = false;
        loadingPointList_ = asPointList;
        std::vector<SceneObject> parts = loadParts(o, name, warnings, volumeRep);
        loadingPointList_ = false;
        // Held aside until every object is loaded (scene_normals.h).
        std::vector<VertexNormals> shading(parts.size());
        if (vertexNormals_ && !asPointList)
            for (std::size_t i = 0; i < parts.size(); ++i) shading[i] = scenefile::takeShadingNormals(parts[i]);

        Vec3 scale{1, 1, 1}, translate{0, 0, 0};
        if (const YAML::Node s = o["scale"]) {
            if (s.IsSequence()) scale = vec3(s, "scale");
            else scale = Vec3{1, 1, 1} * number(s, "scale");
        }
        if (o["translate"]) translate = vec3(o["translate"], "translate");

        std::optional<Representation> rep;
        if (const YAML::Node r = o["representation"]; r && !volumeRep) {
            const std::string s = text(r, "representation");
            if (s == "surface") rep = Representation::Surface;
            else if (s == "lines") rep = Representation::Lines;
            else if (s == "points") rep = Representation::Points;
            else fail(r, "representation must be surface, lines or points (volumes: boundary, isosurface or slice), got '" + s + "'");
        }
        std::optional<float> radius;
        if (const YAML::Node r = o["radius"]) {
            const double v = number(r, "radius");
            if (!(v > 0)) fail(r, "radius must be positive (world units)");
            radius = float(v);
        }
        if (const YAML::Node f = o["fields"]) {
            const std::vector<std::string> wanted = names(f, "fields");
            std::vector<std::string> available;
            for (const auto& p : parts)
                for (const auto& fl : p.fields)
                    if (std::find(available.begin(), available.end(), fl.name) == available.end()) available.push_back(fl.name);
            for (std::size_t i = 0; i < wanted.size(); ++i) {
                if (std::find(available.begin(), available.end(), wanted[i]) != available.end()) continue;
                std::string list;
                for (const auto& a : available) list += (list.empty() ? "" : ", ") + a;
                fail(f[i], "object '" + name + "' has no field '" + wanted[i] + "' (" +
                               (available.empty() ? std::string("it has no fields") : "available: " + list) + ")");
            }
            for (auto& p : parts) scenefile::keepFields(p, wanted);
        }
        for (std::size_t i = 0; i < parts.size(); ++i) {
            SceneObject& p = parts[i];
            if (parts.size() > 1 && o["name"]) p.name = name + p.name.substr(p.name.rfind('/'));
            else if (o["name"]) p.name = name;
            scenefile::transform(p, scale, translate);
            scaleVertexNormals(shading[i], scale);
            if (rep) p = scenefile::restyle(std::move(p), *rep);
            if (p.representation != Representation::Surface) VertexNormals().swap(shading[i]);
            // A surface's vertices become spheres; lines stay lines (their
            // list joins each polyline's points, for PointListAO).
            if (asPointList && p.representation == Representation::Surface)
                p = scenefile::restyle(std::move(p), Representation::Points);
            if (radius) scenefile::setRadius(p, *radius);
            if (asPointList) {
                for (const auto& other : pointLists)
                    if (other.name == p.name)
                        fail(o, "two point lists are named '" + p.name + "'; give one a 'name'");
                pointLists.push_back(std::move(p));
            } else {
                scene.objects.push_back(std::move(p));
                pieceWise_.push_back(loadedPieceWise_);
                shading_.push_back(std::move(shading[i]));
            }
        }
    }

    // Point lists get the radius rule of drawn points, on the drawn scene's
    // bounds (agreed over the ranks when the scene is split).
    void defaultPointListRadii(const Scene& scene, std::vector<SceneObject>& lists) const {
        Scene all;
        all.objects = lists;
        const double r = scene.objects.empty() ? all.bounds().radius() : bounds(scene).radius();
        const float fallback = float(r > 0 ? 0.005 * r : 0.01);
        for (auto& o : lists) {
            bool zero = true;
            for (std::size_t i = 3; zero && i < o.vertices.size(); i += 4) zero = o.vertices[i] == 0.f;
            if (zero) scenefile::setRadius(o, fallback);
        }
    }

    // Lines and points read from files carry radius 0: give them 0.5% of the
    // scene's bounding radius unless the scene file set one.
    void defaultRadii(Scene& scene) {
        const double r = frameBounds(scene).radius();
        const float fallback = float(r > 0 ? 0.005 * r : 0.01);
        for (auto& o : scene.objects) {
            if (o.representation == Representation::Surface) continue;
            bool zero = true;
            for (std::size_t i = 3; zero && i < o.vertices.size(); i += 4) zero = o.vertices[i] == 0.f;
            if (zero) scenefile::setRadius(o, fallback);
        }
    }

    // `channels: normals` (true = smooth, smooth, geometric, false) and
    // `featureAngle` into `out`; returns whether the normal channels are on.
    bool normalsChannel(const YAML::Node& n, NormalsOptions& out) const {
        if (!n || !n.IsMap()) return false;  // channels() reports a bad map
        bool on = false;
        if (const YAML::Node v = n["normals"]) {
            const std::string s = v.IsScalar() ? v.Scalar() : std::string();
            if (s == "smooth" || s == "geometric") {
                on = true;
                out.style = s == "smooth" ? NormalsOptions::Style::Smooth : NormalsOptions::Style::Geometric;
            } else if (s == "true" || s == "yes" || s == "on" || s == "false" || s == "no" || s == "off") {
                on = boolean(v, "normals");
            } else {
                fail(v, "normals must be smooth (or true: interpolated vertex normals), geometric (each triangle's "
                        "own normal) or false");
            }
        }
        if (const YAML::Node a = n["featureAngle"]) {
            if (out.style == NormalsOptions::Style::Geometric)
                fail(a, "'featureAngle' only applies to smooth normals (normals: smooth or true)");
            out.featureAngle = number(a, "featureAngle");
            if (out.featureAngle < 0 || out.featureAngle > 180)
                fail(a, "featureAngle must lie in [0, 180] degrees");
        }
        return on;
    }

    CaptureRequest channels(const YAML::Node& n, const Scene& scene, bool normalsOn) const {
        CaptureRequest req;
        std::vector<std::string> available;
        for (const auto& o : scene.objects)
            for (const auto& f : o.fields)
                if (std::find(available.begin(), available.end(), f.name) == available.end()) available.push_back(f.name);
        req.scalars = available;
        if (!n) return req;
        if (!n.IsMap()) fail(n, "'channels' must be a map (scalars, normals, featureAngle, objectId, primitiveId, layers)");
        checkKeys(n, {"scalars", "normals", "featureAngle", "objectId", "primitiveId", "layers"}, "channels");
        if (const YAML::Node s = n["scalars"]) {
            req.scalars = names(s, "scalars");
            for (std::size_t i = 0; i < req.scalars.size(); ++i)
                if (std::find(available.begin(), available.end(), req.scalars[i]) == available.end()) {
                    std::string list;
                    for (const auto& a : available) list += (list.empty() ? "" : ", ") + a;
                    fail(s[i], "no object carries the field '" + req.scalars[i] + "' (" +
                                   (available.empty() ? std::string("the objects keep no fields") : "kept fields: " + list) + ")");
                }
        }
        req.normals = normalsOn;
        if (n["objectId"]) req.objectId = boolean(n["objectId"], "objectId");
        if (n["primitiveId"]) req.primitiveId = boolean(n["primitiveId"], "primitiveId");
        // The K nearest surface crossings per pixel (darkroom/layers.h).
        if (n["layers"]) req.layers = integer(n["layers"], "layers (surface crossings per pixel)", 1, CaptureRequest::kMaxLayers);
        return req;
    }

    std::vector<double> angles(const YAML::Node& n, const char* what, double lo, double hi, bool phi) const {
        if (n.IsScalar()) {
            const int count = integer(n, std::string(what) + " (a count)", 1, 3600);
            return phi ? phiAngles(count) : thetaAngles(count);
        }
        if (!n.IsSequence() || n.size() == 0) fail(n, std::string(what) + " must be a count or a non-empty list of angles in degrees");
        std::vector<double> a;
        for (const auto& x : n) {
            const double v = number(x, std::string(what) + " angle");
            if (v < lo || v > hi) fail(x, std::string(what) + " angles must lie in [" + std::to_string(int(lo)) + ", " + std::to_string(int(hi)) + "]");
            a.push_back(v);
        }
        return a;
    }

    std::vector<CameraSample> cameras(const YAML::Node& n, const Scene& scene) const {
        Camera proto;
        proto.width = proto.height = 512;
        proto.fovYDegrees = 30.0;
        const Bounds b = frameBounds(scene);
        const double radius = camera_bounds::sceneRadius(b);
        const Vec3 center = camera_bounds::sceneCentre(b);
        if (n) {
            if (!n.IsMap()) fail(n, "'cameras' must be a map (projection, fov, height, resolution, grid or list)");
            checkKeys(n, {"projection", "fov", "height", "resolution", "grid", "list", "framing"}, "cameras");
            if (const YAML::Node f = n["framing"]; f && text(f, "framing") != "series" && f.Scalar() != "step")
                fail(f, "framing must be series (a time series framed once, on the union of its steps' bounds) "
                        "or step (each step framed on its own bounds)");
            if (const YAML::Node p = n["projection"]) {
                const std::string s = text(p, "projection");
                if (s == "perspective") proto.projection = Camera::Projection::Perspective;
                else if (s == "orthographic") proto.projection = Camera::Projection::Orthographic;
                else fail(p, "projection must be perspective or orthographic, got '" + s + "'");
            }
            if (const YAML::Node f = n["fov"]) {
                proto.fovYDegrees = number(f, "fov");
                check(f, camera_bounds::fovProblem(proto.fovYDegrees));
            }
            if (const YAML::Node r = n["resolution"]) {
                if (!r.IsSequence() || r.size() != 2) fail(r, "resolution must be [width, height]");
                proto.width = integer(r[0], "width", 1, 65536);
                proto.height = integer(r[1], "height", 1, 65536);
            }
            // Orthographic: by default the bounding sphere fits the narrower side.
            proto.viewHeight = 2.0 * radius * std::max(1.0, double(proto.height) / proto.width);
            if (const YAML::Node h = n["height"]) {
                proto.viewHeight = number(h, "height");
                check(h, camera_bounds::viewHeightProblem(proto.viewHeight, radius));
            }
            if (n["grid"] && n["list"]) fail(n, "give either 'grid' or 'list' cameras, not both");
            if (n["list"]) return cameraList(n["list"], proto, center, radius);
        } else {
            proto.viewHeight = 2.0 * radius;
        }
        if (n && n["grid"]) return cameraGrid(n["grid"], proto, center, radius);
        return cameraGrid(std::nullopt, proto, center, radius);
    }

    // `grid` absent: 8 azimuths on the equator.
    std::vector<CameraSample> cameraGrid(const std::optional<YAML::Node>& grid, const Camera& proto, Vec3 target,
                                         double radius) const {
        std::vector<double> phis = phiAngles(8), thetas = thetaAngles(1);
        Vec3 up{0, 1, 0};
        double distance = fittingDistance(proto, radius);
        if (grid) {
            const YAML::Node& g = *grid;
            if (!g.IsMap()) fail(g, "'grid' must be a map (phi, theta, distance, up, target)");
            checkKeys(g, {"phi", "theta", "distance", "up", "target"}, "grid");
            if (g["phi"]) phis = angles(g["phi"], "phi", -360, 360, true);
            if (g["theta"]) thetas = angles(g["theta"], "theta", -90, 90, false);
            if (g["up"]) up = direction(g["up"], "up");
            if (g["target"]) target = within(g["target"], vec3(g["target"], "target"), "target", target, radius);
            if (g["distance"]) {
                distance = number(g["distance"], "distance");
                check(g["distance"], camera_bounds::distanceProblem(distance, radius));
            }
        }
        std::vector<CameraSample> out;
        for (double phi : phis)
            for (double theta : thetas)
                out.push_back({{{"phi", phi}, {"theta", theta}}, orbitCamera(proto, target, distance, phi, theta, up)});
        return out;
    }

    std::vector<CameraSample> cameraList(const YAML::Node& l, const Camera& proto, const Vec3& center,
                                         double radius) const {
        if (!l.IsSequence() || l.size() == 0) fail(l, "'list' must be a non-empty list of {position, target or forward, up}");
        std::vector<CameraSample> out;
        for (std::size_t i = 0; i < l.size(); ++i) {
            const YAML::Node c = l[i];
            if (!c.IsMap()) fail(c, "each camera must be a map {position, target or forward, up}");
            checkKeys(c, {"position", "target", "forward", "up"}, "a camera");
            if (!c["position"]) fail(c, "camera " + std::to_string(i) + " needs a 'position'");
            if (c["target"] && c["forward"]) fail(c, "give either 'target' or 'forward', not both");
            Camera cam = proto;
            cam.position = within(c["position"], vec3(c["position"], "position"), "position", center, radius);
            const Vec3 target =
                c["target"] ? within(c["target"], vec3(c["target"], "target"), "target", center, radius) : center;
            if (c["forward"]) {
                cam.forward = direction(c["forward"], "forward");
            } else {
                cam.forward = target - cam.position;
                if (length(cam.forward) == 0)
                    fail(c, "camera " + std::to_string(i) + " looks nowhere (target equals position)");
                cam.forward = normalize(cam.forward);
            }
            if (c["up"]) cam.up = direction(c["up"], "up");
            if (length(cross(cam.forward, cam.up)) < 1e-9)
                fail(c["up"] ? c["up"] : c, "camera " + std::to_string(i) + ": up must not be parallel to the view direction");
            out.push_back({{{"camera", double(i)}}, cam});
        }
        return out;
    }

    // Camera values out of bounds (camera_bounds.h: they would abort inside Embree).
    void check(const YAML::Node& n, const std::string& problem) const {
        if (!problem.empty()) fail(n, problem);
    }
    // Wherever the grid or list put a camera, its rays start within a float's reach.
    void checkRayOrigin(const YAML::Node& n, const CameraSample& c) const {
        const std::string problem = camera_bounds::rayOriginProblem(c.camera);
        if (problem.empty()) return;
        std::string name;
        for (const auto& [k, v] : c.parameters)
            name += (name.empty() ? "" : ", ") + k + "=" + camera_bounds::shortNumber(v);
        fail(n, "camera " + name + ": " + problem);
    }
    Vec3 within(const YAML::Node& n, const Vec3& p, const std::string& what, const Vec3& center, double radius) const {
        check(n, camera_bounds::pointProblem(what, p, center, radius));
        return p;
    }
    // A unit direction; any non-zero length is accepted (scaled first, so 1e300 does not overflow).
    Vec3 direction(const YAML::Node& n, const std::string& what) const {
        const Vec3 v = vec3(n, what);
        const double m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
        if (!(m > 0)) fail(n, what + " must not be zero");
        return normalize(Vec3{v.x / m, v.y / m, v.z / m});
    }

    // The whole scene's bounds, also when this process holds only part of it.
    Bounds bounds(const Scene& scene) const {
        return group_ ? partition::agreeBounds(scene.bounds(), *group_) : scene.bounds();
    }

    // What cameras frame: a series' bounds when given (SceneLoadOptions::framing), else the scene's.
    Bounds frameBounds(const Scene& scene) const { return options_.framing ? *options_.framing : bounds(scene); }

    std::string source_, baseDir_;
    mutable std::map<std::string, std::shared_ptr<VolumeMesh>> volumes_;
    mutable std::vector<std::string> inputFiles_;
    ProcessGroup* group_ = nullptr;
    mutable bool loadedPieceWise_ = false;  // set by loadParts for the object being loaded
    std::vector<bool> pieceWise_;
    bool loadingPointList_ = false;
    std::size_t objectIndex_ = 0;  // of the object being loaded, in the file's `objects`
    SceneLoadOptions options_;
    // Whether surfaces get vertex normals, and those held per scene object
    // until all are loaded (scene_normals.h).
    bool vertexNormals_ = false;
    std::vector<VertexNormals> shading_;
};

[[noreturn]] void yamlError(const std::string& sourceName, const YAML::Exception& e) {
    throw InputError(sourceName + ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1) +
                     ": " + e.msg);
}

// One document, no repeated keys, aliases within a budget (yaml_guard.h).
YAML::Node loadYaml(const std::string& yamlText, const std::string& sourceName) {
    try {
        return yamlguard::load(yamlText);
    } catch (const YAML::Exception& e) {
        yamlError(sourceName, e);
    }
}

}  // namespace

SceneDescription parseSceneFile(const std::string& yamlText, const std::string& sourceName, const std::string& baseDir,
                                const SceneLoadOptions& options) {
    const YAML::Node root = loadYaml(yamlText, sourceName);
    try {
        return Parser(sourceName, baseDir, nullptr, options).parse(root);
    } catch (const YAML::Exception& e) {
        // A conversion yaml-cpp itself refused (should be rare: values are parsed here).
        yamlError(sourceName, e);
    }
}

SceneDescription loadSceneFile(const std::string& path, const SceneLoadOptions& options) {
    const std::string text = readInputFile(path, "scene file");
    return parseSceneFile(text, path, std::filesystem::path(path).parent_path().string(), options);
}

PartitionedScene parseSceneFilePart(const std::string& yamlText, const std::string& sourceName,
                                    const std::string& baseDir, ProcessGroup& group, const SceneLoadOptions& options) {
    // Every process parses the same text, so a problem in it is met by all
    // at the same point; problems met by some processes only (their pieces)
    // are agreed inside the parser.
    const YAML::Node root = loadYaml(yamlText, sourceName);
    Parser parser(sourceName, baseDir, &group, options);
    PartitionedScene out;
    try {
        out.description = parser.parse(root);
    } catch (const YAML::Exception& e) {
        yamlError(sourceName, e);
    }
    std::vector<SceneObject>& objects = out.description.scene->objects;
    const std::size_t n = objects.size();
    std::vector<std::uint64_t> pieceCounts(n, 0);
    out.primitiveOffset.assign(n, 0);
    out.wholePrimitiveCount.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        if (parser.pieceWise()[i]) {
            pieceCounts[i] = objects[i].primitiveCount();
            continue;
        }
        // Loaded whole by every process: keep this process's share.
        const auto [first, last] = partition::shareOf(objects[i], group.rank(), group.size());
        out.wholePrimitiveCount[i] = objects[i].primitiveCount();
        out.primitiveOffset[i] = first;
        objects[i] = partition::shareObject(objects[i], first, last);
    }
    // Pieces are read in rank order, so a process's primitives follow those of the lower ranks.
    std::vector<std::uint64_t> totals;
    const std::vector<std::uint64_t> before = partition::exclusiveSums(pieceCounts, group, totals);
    for (std::size_t i = 0; i < n; ++i)
        if (parser.pieceWise()[i]) {
            out.primitiveOffset[i] = before[i];
            out.wholePrimitiveCount[i] = totals[i];
        }
    return out;
}

PartitionedScene loadSceneFilePart(const std::string& path, ProcessGroup& group, const SceneLoadOptions& options) {
    std::string text, error;
    try {
        text = readInputFile(path, "scene file");
    } catch (const Error& e) {
        error = e.what();
    }
    partition::agreeNoError(error, group);
    return parseSceneFilePart(text, path, std::filesystem::path(path).parent_path().string(), group, options);
}

std::pair<std::size_t, std::size_t> blockOf(std::size_t count, int rank, int size) {
    const auto at = [&](int r) { return std::size_t((unsigned long long)count * unsigned(r) / unsigned(size)); };
    return {at(rank), at(rank + 1)};
}

}  // namespace darkroom
