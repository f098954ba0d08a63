// What a scene file gives the capture loop: its cameras as entries and its
// point lists as attachments.
#include <darkroom/workflows/capture.h>

#include <darkroom/error.h>
#include <darkroom/data/formats/point_list.h>
#include <darkroom/scene/scene_file.h>

#include <cctype>

namespace darkroom::workflows {

namespace {

// A point list's object name as a column and file-name part: letters, digits,
// '-' kept, everything else '_' ("maxima", "cloud_points").
std::string pointListColumnName(const std::string& object) {
    std::string s;
    for (char c : object) s += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_';
    return s.empty() ? std::string("points") : s;
}

}  // namespace

std::vector<CaptureEntry> captureEntriesOf(const SceneDescription& scene) {
    std::vector<CaptureEntry> out;
    out.reserve(scene.cameras.size());
    for (const CameraSample& cam : scene.cameras) {
        CaptureEntry e;
        e.camera = cam.camera;
        for (const auto& [k, v] : cam.parameters) {
            e.parameters.emplace(k, CinemaValue(v));
            e.label += (e.label.empty() ? "" : " ") + k + "=" + CinemaValue(v).str();
        }
        out.push_back(std::move(e));
    }
    return out;
}

std::map<std::string, std::string> pointListAttachments(const SceneDescription& scene, CinemaWriterOptions& options) {
    std::map<std::string, std::string> contents;
    for (const SceneObject& o : scene.pointLists) {
        const std::string name = pointListColumnName(o.name);
        options.attachments.push_back({"FILE_" + name, "." + name + ".csv"});
        if (!contents.emplace(options.attachments.back().column, pointListCsv(o)).second)
            throw InputError(scene.path + ": point lists '" + o.name + "' and another both become column FILE_" +
                             name + "; rename one");
    }
    return contents;
}

}  // namespace darkroom::workflows
