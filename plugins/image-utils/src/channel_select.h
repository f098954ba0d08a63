#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// Keeps (optionally renaming) or drops named channels of an image; the planes
// themselves are shared, never copied.
class ChannelSelect final : public Filter {
public:
    enum class Mode { Keep, Drop };

    PortList ports() const override { return {image_, channels_, mode_, result_}; }
    void execute(Context& ctx) override;

private:
    ImageIn image_{"image", "Any image"};
    StringIn channels_{"channels", "R, G, B, A",
                       "Comma-separated channel names; in keep mode SOURCE:NEWNAME renames (e.g. \"value:R\")"};
    EnumIn<Mode> mode_{"mode",
                       {{Mode::Keep, "keep"}, {Mode::Drop, "drop"}},
                       Mode::Keep,
                       "keep: output only the listed channels, in the listed order; drop: output all others, in their "
                       "order"};
    ImageOut result_{"image", "The selected channels with the input's metadata (camera)"};
};

}  // namespace darkroom
