#pragma once
#include <darkroom/capture_backend.h>
#include <darkroom/filter.h>

#include <filesystem>
#include <memory>
#include <string>

namespace darkroom {

struct SceneDescription;

// `Capture`: renders one camera of a scene file through a capture backend.
// The loaded scene and the backend with its built acceleration structure are
// cached per (scene file, modification time, backend) inside the instance, so
// moving through the cameras or changing the resolution re-renders without
// re-reading meshes or rebuilding the BVH.
class CaptureFilter final : public Filter {
public:
    CaptureFilter();
    ~CaptureFilter() override;
    PortList ports() const override;
    void execute(Context& ctx) override;

private:
    struct Cache;
    std::unique_ptr<Cache> cache_;
};

}  // namespace darkroom
