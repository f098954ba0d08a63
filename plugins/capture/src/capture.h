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
class Capture final : public Filter {
public:
    Capture();
    ~Capture() override;
    PortList ports() const override {
        return {scene_, backend_, camera_, width_, height_, scalars_, normals_, ids_, result_};
    }
    void execute(Context& ctx) override;

private:
    struct Cache;
    std::unique_ptr<Cache> cache_;

    PathIn scene_{"scene", "", "Scene file (YAML) naming the objects, cameras and channels to capture"};
    StringIn backend_{"backend", "embree", "Capture backend type, e.g. \"embree\""};
    IntIn camera_{"camera", 0, 0, 1 << 30, "Index of the scene file's camera to render (in the order the file lists them)"};
    IntIn width_{"width", 0, 0, 1 << 15, "Image width in pixels; 0 keeps the scene file's"};
    IntIn height_{"height", 0, 0, 1 << 15, "Image height in pixels; 0 keeps the scene file's"};
    StringIn scalars_{"scalars", "", "Comma-separated scalar fields to render; empty keeps the scene file's list"};
    BoolIn normals_{"normals", false, "Also render normals (N.x, N.y, N.z), in addition to what the scene file asks for; smooth unless "
                         "the file says normals: geometric"};
    BoolIn ids_{"ids", false, "Also render objectId and primitiveId, in addition to what the scene file asks for"};
    ImageOut result_{"image",
                     "The G-buffer: Z (planar depth, +inf on background), scalars, optional normals and ids; "
                     "the camera travels in its metadata"};
};

}  // namespace darkroom
