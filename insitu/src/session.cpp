#include "session.h"

#include "embree_backend.h"
#include "embree_scene.h"
#include "step_bounds.h"

#include <darkroom/data/cinema/writer.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/scene/scene_file.h>
#include <darkroom/workflows/capture.h>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <thread>

namespace darkroom::insitu {

struct Session::StepObject {
    embree::ObjectView view;
    // x, y, z, radius records when they had to be joined; 16-byte aligned
    // (operator new's alignment), as Embree loads them.
    std::vector<float> packed;
    static_assert(__STDCPP_DEFAULT_NEW_ALIGNMENT__ >= 16);
};

struct Session::Step {
    double time = 0;
    std::vector<StepObject> objects;
};

Session::Session(std::string database, int mode) : database_(std::move(database)), mode_(mode) {
    checkName("darkroom_insitu_open", "database path", database_);
    if (mode < 0 || mode > 2)
        throw BadInput("darkroom_insitu_open: mode " + std::to_string(mode) +
                       " is not DARKROOM_INSITU_CREATE (0), _OVERWRITE (1) or _RESUME (2)");
    ranks_ = aloneRanks();
}

Session::~Session() = default;

void Session::setRanks(std::unique_ptr<ProcessGroup> ranks) {
    if (setup_.fixed()) throw BadInput("darkroom_insitu_set_mpi_comm: call it before the first capture");
    ranks_ = std::move(ranks);
}

void Session::setThreads(int threads) {
    if (threads < 0 || threads > kMaxThreads)
        throw BadInput("darkroom_insitu_set_threads: " + std::to_string(threads) + " threads; expected 0 to " +
                       std::to_string(kMaxThreads) + " (0: the machine's cores)");
    threads_ = threads;
    context_.reset();
}

void Session::beginStep(double time) {
    if (!std::isfinite(time)) throw BadInput("darkroom_insitu_begin_step: the time must be a finite number");
    step_ = std::make_unique<Step>();
    step_->time = time;
}

Session::StepObject& Session::declare(const char* call, const std::string& name, Representation representation) {
    if (!step_) throw BadInput(std::string(call) + ": declare objects after darkroom_insitu_begin_step");
    for (const auto& o : step_->objects)
        if (o.view.name == name)
            throw BadInput(std::string(call) + ": object '" + name + "' is declared twice in this step");
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
    const char* call = "darkroom_insitu_triangles";
    checkName(call, "object name", name);
    checkCount(call, name, "vertices", vertexCount, vertices);
    checkCount(call, name, "triangles", triangleCount, triangles);
    stride = checkStride(call, name, stride, 12);
    StepObject& o = declare(call, name, Representation::Surface);
    o.view.vertices = vertices;
    o.view.vertexStride = stride;
    o.view.vertexCount = std::size_t(vertexCount);
    o.view.indices = triangles;
    o.view.primitiveCount = std::size_t(triangleCount);
}

const float* Session::roundVertices(const char* call, StepObject& o, const float* vertices, std::size_t stride,
                                    std::int64_t count, const float* radii, float radius) {
    const std::string& name = o.view.name;
    stride = checkStride(call, name, stride, 16);
    const bool recordRadii = !radii && stride >= 16;
    checkRadius(call, name, radius, !radii && !recordRadii);
    if (recordRadii && count > 0) checkRadii(call, name, vertices + 3, stride, count);  // NULL when count is 0
    if (radii) checkRadii(call, name, radii, sizeof(float), count);
    // Embree loads each x, y, z, radius record of tubes and spheres with one
    // aligned 16-byte load (a misaligned one segfaults in its BVH build).
    const bool aligned = reinterpret_cast<std::uintptr_t>(vertices) % 16 == 0 && stride % 16 == 0;
    if (recordRadii && aligned) {
        o.view.vertexStride = stride;  // shared as they are
        return vertices;
    }
    // Joined into aligned records (counted as copied).
    o.packed.resize(4 * std::size_t(count));
    for (std::size_t i = 0; i < std::size_t(count); ++i) {
        const float* v = reinterpret_cast<const float*>(reinterpret_cast<const char*>(vertices) + i * stride);
        o.packed[4 * i] = v[0];
        o.packed[4 * i + 1] = v[1];
        o.packed[4 * i + 2] = v[2];
        o.packed[4 * i + 3] = radii ? radii[i] : recordRadii ? v[3] : radius;
    }
    copied_ += std::int64_t(16 * std::size_t(count));
    o.view.vertexStride = 16;
    return o.packed.data();
}

Session::StepObject& Session::declareRound(const char* call, const std::string& name, Representation representation,
                                           const float* vertices, std::size_t stride, std::int64_t vertexCount,
                                           const float* radii, float radius) {
    StepObject& o = declare(call, name, representation);
    try {
        o.view.vertices = roundVertices(call, o, vertices, stride, vertexCount, radii, radius);
    } catch (...) {
        step_->objects.pop_back();  // a refused call declares nothing
        throw;
    }
    o.view.vertexCount = std::size_t(vertexCount);
    return o;
}

void Session::lines(const std::string& name, const float* vertices, std::size_t stride, std::int64_t vertexCount,
                    const std::uint32_t* segments, std::int64_t segmentCount, const float* radii, float radius) {
    const char* call = "darkroom_insitu_lines";
    checkName(call, "object name", name);
    checkCount(call, name, "vertices", vertexCount, vertices);
    checkCount(call, name, "segments", segmentCount, segments);
    StepObject& o = declareRound(call, name, Representation::Lines, vertices, stride, vertexCount, radii, radius);
    o.view.indices = segments;
    o.view.primitiveCount = std::size_t(segmentCount);
}

void Session::points(const std::string& name, const float* vertices, std::size_t stride, std::int64_t vertexCount,
                     const float* radii, float radius) {
    const char* call = "darkroom_insitu_points";
    checkName(call, "object name", name);
    checkCount(call, name, "vertices", vertexCount, vertices);
    StepObject& o = declareRound(call, name, Representation::Points, vertices, stride, vertexCount, radii, radius);
    o.view.primitiveCount = std::size_t(vertexCount);
}

void Session::field(const std::string& object, const std::string& name, const float* values, std::int64_t count,
                    int association) {
    if (!step_) throw BadInput("darkroom_insitu_field: declare objects after darkroom_insitu_begin_step");
    checkName("darkroom_insitu_field", "object name", object);
    checkName("darkroom_insitu_field", "field name", name);
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
    // A refusal advises what a simulation chooses: darkroom_insitu_open's mode.
    o.overwriteAdvice = "DARKROOM_INSITU_OVERWRITE";
    o.resumeAdvice = "DARKROOM_INSITU_RESUME";
    o.image.halfFloat = setup_.halfFloat();
    o.origin = setup_.origin();  // a resume of a database made with another setup is refused
    writer_ = std::make_unique<CinemaWriter>(database_, columns, o);
}

void Session::capture() {
    if (closed_) throw BadInput("darkroom_insitu_capture: the session is closed");
    if (!setup_.hasCameras())
        throw BadInput("darkroom_insitu_capture: no cameras (darkroom_insitu_camera_orbit or _add_camera)");
    if (!step_) throw BadInput("darkroom_insitu_capture: call darkroom_insitu_begin_step and hand over the objects first");
    std::vector<embree::ObjectView> views;
    for (const auto& o : step_->objects) views.push_back(o.view);
    // Cameras against the data's size: the same bounds, so the same answer,
    // on every rank that made the same setup calls; agreed all the same, so
    // that ranks set up differently fail together rather than wait.
    std::string outOfReach;
    try {
        setup_.checkReach(agreeBounds(*ranks_, boundsOf(views)));
    } catch (const BadInput& e) {
        outOfReach = e.what();
    }
    if (const std::string e = ranks_->agreedError(outOfReach); !e.empty()) throw BadInput(e);
    const std::unique_ptr<embree::SceneBvh> bvh = buildThisRanksPart(views);
    if (!context_) {
        FilterRunOptions ro;
        const int cores = int(std::thread::hardware_concurrency());
        const bool several = ranks_->size() > 1;
        ro.threads = threads_ ? threads_ : several ? std::max(1, cores / std::max(1, ranks_->onThisNode())) : 0;
        context_ = makeStandaloneContext(ro, "insitu");
    }
    workflows::CaptureSettings settings;
    settings.request = setup_.request();
    std::vector<std::uint64_t> counts;
    for (const auto& v : views) counts.push_back(v.primitiveCount);
    settings.primitiveOffsets = ranks_->exclusiveSums(counts);
    const CameraList cams = setup_.cameras();
    // The database is opened on the first capture, on rank 0, which also
    // decides which rows a resumed session still lacks.
    settings.openDatabase = [&]() -> CinemaWriter& {
        if (!writer_) {
            std::vector<std::string> columns{"time"};
            for (const auto& [name, v] : cams.front().first) columns.push_back(name);
            openWriter(columns);
        }
        return *writer_;
    };
    settings.entriesAgreed = [this] { setup_.fix(); };  // the database holds products of this setup now
    std::vector<workflows::CaptureEntry> entries;
    for (const auto& [parameters, camera] : cams) {
        workflows::CaptureEntry e;
        e.camera = camera;
        e.parameters.emplace("time", CinemaValue(step_->time));
        for (const auto& [name, v] : parameters) e.parameters.emplace(name, CinemaValue(v));
        entries.push_back(std::move(e));
    }
    const workflows::RenderFn render = [&](const Camera& camera, const CaptureRequest& request) {
        return BufferPtr(embree::renderGBuffer(*bvh, camera, request, *context_));
    };
    try {
        const workflows::CaptureSummary done = workflows::captureEntries(entries, render, *ranks_, settings);
        if (ranks_->lead()) rows_ += std::int64_t(done.rendered);
    } catch (const InputError& e) {
        throw Error(e.what());  // a refused database is the session's error, as before the loop was shared
    }
}

std::unique_ptr<embree::SceneBvh> Session::buildThisRanksPart(const std::vector<embree::ObjectView>& views) {
    // This rank's part: the acceleration structure over the simulation's arrays.
    std::string error, names;
    for (const auto& v : views) names += v.name + '\n';
    std::unique_ptr<embree::SceneBvh> bvh;
    try {
        if (!device_) device_ = std::make_shared<embree::Device>();
        bvh = std::make_unique<embree::SceneBvh>(device_, views, nullptr);
    } catch (const Error& e) {
        error = e.what();
    }
    if (ranks_->size() > 1) {
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
    return bvh;
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
