#include "session.h"

#include "embree_backend.h"
#include "embree_scene.h"

#include <darkroom/data/cinema/writer.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/scene/scene_file.h>

#include <cmath>
#include <sstream>
#include <thread>

namespace darkroom::insitu {

struct Session::CameraSpec {
    bool orbit = false;
    Vec3 target, up, position;
    double distance = 0;
    std::vector<double> phi, theta;
};

struct Session::StepObject {
    embree::ObjectView view;
    std::vector<float> packed;  // x, y, z, radius records when they had to be joined
};

struct Session::Step {
    double time = 0;
    std::vector<StepObject> objects;
};

Session::Session(std::string database, int mode) : database_(std::move(database)), mode_(mode) {
    if (database_.empty()) throw BadInput("darkroom_insitu_open: the database path is empty");
    if (mode < 0 || mode > 2)
        throw BadInput("darkroom_insitu_open: mode " + std::to_string(mode) +
                       " is not DARKROOM_INSITU_CREATE (0), _OVERWRITE (1) or _RESUME (2)");
    ranks_ = aloneRanks();
}

Session::~Session() = default;

void Session::setRanks(std::unique_ptr<Ranks> ranks) {
    if (writer_ || rows_ > 0) throw BadInput("darkroom_insitu_set_mpi_comm: call it before the first capture");
    ranks_ = std::move(ranks);
}

void Session::setThreads(int threads) {
    if (threads < 0) throw BadInput("darkroom_insitu_set_threads: " + std::to_string(threads) + " threads; expected 0 or more");
    threads_ = threads;
    context_.reset();
}

void Session::setImage(int width, int height, double fov, double viewHeight) {
    if (width < 1 || height < 1 || width > 65536 || height > 65536)
        throw BadInput("darkroom_insitu_set_image: " + std::to_string(width) + " x " + std::to_string(height) +
                       " pixels; expected 1 to 65536 each way");
    if (fov == 0.0 ? !(viewHeight > 0 && std::isfinite(viewHeight)) : !(fov > 0 && fov < 180))
        throw BadInput("darkroom_insitu_set_image: expected a field of view in (0, 180) degrees, or 0 and a positive "
                       "view height for an orthographic camera");
    width_ = width;
    height_ = height;
    fov_ = fov;
    viewHeight_ = viewHeight;
}

void Session::cameraOrbit(const Vec3& target, double distance, const Vec3& up, std::vector<double> phi,
                          std::vector<double> theta) {
    if (!cameraSpecs_.empty())
        throw BadInput("darkroom_insitu_camera_orbit: the session already has cameras; give one orbit or a list");
    if (!(distance > 0) || !std::isfinite(distance))
        throw BadInput("darkroom_insitu_camera_orbit: the distance must be positive");
    if (!(length(up) > 0)) throw BadInput("darkroom_insitu_camera_orbit: up must not be zero");
    if (phi.empty() || theta.empty())
        throw BadInput("darkroom_insitu_camera_orbit: expected at least one phi and one theta angle");
    for (double t : theta)
        if (!(t >= -90 && t <= 90)) throw BadInput("darkroom_insitu_camera_orbit: theta angles must lie in [-90, 90]");
    for (double p : phi)
        if (!(p >= -360 && p <= 360)) throw BadInput("darkroom_insitu_camera_orbit: phi angles must lie in [-360, 360]");
    CameraSpec c;
    c.orbit = true;
    c.target = target;
    c.distance = distance;
    c.up = up;
    c.phi = std::move(phi);
    c.theta = std::move(theta);
    cameraSpecs_.push_back(std::move(c));
}

void Session::addCamera(const Vec3& position, const Vec3& target, const Vec3& up) {
    if (!cameraSpecs_.empty() && cameraSpecs_.front().orbit)
        throw BadInput("darkroom_insitu_add_camera: the session has an orbit; give one orbit or a list");
    if (!(length(target - position) > 0)) throw BadInput("darkroom_insitu_add_camera: the target equals the position");
    if (!(length(cross(target - position, up)) > 1e-12 * length(target - position)))
        throw BadInput("darkroom_insitu_add_camera: up must not be parallel to the view direction");
    CameraSpec c;
    c.position = position;
    c.target = target;
    c.up = up;
    cameraSpecs_.push_back(c);
}

void Session::requestField(const std::string& name) {
    static const char* reserved[] = {"Z", "N.x", "N.y", "N.z", "objectId", "primitiveId"};
    if (name.empty()) throw BadInput("darkroom_insitu_request_field: the name is empty");
    for (const char* r : reserved)
        if (name == r) throw BadInput("darkroom_insitu_request_field: '" + name + "' is the name of a G-buffer channel");
    for (const auto& s : request_.scalars)
        if (s == name) throw BadInput("darkroom_insitu_request_field: '" + name + "' is requested twice");
    request_.scalars.push_back(name);
}

std::vector<std::pair<std::vector<std::pair<std::string, double>>, Camera>> Session::cameras() const {
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
    std::vector<std::pair<std::vector<std::pair<std::string, double>>, Camera>> out;
    for (std::size_t i = 0; i < cameraSpecs_.size(); ++i) {
        const CameraSpec& c = cameraSpecs_[i];
        if (c.orbit) {
            for (double phi : c.phi)
                for (double theta : c.theta)
                    out.push_back({{{"phi", phi}, {"theta", theta}}, orbitCamera(proto, c.target, c.distance, phi, theta, c.up)});
            continue;
        }
        Camera cam = proto;
        cam.position = c.position;
        cam.forward = normalize(c.target - c.position);
        cam.up = c.up;
        out.push_back({{{"camera", double(i)}}, cam});
    }
    return out;
}

void Session::beginStep(double time) {
    if (!std::isfinite(time)) throw BadInput("darkroom_insitu_begin_step: the time must be a finite number");
    step_ = std::make_unique<Step>();
    step_->time = time;
}

Session::StepObject& Session::declare(const std::string& name, Representation representation) {
    if (!step_) throw BadInput("declare objects after darkroom_insitu_begin_step");
    if (name.empty()) throw BadInput("an object needs a name");
    for (const auto& o : step_->objects)
        if (o.view.name == name) throw BadInput("object '" + name + "' is declared twice in this step");
    StepObject o;
    o.view.name = name;
    o.view.representation = representation;
    step_->objects.push_back(std::move(o));
    return step_->objects.back();
}

namespace {

void checkCount(const char* call, const std::string& name, const char* what, std::int64_t count, const void* data) {
    if (count < 0 || count > std::int64_t(0xFFFFFFFFu))
        throw BadInput(std::string(call) + ": object '" + name + "' has " + std::to_string(count) + " " + what +
                       "; expected 0 to 2^32 - 1");
    if (count > 0 && !data)
        throw BadInput(std::string(call) + ": object '" + name + "' has " + std::to_string(count) + " " + what +
                       " but no array");
}

}  // namespace

void Session::triangles(const std::string& name, const float* vertices, std::size_t stride, std::int64_t vertexCount,
                        const std::uint32_t* triangles, std::int64_t triangleCount) {
    checkCount("darkroom_insitu_triangles", name, "vertices", vertexCount, vertices);
    checkCount("darkroom_insitu_triangles", name, "triangles", triangleCount, triangles);
    if (stride == 0) stride = 12;
    if (stride < 12 || stride % 4 != 0)
        throw BadInput("darkroom_insitu_triangles: object '" + name + "': vertices " + std::to_string(stride) +
                       " bytes apart; expected a multiple of 4 of at least 12 (x, y, z)");
    StepObject& o = declare(name, Representation::Surface);
    o.view.vertices = vertices;
    o.view.vertexStride = stride;
    o.view.vertexCount = std::size_t(vertexCount);
    o.view.indices = triangles;
    o.view.primitiveCount = std::size_t(triangleCount);
}

const float* Session::roundVertices(StepObject& o, const float* vertices, std::size_t stride, std::int64_t count,
                                    const float* radii, float radius) {
    if (stride == 0) stride = 16;
    if (stride < 12 || stride % 4 != 0)
        throw BadInput("object '" + o.view.name + "': vertices " + std::to_string(stride) +
                       " bytes apart; expected a multiple of 4 of at least 12 (x, y, z)");
    if (!radii && stride >= 16) {
        // Shared as they are: x, y, z, radius records.
        o.view.vertexStride = stride;
        return vertices;
    }
    if (!radii && !(radius > 0 && std::isfinite(radius)))
        throw BadInput("object '" + o.view.name + "': give radii, records of x, y, z, radius, or a positive radius");
    // Embree reads x, y, z, radius together: join them (counted as copied).
    o.packed.resize(4 * std::size_t(count));
    for (std::size_t i = 0; i < std::size_t(count); ++i) {
        const float* v = reinterpret_cast<const float*>(reinterpret_cast<const char*>(vertices) + i * stride);
        o.packed[4 * i] = v[0];
        o.packed[4 * i + 1] = v[1];
        o.packed[4 * i + 2] = v[2];
        o.packed[4 * i + 3] = radii ? radii[i] : radius;
    }
    copied_ += std::int64_t(16 * std::size_t(count));
    o.view.vertexStride = 16;
    return o.packed.data();
}

Session::StepObject& Session::declareRound(const std::string& name, Representation representation,
                                           const float* vertices, std::size_t stride, std::int64_t vertexCount,
                                           const float* radii, float radius) {
    StepObject& o = declare(name, representation);
    try {
        o.view.vertices = roundVertices(o, vertices, stride, vertexCount, radii, radius);
    } catch (...) {
        step_->objects.pop_back();  // a refused call declares nothing
        throw;
    }
    o.view.vertexCount = std::size_t(vertexCount);
    return o;
}

void Session::lines(const std::string& name, const float* vertices, std::size_t stride, std::int64_t vertexCount,
                    const std::uint32_t* segments, std::int64_t segmentCount, const float* radii, float radius) {
    checkCount("darkroom_insitu_lines", name, "vertices", vertexCount, vertices);
    checkCount("darkroom_insitu_lines", name, "segments", segmentCount, segments);
    StepObject& o = declareRound(name, Representation::Lines, vertices, stride, vertexCount, radii, radius);
    o.view.indices = segments;
    o.view.primitiveCount = std::size_t(segmentCount);
}

void Session::points(const std::string& name, const float* vertices, std::size_t stride, std::int64_t vertexCount,
                     const float* radii, float radius) {
    checkCount("darkroom_insitu_points", name, "vertices", vertexCount, vertices);
    StepObject& o = declareRound(name, Representation::Points, vertices, stride, vertexCount, radii, radius);
    o.view.primitiveCount = std::size_t(vertexCount);
}

void Session::field(const std::string& object, const std::string& name, const float* values, std::int64_t count,
                    int association) {
    if (!step_) throw BadInput("darkroom_insitu_field: declare objects after darkroom_insitu_begin_step");
    StepObject* o = nullptr;
    for (auto& x : step_->objects)
        if (x.view.name == object) o = &x;
    if (!o) throw BadInput("darkroom_insitu_field: no object '" + object + "' in this step");
    if (association != 0 && association != 1)
        throw BadInput("darkroom_insitu_field: association " + std::to_string(association) +
                       " is not DARKROOM_INSITU_POINT_DATA (0) or _CELL_DATA (1)");
    checkCount("darkroom_insitu_field", object, "values", count, values);
    const bool cell = association == 1;
    const std::size_t expected = cell ? o->view.primitiveCount : o->view.vertexCount;
    if (std::size_t(count) != expected)
        throw BadInput("darkroom_insitu_field: field '" + name + "' of object '" + object + "' has " +
                       std::to_string(count) + " values; expected one per " + (cell ? "primitive (" : "vertex (") +
                       std::to_string(expected) + ")");
    if (o->view.field(name)) throw BadInput("darkroom_insitu_field: object '" + object + "' already has a field '" + name + "'");
    o->view.fields.push_back({name, values, std::size_t(count), cell});
}

void Session::openWriter(const std::vector<std::string>& columns) {
    CinemaWriterOptions o;
    o.overwrite = mode_ == 1;
    o.resume = mode_ == 2;
    o.image.halfFloat = half_;
    writer_ = std::make_unique<CinemaWriter>(database_, columns, o);
}

void Session::capture() {
    if (closed_) throw BadInput("darkroom_insitu_capture: the session is closed");
    if (cameraSpecs_.empty())
        throw BadInput("darkroom_insitu_capture: no cameras (darkroom_insitu_camera_orbit or _add_camera)");
    if (!step_) throw BadInput("darkroom_insitu_capture: call darkroom_insitu_begin_step and hand over the objects first");
    const bool several = ranks_->size() > 1;
    const bool root = ranks_->rank() == 0;

    // This rank's part: the acceleration structure over the simulation's arrays.
    std::string error, names;
    std::unique_ptr<embree::SceneBvh> bvh;
    std::vector<std::uint64_t> counts;
    std::vector<embree::ObjectView> views;
    for (const auto& o : step_->objects) {
        views.push_back(o.view);
        counts.push_back(o.view.primitiveCount);
        names += o.view.name + '\n';
    }
    try {
        if (!device_) device_ = std::make_shared<embree::Device>();
        bvh = std::make_unique<embree::SceneBvh>(device_, views, nullptr);
    } catch (const Error& e) {
        error = e.what();
    }
    if (several) {
        // Objects are matched by declaration order: the same names everywhere.
        const auto all = ranks_->allGather(names);
        for (std::size_t r = 1; r < all.size() && error.empty(); ++r)
            if (all[r] != all[0])
                error = "rank " + std::to_string(r) + " declared the objects [" + all[r] + "] but rank 0 [" + all[0] +
                        "]; every rank must declare the same objects in the same order";
        for (char& c : error)
            if (c == '\n') c = ' ';
    }
    if (const std::string e = ranks_->agreedError(error); !e.empty()) throw Error(e);
    const std::vector<std::uint64_t> offsets = ranks_->exclusiveSums(counts);

    // The database is opened on the first capture, on rank 0, which also
    // decides which rows a resumed session still lacks.
    const auto cams = cameras();
    std::string todo;
    if (root) {
        try {
            if (!writer_) {
                std::vector<std::string> columns{"time"};
                for (const auto& [name, v] : cams.front().first) columns.push_back(name);
                openWriter(columns);
            }
            for (std::size_t i = 0; i < cams.size(); ++i) {
                CinemaParameters p{{"time", CinemaValue(step_->time)}};
                for (const auto& [name, v] : cams[i].first) p.emplace(name, CinemaValue(v));
                if (!writer_->hasEntry(p)) todo += std::to_string(i) + " ";
            }
        } catch (const Error& e) {
            error = e.what();
        }
    }
    if (const std::string e = ranks_->agreedError(error); !e.empty()) throw Error(e);
    ranks_->broadcast(todo);

    if (!context_) {
        FilterRunOptions ro;
        const int cores = int(std::thread::hardware_concurrency());
        ro.threads = threads_ ? threads_ : several ? std::max(1, cores / std::max(1, ranks_->onThisNode())) : 0;
        context_ = makeStandaloneContext(ro, "insitu");
    }
    CaptureRequest request = request_;
    if (several) request.objectId = request.primitiveId = true;  // they break ties across ranks
    std::istringstream in(todo);
    for (std::size_t i; in >> i;) {
        BufferPtr image;
        try {
            image = embree::renderGBuffer(*bvh, cams[i].second, request, *context_);
        } catch (const Error& e) {
            error = e.what();
        }
        // A failure on any rank (this render, or rank 0's last write) stops all.
        if (const std::string e = ranks_->agreedError(error); !e.empty()) throw Error(e);
        if (several) image = ranks_->composite(*image, offsets, request_.objectId, request_.primitiveId);
        if (!image) continue;
        try {
            CinemaParameters p{{"time", CinemaValue(step_->time)}};
            for (const auto& [name, v] : cams[i].first) p.emplace(name, CinemaValue(v));
            writer_->addEntry(p, *image);
            ++rows_;
        } catch (const Error& e) {
            error = e.what();
        }
    }
    if (const std::string e = ranks_->agreedError(error); !e.empty()) throw Error(e);
}

void Session::close() {
    if (closed_) return;
    closed_ = true;
    std::string error;
    try {
        if (writer_) writer_->finish();
    } catch (const Error& e) {
        error = e.what();
    }
    const std::string e = ranks_->agreedError(error);
    writer_.reset();
    ranks_.reset();  // frees the duplicated communicator (collective)
    if (!e.empty()) throw Error(e);
}

}  // namespace darkroom::insitu
