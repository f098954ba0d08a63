#include "capture_origin.h"
#include "capture_over_ranks.h"
#include "commands.h"
#include "processes.h"
#include "progress_bar.h"

#include <darkroom/capture_backend.h>
#include <darkroom/error.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/data/cinema/writer.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/scene/point_list.h>
#include <darkroom/scene/scene_file.h>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <cctype>
#include <chrono>
#include <map>

namespace darkroom::cli {

namespace {

// A point list's object name as a column and file-name part: letters, digits,
// '-' kept, everything else '_' ("maxima", "cloud_points").
std::string pointListColumnName(const std::string& object) {
    std::string s;
    for (char c : object) s += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_';
    return s.empty() ? std::string("points") : s;
}

}  // namespace

void addCaptureCommand(CLI::App& app, GlobalOptions& global, Runner& run) {
    auto* cmd = app.add_subcommand("capture", "Ray trace a scene file's cameras into a Cinema database of G-buffers");
    struct Args {
        std::string scene, output, compression = "zip";
        bool overwrite = false, resume = false, half = false;
        int threads = 0;
    };
    auto a = std::make_shared<Args>();
    cmd->add_option("SCENE", a->scene, "Scene file (YAML): objects, cameras, channels")->required();
    cmd->add_option("-o,--output", a->output, "Database folder to write, e.g. out/demo.cdb")->required()->type_name("DB.cdb");
    auto* ow = cmd->add_flag("--overwrite", a->overwrite, "Replace an existing database");
    cmd->add_flag("--resume", a->resume, "Complete an interrupted capture, keeping the entries already written")
        ->excludes(ow);
    cmd->add_option("--compression", a->compression, "OpenEXR compression of the products")
        ->check(CLI::IsMember({"none", "zip", "zips", "piz", "rle", "pxr24", "b44", "dwaa", "dwab"}));
    cmd->add_flag("--half", a->half, "Store scalar channels as half floats (depth and ids stay exact)");
    cmd->add_option("-j,--threads", a->threads, "Worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
    cmd->callback([&global, &run, a] {
        run = [&global, a] {
            if (processes().size > 1)
                return captureOverRanks(global, {a->scene, a->output, a->compression, a->overwrite, a->resume,
                                                 a->half, a->threads});
            const Registry& registry = loadRegistry(global);
            SceneDescription scene;
            try {
                scene = loadSceneFile(a->scene);
            } catch (const Error& e) {
                reportError(e.what());
                return int(kBadInput);
            }
            for (const auto& w : scene.warnings) std::fprintf(stderr, "darkroom: warning: %s\n", w.c_str());
            if (scene.cameras.empty()) {
                reportError(a->scene + ": the scene has no cameras");
                return int(kBadInput);
            }
            std::unique_ptr<CaptureBackend> backend = registry.createBackend(scene.backend);
            backend->setScene(scene.scene);

            std::vector<std::string> columns;
            for (const auto& [k, v] : scene.cameras.front().parameters) columns.push_back(k);
            CinemaWriterOptions wo;
            wo.overwrite = a->overwrite;
            wo.resume = a->resume;
            wo.image.compression = a->compression;
            wo.image.halfFloat = a->half;
            // Objects kept as point lists: one CSV per entry in FILE_<name>.
            std::map<std::string, std::string> pointLists;
            for (const SceneObject& o : scene.pointLists) {
                const std::string name = pointListColumnName(o.name);
                wo.attachments.push_back({"FILE_" + name, "." + name + ".csv"});
                if (!pointLists.emplace(wo.attachments.back().column, pointListCsv(o)).second) {
                    reportError(a->scene + ": point lists '" + o.name + "' and another both become column FILE_" +
                                name + "; rename one");
                    return int(kBadInput);
                }
            }
            std::unique_ptr<CinemaWriter> writer;
            try {
                // A resume must find the database made from the same scene and options.
                wo.origin = captureOrigin(a->scene, scene, a->compression, a->half);
                writer = std::make_unique<CinemaWriter>(a->output, columns, wo);
            } catch (const Error& e) {
                reportError(e.what());
                return int(kBadInput);
            }

            FilterRunOptions ro;
            ro.threads = a->threads;
            ro.registry = &registry;
            std::unique_ptr<Context> ctx = makeStandaloneContext(ro, "capture");
            ProgressBar bar("capture", showProgress(global));
            const auto start = std::chrono::steady_clock::now();
            std::size_t rendered = 0, skipped = 0;
            for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
                const CameraSample& cam = scene.cameras[i];
                CinemaParameters params;
                std::string label;
                for (const auto& [k, v] : cam.parameters) {
                    params.emplace(k, CinemaValue(v));
                    label += (label.empty() ? "" : " ") + k + "=" + CinemaValue(v).str();
                }
                bar.update(double(i) / double(scene.cameras.size()), label);
                if (writer->hasEntry(params)) {
                    ++skipped;
                    continue;
                }
                const BufferPtr image = backend->render(cam.camera, scene.request, *ctx);
                writer->addEntry(params, *image, pointLists);
                ++rendered;
            }
            writer->finish();
            bar.finish();
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (!global.quiet)
                fmt::print(stderr, "darkroom: wrote {} ({} entries rendered{}, {:.1f} s)\n", a->output, rendered,
                           skipped ? fmt::format(", {} kept from the interrupted capture", skipped) : "", seconds);
            return int(kOk);
        };
    });
}

void addInfoCommand(CLI::App& app, GlobalOptions&, Runner& run) {
    auto* cmd = app.add_subcommand("info", "Describe a Cinema database: rows, columns, channels, image size, camera");
    auto path = std::make_shared<std::string>();
    auto strict = std::make_shared<bool>(false);
    cmd->add_option("DB", *path, "A .cdb folder or its data.csv")->required();
    cmd->add_flag("--strict", *strict, "Treat irregular data.csv rows and cells as errors");
    cmd->callback([&run, path, strict] {
        run = [path, strict] {
            CsvReadOptions o;
            o.strict = *strict;
            try {
                const CinemaDatabase db = CinemaDatabase::open(*path, o);
                const CinemaDescription d = db.describe();
                report(d.warnings);
                fmt::print("{}", formatDescription(d));
                // A product that disagrees with data.csv fails the check, as reading it would.
                if (hasErrors(d.warnings)) return int(kBadInput);
            } catch (const Error& e) {
                reportError(e.what());
                return int(kBadInput);
            }
            return int(kOk);
        };
    });
}

}  // namespace darkroom::cli
