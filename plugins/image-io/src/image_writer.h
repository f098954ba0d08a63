#pragma once
#include <darkroom/filter.h>

#include <string>
#include <utility>
#include <vector>

namespace darkroom {

// Sink node: writes its input to a file, atomically. It has no outputs; the
// runner executes it because it is a sink.
class ImageWriter final : public Filter {
public:
    PortList ports() const override { return {image_, path_, compression_, half_, channels_}; }
    void execute(Context& ctx) override;

private:
    static std::vector<std::pair<std::string, std::string>> compressions() {
        std::vector<std::pair<std::string, std::string>> out;
        for (const char* c : {"none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"})
            out.emplace_back(c, c);
        return out;
    }

    ImageIn image_{"image", "Image to write"};
    OutputPathIn path_{"path", "",
                 "Output file; the extension picks the format (.exr keeps every channel exactly; "
                 ".png, .jpg, .tif are 8-bit sRGB). Relative to --output or the pipeline file"};
    EnumIn<std::string> compression_{"compression", compressions(), "zip",
                                     "EXR compression (pxr24, b44, b44a, dwaa, dwab are lossy); ignored by 8-bit "
                                     "formats"};
    BoolIn half_{"half", false, "EXR: store float channels except depth Z as 16-bit half (lossy)"};
    StringIn channels_{"channels", "",
                       "Channels to write, comma separated. 8-bit: 1 (grey), 2 (grey, alpha), 3 (RGB) or 4 "
                       "(RGBA); empty = R, G, B(, A), else Y(, A), else the one float channel. EXR: a subset; "
                       "empty = all"};
};

}  // namespace darkroom
