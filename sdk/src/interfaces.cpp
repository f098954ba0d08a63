// Key functions of the SDK's abstract interfaces, so their vtables and
// type_info are emitted once, in the SDK library.
#include <darkroom/capture_backend.h>
#include <darkroom/colormap.h>
#include <darkroom/context.h>
#include <darkroom/error.h>
#include <darkroom/filter.h>
#include <darkroom/registrar.h>

#include <filesystem>

namespace darkroom {

Filter::~Filter() = default;
CaptureBackend::~CaptureBackend() = default;

BufferPtr CaptureBackend::trace(const RayBatch&, const CaptureRequest&, Context&) {
    throw Error("this capture backend cannot trace arbitrary rays (CaptureBackend::trace), so it cannot "
                "compute ray-traced references; use the 'embree' backend");
}

void CaptureBackend::occluded(const RayBatch&, std::vector<std::uint8_t>&, Context&) {
    throw Error("this capture backend cannot answer occlusion queries (CaptureBackend::occluded), so it "
                "cannot compute ray-traced references; use the 'embree' backend");
}
Registrar::~Registrar() = default;
Context::~Context() = default;

BufferPtr Context::requireImage(std::string_view port) const {
    BufferPtr b = image(port);
    // The host names the node when it reports the error.
    if (!b) throw Error("input '" + std::string(port) + "' is not connected");
    return b;
}

std::string Context::get(const ColorMapIn& p) const {
    const std::string& spec = getString(p.name());
    return spec.empty() || isColorMapPreset(spec) ? spec : resolveInputPath(spec);
}

std::string Context::get(const PathIn& p) const {
    const std::string& path = getString(p.name());
    return path.empty() ? path : resolveInputPath(path);
}

std::string Context::get(const OutputPathIn& p) const {
    const std::string& path = getString(p.name());
    if (path.empty()) throw Error("'" + p.name() + "' is empty; set the file or folder to write");
    return std::filesystem::path(resolveOutputPath(path)).lexically_normal().string();
}

void Filter::beginSequence(const SequenceInfo&) {}
void Filter::endSequence(const SequenceInfo&, bool) {}

}  // namespace darkroom
