#include "session_setup.h"

#include "arguments.h"

#include <darkroom/core/hash_mix.h>
#include <darkroom/scene/camera_bounds.h>
#include <darkroom/scene/scene_file.h>

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>

namespace darkroom::insitu {

namespace {

std::string number(double v) { return CinemaValue(v).str(); }

// `v` scaled to a largest coordinate of 1: a direction, without overflow.
Vec3 scaled(const Vec3& v) {
    const double m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    return Vec3{v.x / m, v.y / m, v.z / m};
}

}  // namespace

void Setup::refuseIfFixed(const char* call) const {
    if (fixed_)
        throw BadInput(std::string(call) +
                       ": the session's setup is fixed after its first capture (its database holds products of "
                       "that setup); close the session and open a new database to change it");
}

void Setup::setImage(int width, int height, double fov, double viewHeight) {
    const char* call = "darkroom_insitu_set_image";
    refuseIfFixed(call);
    if (width < 1 || height < 1 || width > 65536 || height > 65536)
        throw BadInput(std::string(call) + ": " + std::to_string(width) + " x " + std::to_string(height) +
                       " pixels; expected 1 to 65536 each way");
    if (!(viewHeight >= 0) || !std::isfinite(viewHeight))
        throw BadInput(std::string(call) + ": view height " + camera_bounds::shortNumber(viewHeight) +
                       "; expected a finite height of 0 or more (world units)");
    if (fov == 0.0 && !(viewHeight > 0))
        throw BadInput(std::string(call) + ": an orthographic camera (fov 0) needs a positive view height");
    if (fov != 0.0)
        if (const std::string p = camera_bounds::fovProblem(fov); !p.empty())
            throw BadInput(std::string(call) + ": " + p + " (or 0 for an orthographic camera)");
    width_ = width;
    height_ = height;
    fov_ = fov;
    viewHeight_ = viewHeight;
}

void Setup::cameraOrbit(const Vec3& target, double distance, const Vec3& up, std::vector<double> phi,
                        std::vector<double> theta) {
    const char* call = "darkroom_insitu_camera_orbit";
    refuseIfFixed(call);
    if (!specs_.empty()) throw BadInput(std::string(call) + ": the session already has cameras; give one orbit or a list");
    checkFinite(call, "target", target);
    if (!(distance > 0) || !std::isfinite(distance))
        throw BadInput(std::string(call) + ": distance " + camera_bounds::shortNumber(distance) +
                       "; expected a positive finite distance");
    checkDirection(call, "up", up);
    if (phi.empty() || theta.empty())
        throw BadInput(std::string(call) + ": expected at least one phi and one theta angle");
    for (double t : theta)
        if (!(t >= -90 && t <= 90)) throw BadInput(std::string(call) + ": theta angles must lie in [-90, 90]");
    for (double p : phi)
        if (!(p >= -360 && p <= 360)) throw BadInput(std::string(call) + ": phi angles must lie in [-360, 360]");
    CameraSpec c;
    c.orbit = true;
    c.target = target;
    c.distance = distance;
    c.up = up;
    c.phi = std::move(phi);
    c.theta = std::move(theta);
    specs_.push_back(std::move(c));
}

void Setup::addCamera(const Vec3& position, const Vec3& target, const Vec3& up) {
    const char* call = "darkroom_insitu_add_camera";
    refuseIfFixed(call);
    if (!specs_.empty() && specs_.front().orbit)
        throw BadInput(std::string(call) + ": the session has an orbit; give one orbit or a list");
    checkFinite(call, "position", position);
    checkFinite(call, "target", target);
    checkDirection(call, "up", up);
    const Vec3 d = target - position;
    if (d.x == 0 && d.y == 0 && d.z == 0) throw BadInput(std::string(call) + ": the target equals the position");
    if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z))
        throw BadInput(std::string(call) + ": the position and the target are too far apart for a double");
    // As scene files: forward and up normalised, then their cross product.
    if (length(cross(normalize(scaled(d)), normalize(scaled(up)))) < 1e-9)
        throw BadInput(std::string(call) + ": up must not be parallel to the view direction");
    CameraSpec c;
    c.position = position;
    c.target = target;
    c.up = up;
    specs_.push_back(c);
}

void Setup::requestField(const std::string& name) {
    const char* call = "darkroom_insitu_request_field";
    refuseIfFixed(call);
    checkName(call, "field name", name);
    static const char* reserved[] = {"Z", "N.x", "N.y", "N.z", "objectId", "primitiveId"};
    for (const char* r : reserved)
        if (name == r) throw BadInput(std::string(call) + ": '" + name + "' is the name of a G-buffer channel");
    for (const auto& s : request_.scalars)
        if (s == name) throw BadInput(std::string(call) + ": '" + name + "' is requested twice");
    request_.scalars.push_back(name);
}

void Setup::requestNormals(int on) {
    refuseIfFixed("darkroom_insitu_request_normals");
    request_.normals = checkSwitch("darkroom_insitu_request_normals", "on", on);
}

