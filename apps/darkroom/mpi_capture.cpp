// Distributed capture: every rank ray traces its part of the scene, the
// G-buffers are composited by depth, rank 0 writes. See capture_over_ranks.h.
#include "capture_origin.h"
#include "capture_over_ranks.h"
#include "processes.h"
#include "progress_bar.h"

#include <darkroom/capture_backend.h>
#include <darkroom/error.h>
#include <darkroom/data/cinema/writer.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/scene/scene_partition.h>
#include <darkroom/mpi/distributed_capture.h>
#include <darkroom/mpi/mpi_process_group.h>

#include <fmt/core.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace darkroom::cli {

int captureOverRanks(const GlobalOptions& global, const CaptureSettings& settings) {
    const mpi::Communicator comm(MPI_COMM_WORLD);
    const bool root = comm.rank() == 0;
    auto fail = [&](const std::string& message, int code) {
        if (root) reportError(message);
        return code;
    };
    const Registry& registry = loadRegistry(global);

    // The scene: each rank loads its part; errors are the same on every rank.
    mpi::MpiProcessGroup group(comm);
    PartitionedScene part;
    try {
        part = loadSceneFilePart(settings.scene, group);
    } catch (const Error& e) {
        return fail(e.what(), kBadInput);
    }
    const SceneDescription& scene = part.description;
    // Warnings about pieces differ between ranks: each rank says its own.
    for (const auto& w : scene.warnings) std::fprintf(stderr, "darkroom: rank %d: warning: %s\n", comm.rank(), w.c_str());
    if (scene.cameras.empty()) return fail(settings.scene + ": the scene has no cameras", kBadInput);

    std::string error;
    std::unique_ptr<CaptureBackend> backend;
    try {
        backend = registry.createBackend(scene.backend);
        backend->setScene(scene.scene);
    } catch (const Error& e) {
        error = e.what();
    }
    if (const std::string e = mpi::agreedError(comm, error); !e.empty()) return fail(e, kBadInput);

    // Rank 0 alone opens (and locks) the database and decides what a resume keeps.
    std::vector<std::string> columns;
    for (const auto& [k, v] : scene.cameras.front().parameters) columns.push_back(k);
    std::unique_ptr<CinemaWriter> writer;
    std::string todo;  // camera indices to render, separated by spaces
    if (root) {
        try {
            CinemaWriterOptions wo;
            wo.overwrite = settings.overwrite;
            wo.resume = settings.resume;
            wo.image.compression = settings.compression;
            wo.image.halfFloat = settings.half;
            wo.origin = captureOrigin(settings.scene, scene, settings.compression, settings.half);
            writer = std::make_unique<CinemaWriter>(settings.output, columns, wo);
            for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
                CinemaParameters params;
                for (const auto& [k, v] : scene.cameras[i].parameters) params.emplace(k, CinemaValue(v));
                if (!writer->hasEntry(params)) todo += std::to_string(i) + " ";
            }
        } catch (const Error& e) {
            error = e.what();
        }
    }
    if (const std::string e = mpi::agreedError(comm, error); !e.empty()) return fail(e, kBadInput);
    comm.broadcast(todo);
    std::vector<std::size_t> cameras;
    {
        std::istringstream in(todo);
        for (std::size_t i; in >> i;) cameras.push_back(i);
    }

    // Both ids are rendered even when not asked for: primitive ids are made
    // global through the object of each hit, and at equal depth the lower
    // (objectId, primitiveId) wins, in the compositing as inside Embree
    // (capture-embree's nearest_hit_rule.h), so any partition gives the
    // single-process result. They cost 8 bytes a pixel in the exchanges and
    // are dropped before writing when the scene did not ask for them.
    CaptureRequest request = scene.request;
    const bool dropObjectId = !request.objectId, dropPrimitiveId = !request.primitiveId;
    request.objectId = request.primitiveId = true;

    FilterRunOptions ro;
    ro.threads = settings.threads ? settings.threads : defaultThreads();
    ro.registry = &registry;
    std::unique_ptr<Context> ctx = makeStandaloneContext(ro, "capture");
    ProgressBar bar("capture", showProgress(global));
    const double start = MPI_Wtime();
    double traceSeconds = 0, writeSeconds = 0;
    mpi::CompositeStats stats;
    for (std::size_t k = 0; k < cameras.size(); ++k) {
        const CameraSample& cam = scene.cameras[cameras[k]];
        bar.update(double(k) / double(cameras.size()));
        double t = MPI_Wtime();
        BufferPtr local;
        try {
            local = backend->render(cam.camera, request, *ctx);
        } catch (const Error& e) {
            error = e.what();
        }
        traceSeconds += MPI_Wtime() - t;
        // A failure on any rank (this render, or rank 0's last write) stops all.
        if (const std::string e = mpi::agreedError(comm, error); !e.empty()) {
            bar.finish();
            return fail(e, kRuntimeFailure);
        }
        const auto image =
            mpi::compositeCapture(comm, *local, part.primitiveOffset, !dropObjectId, !dropPrimitiveId, &stats);
        if (!image) continue;
        t = MPI_Wtime();
        try {
            CinemaParameters params;
            for (const auto& [name, v] : cam.parameters) params.emplace(name, CinemaValue(v));
            writer->addEntry(params, *image);
        } catch (const Error& e) {
            error = e.what();
        }
        writeSeconds += MPI_Wtime() - t;
    }
    if (const std::string e = mpi::agreedError(comm, error); !e.empty()) {
        bar.finish();
        return fail(e, kRuntimeFailure);
    }
    bar.finish();
    // The slowest rank's times are the ones that bound the run.
    double mine[2] = {traceSeconds, stats.exchangeSeconds + stats.mergeSeconds + stats.gatherSeconds}, slowest[2];
    MPI_Reduce(mine, slowest, 2, MPI_DOUBLE, MPI_MAX, 0, comm.handle());
    if (root) {
        writer->finish();
        if (!global.quiet)
            fmt::print(stderr,
                       "darkroom: wrote {} ({} entries rendered over {} ranks{}, {:.1f} s: ray tracing {:.2f} s, "
                       "compositing {:.2f} s (slowest rank), writing {:.2f} s)\n",
                       settings.output, cameras.size(), comm.size(),
                       writer->resumedCount() ? fmt::format(", {} kept from the interrupted capture", writer->resumedCount())
                                              : "",
                       MPI_Wtime() - start, slowest[0], slowest[1], writeSeconds);
    }
    return kOk;
}

}  // namespace darkroom::cli
