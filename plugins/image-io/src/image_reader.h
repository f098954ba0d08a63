#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// Source node: one image file -> a buffer (see darkroom/data/image_io.h for what
// each format becomes).
class ImageReader final : public Filter {
public:
    PortList ports() const override { return {path_, result_}; }
    void execute(Context& ctx) override;

private:
    PathIn path_{"path", "", "Image file to read (PNG, JPEG, TIFF, EXR, ...); relative to the pipeline file"};
    ImageOut result_{"image",
                     "Every EXR channel with its name (float32, uint32 kept), or linear R, G, B(, A) / Y "
                     "decoded from sRGB for 8/16-bit images; the camera travels in the metadata"};
};

}  // namespace darkroom