void Setup::requestIds(int objectIds, int primitiveIds) {
    const char* call = "darkroom_insitu_request_ids";
    refuseIfFixed(call);
    const bool object = checkSwitch(call, "object_ids", objectIds);
    request_.primitiveId = checkSwitch(call, "primitive_ids", primitiveIds);
    request_.objectId = object;
}

void Setup::setHalfFloat(int on) {
    refuseIfFixed("darkroom_insitu_set_half_float");
    half_ = checkSwitch("darkroom_insitu_set_half_float", "on", on);
}

void Setup::checkReach(const Bounds& data) const {
    const double radius = camera_bounds::sceneRadius(data);
    const Vec3 centre = camera_bounds::sceneCentre(data);
    auto refuse = [](const std::string& where, const std::string& problem) {
        if (!problem.empty()) throw BadInput("darkroom_insitu_capture: " + where + problem);
    };
    // The scene, for these bounds, is this step's objects on every rank. A
    // step without any (no particles yet) says nothing of where the data
    // lie: only the float's reach applies then.
    if (fov_ == 0.0 && !data.empty()) refuse("", camera_bounds::viewHeightProblem(viewHeight_, radius));
    for (std::size_t i = 0; i < specs_.size() && !data.empty(); ++i) {
        const CameraSpec& c = specs_[i];
        if (c.orbit) {
            refuse("the orbit's ", camera_bounds::pointProblem("target", c.target, centre, radius));
            refuse("the orbit's ", camera_bounds::distanceProblem(c.distance, radius));
            continue;
        }
        const std::string camera = "camera " + std::to_string(i) + ": ";
        refuse(camera, camera_bounds::pointProblem("position", c.position, centre, radius));
        refuse(camera, camera_bounds::pointProblem("target", c.target, centre, radius));
    }
    // Within the scene's reach, yet perhaps beyond a float's (a huge scene).
    for (const auto& [parameters, camera] : cameras()) {
        std::string name;
        for (const auto& [k, v] : parameters) name += (name.empty() ? "" : ", ") + k + "=" + number(v);
        refuse("camera " + name + ": ", camera_bounds::rayOriginProblem(camera));
    }
}

CameraList Setup::cameras() const {
    Camera proto;
    proto.width = width_;
    proto.height = height_;
    if (fov_ > 0) {
        proto.projection = Camera::Projection::Perspective;
        proto.fovYDegrees = fov_;
    } else {
        proto.projection = Camera::Projection::Orthographic;
        proto.viewHeight = viewHeight_;
    }
    CameraList out;
    for (std::size_t i = 0; i < specs_.size(); ++i) {
        const CameraSpec& c = specs_[i];
        if (c.orbit) {
            for (double phi : c.phi)
                for (double theta : c.theta)
                    out.push_back({{{"phi", phi}, {"theta", theta}}, orbitCamera(proto, c.target, c.distance, phi, theta, c.up)});
            continue;
        }
        Camera cam = proto;
        cam.position = c.position;
        cam.forward = normalize(c.target - c.position);  // as scene files: the same bytes
        cam.up = c.up;
        out.push_back({{{"camera", double(i)}}, cam});
    }
    return out;
}

std::vector<CinemaOriginItem> Setup::origin() const {
    const std::string source = "the session's setup";
    std::string cameras = "none";
    std::uint64_t poses = 0;
    for (const auto& c : specs_) {
        for (const Vec3& v : {c.target, c.up, c.position})
            for (double x : {v.x, v.y, v.z}) poses = hashing::mixDouble(poses, x);
        poses = hashing::mixDouble(poses, c.distance);
        for (double a : c.phi) poses = hashing::mixDouble(poses, a);
        poses = hashing::mix(poses, c.phi.size());
        for (double a : c.theta) poses = hashing::mixDouble(poses, a);
        poses = hashing::mix(poses, c.theta.size());
    }
    if (!specs_.empty())
        cameras = specs_.front().orbit ? "an orbit of " + std::to_string(specs_.front().phi.size()) + " phi x " +
                                             std::to_string(specs_.front().theta.size()) + " theta"
                                       : "a list of " + std::to_string(specs_.size());
    char posesHex[17];
    std::snprintf(posesHex, sizeof posesHex, "%016" PRIx64, poses);
    std::string channels;
    auto addChannel = [&](const std::string& c) { channels += (channels.empty() ? "" : ",") + c; };
    for (const auto& s : request_.scalars) addChannel(s);
    if (request_.normals) addChannel("normals");
    if (request_.objectId) addChannel("objectId");
    if (request_.primitiveId) addChannel("primitiveId");
    return {
        {source, "resolution", std::to_string(width_) + "x" + std::to_string(height_), false},
        {source, "projection",
         fov_ > 0 ? "perspective, fov " + number(fov_) : "orthographic, height " + number(viewHeight_), false},
        {source, "cameras", cameras, false},
        {source, "camera poses", posesHex, true},
        {source, "channels", channels.empty() ? "depth only" : channels, false},
        {source, "half floats", half_ ? "yes" : "no", false},
    };
}

}  // namespace darkroom::insitu
