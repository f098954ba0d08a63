#pragma once
#include <darkroom/filter.h>

#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace darkroom {

class CinemaWriter;

// A sink that writes its input as one entry of a Cinema Spec D database, the
// entry's columns copied from the CinemaReader row being shaded: a
// `darkroom run --foreach` of a pipeline ending here turns a database into a
// new one, entry by entry.
class CinemaWriterNode final : public Filter {
public:
    enum class Format { Png, Exr };
    enum class Mode { Create, Overwrite, Resume };

    CinemaWriterNode();
    ~CinemaWriterNode() override;
    PortList ports() const override {
        return {image_, row_, database_, format_, channels_, compression_, mode_, pipeline_};
    }
    void execute(Context& ctx) override;

private:
    ImageIn image_{"image", "What to store: colour (PNG) or any channels (EXR)"};
    StringIn row_{"row", "",
                  "The entry's parameters: connect CinemaReader's row (its parameter columns become this "
                  "database's columns; its FILE columns are not copied), or type 'time=0.5, phi=30'"};
    PathIn database_{"database", "",
                     "The database folder to write (name.cdb), relative to the output folder (--output) or the "
                     "pipeline's"};
    EnumIn<Format> format_{"format",
                           {{Format::Png, "png"}, {Format::Exr, "exr"}},
                           Format::Png,
                           "png: 8-bit sRGB pictures (R, G, B and A when present), for browsing and movies; exr: "
                           "float channels and the camera, for further shading"};
    StringIn channels_{"channels", "",
                       "Channels to store, comma separated: PNG 1-4 float channels (default R, G, B(, A)); EXR "
                       "default all"};
    EnumIn<std::string> compression_{"compression",
                                     {{"zip", "zip"}, {"none", "none"}, {"zips", "zips"}, {"piz", "piz"},
                                      {"rle", "rle"}, {"pxr24", "pxr24"}, {"b44", "b44"}, {"dwaa", "dwaa"},
                                      {"dwab", "dwab"}},
                                     "zip",
                                     "EXR compression (pxr24, b44, dwaa, dwab are lossy)"};
    EnumIn<Mode> mode_{"mode",
                       {{Mode::Create, "create"}, {Mode::Overwrite, "overwrite"}, {Mode::Resume, "resume"}},
                       Mode::Create,
                       "create: refuse a database that exists and is not empty; overwrite: replace it; resume: "
                       "keep its complete entries (those are not written again) and add the others"};
    StringIn pipeline_{"pipeline", "",
                       "What produced the images, recorded in the database so that a resume refuses a database "
                       "another pipeline wrote: one line per node upstream, 'node<TAB>digest'. darkroom run sets "
                       "it (docs/publishing.md); empty: nothing recorded"};

    // The open database, kept (and locked) from the first entry of a run to
    // the node's end, so a --foreach run writes one database.
    struct Open;
    std::unique_ptr<Open> open_;
    std::mutex mutex_;
};

}  // namespace darkroom
