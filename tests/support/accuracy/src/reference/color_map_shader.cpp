// The per-sample equivalent of ColorMapping followed by Background.
#include <darkroom/error.h>
#include <darkroom/accuracy/reference.h>

#include <cmath>
#include <memory>

namespace darkroom::reference {

SampleShader colorMapShader(std::string field, ColorMapData colorMap, double lo, double hi, Color background) {
    if (!std::isfinite(lo) || !std::isfinite(hi) || lo == hi)
        throw Error("reference colour-map shader: the range [" + std::to_string(lo) + ", " + std::to_string(hi) +
                    "] must be finite and not empty");
    auto map = std::make_shared<const ColorMapData>(std::move(colorMap));
    return [field = std::move(field), map, lo, hi, background](const Buffer& samples, std::size_t i, float rgba[4]) {
        const float z = samples.requireFloat("Z")[i];
        if (std::isinf(z) && z > 0) {
            rgba[0] = background.r, rgba[1] = background.g, rgba[2] = background.b, rgba[3] = 1.0f;
            return;
        }
        const float v = samples.requireFloat(field)[i];
        // ColorMapping maps (v - lo) / (hi - lo) clamped to [0, 1]; a flipped
        // range (hi < lo) flips the map the same way.
        const Color c = std::isnan(v) ? map->nanColor : map->sample((double(v) - lo) / (hi - lo));
        rgba[0] = c.r, rgba[1] = c.g, rgba[2] = c.b, rgba[3] = 1.0f;
    };
}

}  // namespace darkroom::reference
