#pragma once
// Writing a Cinema Spec D database: `name.cdb/data.csv` with the sampling
// parameters as columns followed by FILE, and one multi-channel OpenEXR per
// entry (every channel of the buffer, camera in the header).
//
// Safety: every product and every version of data.csv is written atomically
// (temporary file, fsync, rename, fsync of the folder), a product before the
// row that names it, so a process killed at any moment leaves a valid
// database; a write that fails throws before the row is added. Rows are kept sorted
// by their parameter values, so the final data.csv does not depend on the
// order entries were added in or on how often the capture was interrupted.
#include <darkroom/buffer.h>
#include <darkroom/export.h>
#include <darkroom/data/image_io.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace darkroom {

// A data.csv cell the writer is given: a number (the usual case) or text.
class DARKROOM_API CinemaValue {
public:
    CinemaValue(double v) : number_(v), isNumber_(true) {}
    CinemaValue(int v) : number_(v), isNumber_(true) {}
    CinemaValue(std::string text) : text_(std::move(text)) {}
    CinemaValue(const char* text) : text_(text) {}

    bool isNumber() const { return isNumber_; }
    double number() const { return number_; }
    const std::string& text() const { return text_; }
    // As written in data.csv and file names: shortest round-trip number or the text.
    std::string str() const;

private:
    double number_ = 0;
    std::string text_;
    bool isNumber_ = false;
};

// Column name -> value; must name exactly the writer's columns.
using CinemaParameters = std::map<std::string, CinemaValue>;

// A further FILE column whose file is given as bytes with each entry, written
// beside the product (e.g. the point list a capture keeps of objects it does
// not ray trace): column "FILE_maxima", file "<entry><suffix>".
struct CinemaAttachmentColumn {
    std::string column;  // a FILE column name other than "FILE": "FILE_<name>"
    std::string suffix;  // appended to the entry's name: ".maxima.csv"
};

// A finished product (and its attachments) written elsewhere, e.g. into a
// staging database on the same file system, for adoptEntries to move in.
struct CinemaStagedEntry {
    CinemaParameters parameters;
    std::string product;                             // path of the product file
    std::map<std::string, std::string> attachments;  // attachment column -> path of its file
};

// One fact about what a database is made from (the scene file's content, the
// resolution, a capture option), recorded in the folder's marker file
// (.darkroom-database) so that a resume can refuse a database made from
// something else, naming what changed.
struct CinemaOriginItem {
    std::string source;    // what it belongs to, in messages: "the scene file", "the capture options"
    std::string key;       // "resolution"
    std::string value;     // "64x64"
    bool summary = false;  // compared, but named only when nothing else of its source differs (a content hash)
};

struct CinemaWriterOptions {
    // Remove an existing database Darkroom created (its folder holds the
    // marker file .darkroom-database): the files its data.csv lists, data.csv,
    // the marker and leftovers of interrupted writes, nothing else; and start
    // afresh. A folder without the marker is refused untouched.
    bool overwrite = false;
    // Keep the entries of an existing database whose products exist, drop
    // the rest and the leftovers of an interrupted write; addEntry then
    // completes it. Its columns, product format and recorded origin must
    // match; a folder without the marker is refused.
    bool resume = false;
    ImageWriteOptions image;  // compression etc. of the products
    // ".exr" (every channel, camera in the header), an 8-bit format OIIO
    // writes (".png": linear colour sRGB-encoded, see writeImage), or ".h5":
    // pycinema's HDF5 layout, the entry's parameters in its meta group
    // (docs/formats.md, "pycinema's HDF5 images").
    std::string productExtension = ".exr";
    // Columns after FILE, each with a file per entry (addEntry's attachments).
    std::vector<CinemaAttachmentColumn> attachments;
    // What this database is made from; recorded in the marker, compared by a resume.
    std::vector<CinemaOriginItem> origin;
    // How the user asks for overwrite and resume, as a refusal advises them
    // ("use --overwrite to replace it"): the command line's options of
    // `darkroom capture` unless the caller says otherwise (adviseNodeMode).
    std::string overwriteAdvice = "--overwrite";
    std::string resumeAdvice = "--resume";
};

// Sets the advice for a node whose `mode` parameter chooses between create,
// overwrite and resume (the CinemaWriter node): `darkroom run` has no
// --overwrite, so a refusal names the parameter and the --set that sets it
// ("mode: overwrite (--set write.mode=overwrite)").
DARKROOM_API void adviseNodeMode(CinemaWriterOptions& options, const std::string& node);

class DARKROOM_API CinemaWriter {
public:
    // Creates (or, with overwrite/resume, reopens) the database folder and
    // locks it (flock on `<path>/.lock`, held until finish() or destruction).
    // Throws darkroom::Error when the folder exists and is not empty without
    // overwrite/resume ("use --overwrite ... or --resume ...", in the words of
    // options.overwriteAdvice and resumeAdvice), when another process
    // holds the lock ("being written by another process (pid N)"), or when
    // the column names are unusable.
    CinemaWriter(std::string path, std::vector<std::string> columnNames,
                 CinemaWriterOptions options = {});
    ~CinemaWriter();
    CinemaWriter(const CinemaWriter&) = delete;
    CinemaWriter& operator=(const CinemaWriter&) = delete;

    // Throws what the constructor would throw for the folder `path` with these
    // options (a file of that name, an existing non-empty folder without
    // overwrite/resume, overwrite of a folder that is no database, resume of
    // one whose data.csv cannot be read, another process's lock), without
    // creating or changing anything there. The columns are not known here: a
    // resume into other columns is refused by the constructor; the origin is
    // compared here only when options.origin is given.
    static void check(std::string path, const CinemaWriterOptions& options);

    // The origin given to the writer of the database at `path`, as its marker
    // records it (without the writer's own items; empty when it has none),
    // e.g. to carry it from a staging database to the final one.
    static std::vector<CinemaOriginItem> recordedOrigin(const std::string& path);

    const std::string& path() const;
    const std::vector<std::string>& columns() const;

    // True when the entry is already in the database (kept by a resume or
    // added earlier); a resumed capture skips it.
    bool hasEntry(const CinemaParameters& parameters) const;
    // Writes the product (replacing an earlier one with the same parameters),
    // then each attachment, then data.csv. Thread-safe. Throws darkroom::Error
    // naming the parameters when they do not match the columns, or when
    // `attachments` (column -> file contents) does not give exactly the
    // attachment columns.
    void addEntry(const CinemaParameters& parameters, const Buffer& image,
                  const std::map<std::string, std::string>& attachments = {});

    // Moves finished files into the database as entries: each product (then
    // its attachments) is renamed into place under the entry's file name
    // (copied and renamed when it lies on another file system), replacing an
    // entry with the same parameters, and data.csv is written once at the end
    // (an interrupted adoption leaves products no row names, as addEntry
    // can). Every entry is checked as addEntry checks it, and every file for
    // existence, before the first file moves. Thread-safe.
    void adoptEntries(const std::vector<CinemaStagedEntry>& entries);

    // Entries in the database now, and how many of them a resume kept.
    std::size_t entryCount() const;
    std::size_t resumedCount() const;
    // Product file name of an entry, relative to the folder ("phi=30_theta=45.exr").
    std::string entryFileName(const CinemaParameters& parameters) const;

    // Writes data.csv a last time and releases and removes the lock file.
    // Further addEntry calls throw. A writer destroyed without finish() (an
    // error) also removes its lock file.
    void finish();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace darkroom
