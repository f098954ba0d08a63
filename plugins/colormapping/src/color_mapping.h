#pragma once
#include <darkroom/filter.h>

#include <vector>

namespace darkroom {

namespace colormapping {
struct LayerValues;
}

// Scalar channel -> linear RGBA through a colour map (the paper's
// ColorMapping pass). Depth Z passes through; background (Z = +inf, or NaN
// in an image without Z) becomes transparent.
class ColorMapping final : public Filter {
public:
    enum class Range { Automatic, Manual, Database };
    enum class Scale { Linear, Log };
    enum class Layers { Composite, Keep };

    PortList ports() const override {
        return {image_,    channel_,        colormap_, range_,  minimum_,     maximum_,     symmetric_, clip_, scale_,
                nanColor_, useMapNanColor_, opacity_,  objectOpacity_, layers_, result_, usedMinimum_,
                usedMaximum_, usedScale_, usedColormap_};
    }
    void execute(Context& ctx) override;

private:
    // The range mapped, [low, high] (NaN when there is none), from the
    // settings and the data; `constant` when it was narrower than the float
    // resolution of its values and became one value.
    struct ChosenRange {
        double low, high;
        bool constant = false;
    };
    // `values`: per layer, the scalar and the depth marking where it counts
    // for an automatic range (one entry for an image of one layer).
    ChosenRange chooseRange(Context& ctx, const Buffer& in, const std::string& channel,
                            const std::vector<colormapping::LayerValues>& values) const;
    // The colour map asked for, else the one stored for the channel, else viridis.
    std::string chooseColorMap(Context& ctx, const Buffer& in, const std::string& channel) const;

    static constexpr double kBig = 1e30;  // no practical limit on data values

    ImageIn image_{"image", "Image holding the scalar channel (and optionally depth Z)"};
    StringIn channel_{"channel", "",
                      "Scalar channel to map (float32 or uint32); empty = the first float32 channel "
                      "other than Z and A"};
    ColorMapIn colormap_{"colormap", "",
                         "Preset name or a ParaView colour-map JSON file (relative to the pipeline file); empty: "
                         "the map the database stores for the channel (a composable image set's "
                         "CISChannelColormap), else viridis"};
    EnumIn<Range> range_{"range",
                         {{Range::Automatic, "automatic"}, {Range::Manual, "manual"}, {Range::Database, "database"}},
                         Range::Automatic,
                         "automatic: the finite minimum and maximum of the channel over non-background pixels; "
                         "manual: minimum and maximum below; database: over every entry of the Cinema database "
                         "the image was read from (its CISChannelVarMin/Max, else one scan, cached), or of the "
                         "reader's selection (a --foreach --where run), so that all its entries share one scale"};
    FloatIn minimum_{"minimum", 0.0, -kBig, kBig, "Value mapped to the start of the map (manual range)"};
    FloatIn maximum_{"maximum", 1.0, -kBig, kBig,
                     "Value mapped to the end of the map (manual range); below minimum flips the map"};
    BoolIn symmetric_{"symmetric", false,
                      "Widen the automatic or database range to be symmetric about zero, [-m, m] with m the "
                      "larger magnitude (a diverging map's centre at 0)"};
    FloatIn clip_{"clip", 0.0, 0.0, 49.0,
                  "Percent of values left out at each end of the automatic or database range (1: the 1st to "
                  "99th percentile), so that a few outliers do not take the whole map"};
    EnumIn<Scale> scale_{"scale",
                         {{Scale::Linear, "linear"}, {Scale::Log, "log"}},
                         Scale::Linear,
                         "linear: t = (v - min) / (max - min); log: t = (log10 v - log10 min) / (log10 max - log10 min) "
                         "(ParaView's log scale): the automatic range then spans the positive values only, a manual "
                         "range must be positive, and values <= 0 take the start of the map"};
    ColorIn nanColor_{"nanColor", Color{1.0f, 1.0f, 0.0f, 1.0f},
                      "Linear colour for NaN values on geometry; in an image without Z, NaN pixels are the "
                      "background (as in ParaView's float images) and are transparent"};
    BoolIn useMapNanColor_{"useMapNanColor", false,
                           "Use the colour map's own NaN colour when it defines one (ParaView JSON NanColor, "
                           "cool-to-warm, blackbody) instead of nanColor"};
    FloatIn opacity_{"opacity", 1.0, 0.0, 1.0,
                     "Alpha of mapped pixels (NaN pixels take nanColor's alpha); below 1 on a layered image, the "
                     "layers behind show through"};
    StringIn objectOpacity_{"objectOpacity", "",
                            "Opacity per object, 'id: opacity' pairs such as \"0: 0.3, 2: 1\" (objects not listed: "
                            "1), multiplying opacity; needs the objectId channel"};
    EnumIn<Layers> layers_{"layers",
                           {{Layers::Composite, "composite"}, {Layers::Keep, "keep"}},
                           Layers::Composite,
                           "For a layered image: composite: blend the layers front to back into one image; keep: "
                           "output every layer's colour (R, G, B, A, Z, then layer1.R ...) so that Compositing can "
                           "merge layers of several databases by depth"};
    ImageOut result_{"image",
                     "Linear R, G, B, A (straight alpha) plus the input's Z; pixels whose Z is +inf are "
                     "transparent black; of a layered image, the layers' front-to-back blend (Z: the nearest "
                     "surface that shows), or every layer with layers: keep",
                     {"R", "G", "B", "A"}};
    ValueOut usedMinimum_{"usedMinimum", PortType::Float, "Value mapped to the start of the map (NaN if none)"};
    ValueOut usedMaximum_{"usedMaximum", PortType::Float, "Value mapped to the end of the map (NaN if none)"};
    ValueOut usedScale_{"usedScale", PortType::Enum, "The scale used (linear or log), for a colour legend"};
    ValueOut usedColormap_{"usedColormap", PortType::ColorMap,
                           "The colour map used (preset name or resolved JSON path), for a colour legend"};
};

}  // namespace darkroom
