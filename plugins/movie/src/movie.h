#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// An MP4 (H.264) of the pictures of a Cinema database, one frame per entry in
// the entries' sorted order: the movie of a `darkroom run --foreach` that
// wrote its frames with CinemaWriter.
class Movie final : public Filter {
public:
    PortList ports() const override {
        return {database_, file_, where_, orderBy_, path_, frameRate_, quality_, preset_, background_};
    }
    void execute(Context& ctx) override;

private:
    PathIn database_{"database", "",
                     "The Cinema database of pictures (a CinemaWriter's output, or any Spec D database with image "
                     "products). A relative path is looked for in the output folder (--output) first, where this "
                     "run's CinemaWriter writes, then next to the pipeline"};
    StringIn file_{"file", "", "FILE column of the frames; empty = the first FILE column"};
    StringIn where_{"where", "",
                    "Which entries: 'phi=30' (other columns any value) or SQL 'phi = 30 AND time > 1'; empty = all"};
    StringIn orderBy_{"orderBy", "",
                      "Columns that order the frames, comma separated, e.g. 'time'; numbers ascending, text in "
                      "byte order; empty = every parameter column, left to right"};
    OutputPathIn path_{"path", "movie.mp4", "The MP4 file to write (relative to --output or the pipeline's folder)"};
    FloatIn frameRate_{"frameRate", 24.0, 0.1, 240.0, "Frames per second"};
    IntIn quality_{"quality", 18, 0, 51,
                   "x264 constant rate factor: lower is better and larger; 18 looks lossless, 23 is x264's default"};
    EnumIn<std::string> preset_{"preset",
                                {{"ultrafast", "ultrafast"}, {"superfast", "superfast"}, {"veryfast", "veryfast"},
                                 {"faster", "faster"}, {"fast", "fast"}, {"medium", "medium"}, {"slow", "slow"},
                                 {"slower", "slower"}, {"veryslow", "veryslow"}},
                                "medium",
                                "x264 preset: slower presets give smaller files at the same quality"};
    ColorIn background_{"background", Color{0.0f, 0.0f, 0.0f, 1.0f},
                        "Linear colour under transparent pixels (video has no alpha)"};
};

}  // namespace darkroom
