#pragma once
#include <darkroom/filter.h>

#include <memory>
#include <mutex>
#include <set>
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
    enum class Format { Png, Exr, H5 };
    enum class Mode { Create, Overwrite, Resume };
    struct Settings;

    CinemaWriterNode();
    ~CinemaWriterNode() override;
    PortList ports() const override {
        return {image_, row_, database_, format_, channels_, compression_, mode_, pipeline_, writtenOut_};
    }
    void execute(Context& ctx) override;
    // The database is opened (and locked) at the first entry of a sequence
    // and finished (data.csv written a last time, the lock removed) when the
    // sequence ends: a --foreach run writes one database, and between the
    // editor's evaluations nothing is held.
    void endSequence(const SequenceInfo& info, bool completed) override;

private:
    ImageIn image_{"image", "What to store: colour (PNG) or any channels (EXR)"};
    RowIn row_{"row",
                  "The entry's parameters: connect CinemaReader's row (its parameter columns become this "
                  "database's columns; its FILE columns are not copied), or type 'time=0.5, phi=30'"};
    OutputPathIn database_{"database", "",
                     "The database folder to write (name.cdb), relative to the output folder (--output) or the "
                     "pipeline's"};
    EnumIn<Format> format_{"format",
                           {{Format::Png, "png"}, {Format::Exr, "exr"}, {Format::H5, "h5"}},
                           Format::Png,
                           "png: 8-bit sRGB pictures (R, G, B and A when present), for browsing and movies; exr: "
                           "float channels and the camera, for further shading; h5: pycinema's HDF5 images "
                           "(every channel, depth normalised, colour as 8-bit rgba, the camera and the row in meta)"};
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
    ValueOut writtenOut_{"written", PortType::Path,
                      "The database written (absolute path): connect Movie's database to it. In a --foreach run "
                      "a node reading it runs once, after the last entry, on the whole database"};

    // The open database (and its lock), inside a sequence only.
    std::unique_ptr<CinemaWriter> writer_;
    // What the node wrote last, and the product files it wrote there, kept
    // over sequences: the next sequence with the same settings adds to that
    // database (the editor evaluating entry after entry), and an entry this
    // node wrote is replaced even in mode resume (an edit re-evaluated).
    std::unique_ptr<Settings> last_;
    std::set<std::string> written_;
    std::mutex mutex_;
};

}  // namespace darkroom
