#pragma once
// The capture loop: cameras ray traced into a Cinema database, by one
// process or by several that each hold a part of the scene. The one loop
// behind `darkroom capture` (alone and under mpirun) and the in situ API
// (docs/architecture.md, "Workflows"), so what one writes the others write:
// the same rows, products and attachments (point lists), the same resume.
//
// Over several processes every one renders its part for every camera, the
// G-buffers are composited by depth (ProcessGroup::compositeByDepth) and
// the lead alone opens, locks and writes the database. Errors are agreed: a
// failure on any process (a render, the lead's write) ends the loop on all
// of them with the same darkroom::Error, so none waits in a collective.
#include <darkroom/camera.h>
#include <darkroom/capture_backend.h>
#include <darkroom/export.h>
#include <darkroom/core/process_group.h>
#include <darkroom/data/cinema/writer.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace darkroom {

class Registry;
struct SceneDescription;

namespace workflows {

// One row of the database: its parameters and the camera that renders it.
struct CaptureEntry {
    CinemaParameters parameters;
    Camera camera;
    std::string label;  // "phi=30 theta=45", for progress
};

// Renders this process's part of the scene for one camera (Embree through
// a CaptureBackend, or the in situ API's shared arrays).
using RenderFn = std::function<BufferPtr(const Camera&, const CaptureRequest&)>;

struct CaptureSettings {
    // The channels the database stores.
    CaptureRequest request;
    // Over several processes: per object, the whole object's id of this
    // part's first primitive (PartitionedScene::primitiveOffset).
    std::vector<std::uint64_t> primitiveOffsets;
    // The files stored beside each entry (column -> contents), the same for
    // every entry: the scene's point lists (pointListAttachments).
    std::map<std::string, std::string> attachments;
    // Called on the lead alone, before the first entry: the database to
    // write, opened (and locked) in the caller's mode. It may throw
    // darkroom::Error to refuse; the loop then throws InputError with the
    // message on every process.
    std::function<CinemaWriter&()> openDatabase;
    // Called on every process once the entries to render are agreed (a
    // resume leaves out those the database holds).
    std::function<void()> entriesAgreed;
    // Progress on the lead: the fraction done and the entry's label.
    std::function<void(double, const std::string&)> progress;
    // Set from any thread to stop before the next entry: every process then
    // throws Cancelled, and the database holds the entries written so far
    // (a resume completes it).
    const std::atomic<bool>* cancel = nullptr;
};

struct CaptureSummary {
    std::size_t rendered = 0;  // entries rendered now
    std::size_t kept = 0;      // entries a resume kept
    double renderSeconds = 0;     // the slowest process's ray tracing
    double compositeSeconds = 0;  // the slowest process's compositing (several processes)
    double writeSeconds = 0;      // the lead's writing
    // Where the time before the first ray went (`darkroom capture --profile`),
    // on this process, from the start of captureSceneFile; 0 for a time series.
    double sceneSeconds = 0;     // reading the scene file and its meshes
    double setupSeconds = 0;     // the backend's setScene (Embree's BVH build)
    double firstRaySeconds = 0;  // until the first render began
    // A time series whose steps the ranks shared (docs/scene-format.md,
    // "Time series"): per rank, the labels of the steps it captured whole
    // ("time=0, time=3"); empty when every process took part in every step.
    std::vector<std::string> stepsPerRank;
};

// Renders every entry the database lacks and adds it. The caller finishes
// the database (CinemaWriter::finish) when it has no more to add. Throws
// InputError when the database is refused, darkroom::Error when an entry
// fails, Cancelled when `cancel` was set; the same on every process.
DARKROOM_API CaptureSummary captureEntries(const std::vector<CaptureEntry>& entries, const RenderFn& render,
                                           ProcessGroup& group, const CaptureSettings& settings);

// The entries of a scene file's cameras, in the scene's order.
DARKROOM_API std::vector<CaptureEntry> captureEntriesOf(const SceneDescription& scene);

// The point lists of a scene (objects with `store: pointList`) as attachment
// columns FILE_<name> with files "<entry>.<name>.csv", added to `options`,
// and their contents. Throws InputError when two lists get one column name.
DARKROOM_API std::map<std::string, std::string> pointListAttachments(const SceneDescription& scene,
                                                                     CinemaWriterOptions& options);

// What `darkroom capture SCENE -o DB` is asked for.
struct SceneCapture {
    std::string scene;   // the scene file
    std::string output;  // the database folder
    std::string compression = "zip";
    bool overwrite = false, resume = false, half = false;
    int threads = 0;  // 0: all cores (shared among the processes on a machine)
    std::function<void(double, const std::string&)> progress;  // on the lead
    std::function<void(const std::string&)> warn;               // every process: its own warnings
    const std::atomic<bool>* cancel = nullptr;
};

// A scene file's cameras captured into a database: the scene loaded whole,
// or over several processes each holding its part (scene_partition.h); the
// backend the scene names, from `registry`; the database recording what it
// was made from (capture_origin.h), with the scene's point lists beside each
// entry; then captureEntries, and the database finished. Throws InputError
// for a bad scene or a refused database, darkroom::Error when an entry fails,
// Cancelled; the same on every process.
DARKROOM_API CaptureSummary captureSceneFile(const SceneCapture& request, const Registry& registry,
                                             ProcessGroup& group);

}  // namespace workflows
}  // namespace darkroom
