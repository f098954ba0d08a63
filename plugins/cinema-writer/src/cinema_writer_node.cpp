#include "cinema_writer_node.h"

#include <darkroom/error.h>
#include <darkroom/strings.h>
#include <darkroom/data/cinema/row.h>
#include <darkroom/data/cinema/csv.h>
#include <darkroom/data/cinema/pipeline_origin.h>
#include <darkroom/data/cinema/writer.h>

#include <filesystem>
#include <set>

namespace darkroom {

// What a database is written with; another value of any of them (the
// columns aside, which must match) starts another database.
struct CinemaWriterNode::Settings {
    std::string path;
    std::vector<std::string> columns;
    Format format;
    Mode mode;
    std::string compression;
    std::vector<std::string> channels;
    std::string pipeline;
    bool sameDatabase(const Settings& o) const {
        return path == o.path && format == o.format && mode == o.mode && compression == o.compression &&
               channels == o.channels && pipeline == o.pipeline;
    }
};

namespace {

CinemaWriterOptions writerOptions(const CinemaWriterNode::Settings& s, bool again, const std::string& node) {
    using Format = CinemaWriterNode::Format;
    using Mode = CinemaWriterNode::Mode;
    CinemaWriterOptions o;
    adviseNodeMode(o, node);
    // A database this node wrote in an earlier sequence (the editor's
    // previous evaluation) is added to, whatever the mode: not refused as
    // existing, not replaced.
    o.overwrite = s.mode == Mode::Overwrite && !again;
    o.resume = s.mode == Mode::Resume || again;
    o.productExtension = s.format == Format::Png ? ".png" : s.format == Format::H5 ? ".h5" : ".exr";
    o.image.compression = s.compression;
    o.image.channels = s.channels;
    // A resume refuses a database these settings did not write (the product
    // format the writer records itself).
    const std::string channelList = join(s.channels, ",");
    o.origin.push_back({"the CinemaWriter settings", "channels", channelList.empty() ? "default" : channelList});
    if (s.format == Format::Exr) o.origin.push_back({"the CinemaWriter settings", "compression", s.compression});
    for (auto& item : pipelineOriginItems(s.pipeline)) o.origin.push_back(std::move(item));
    return o;
}

}  // namespace

CinemaWriterNode::CinemaWriterNode() = default;

CinemaWriterNode::~CinemaWriterNode() {
    // Only a host that never ended the sequence leaves a database open. It
    // is complete after every entry; finishing rewrites data.csv and removes
    // the lock file. A failure here leaves a valid database with a stale
    // lock, which the next writer takes over.
    try {
        endSequence({}, false);
    } catch (...) {
    }
}

void CinemaWriterNode::endSequence(const SequenceInfo&, bool) {
    std::unique_ptr<CinemaWriter> writer;
    {
        std::lock_guard<std::mutex> g(mutex_);
        writer = std::move(writer_);
    }
    if (writer) writer->finish();
}

void CinemaWriterNode::execute(Context& ctx) {
    const BufferPtr image = ctx.get(image_);
    const Row& row = ctx.get(row_);
    if (row.empty())
        throw Error("'row' is empty: connect CinemaReader's row output (or set row to the entry's parameters, e.g. "
                    "'time=0.5, phi=30')");
    CinemaParameters params;
    std::vector<std::string> columns;
    for (const auto& [column, value] : row.cells()) {
        if (isCinemaFileColumn(column)) continue;
        columns.push_back(column);
        params.emplace(column, CinemaValue(value));
    }
    if (columns.empty())
        throw Error("the row '" + formatRow(row) + "' has no parameter columns (only FILE columns), so entries could not "
                    "be told apart");
    if (ctx.getString(database_.name()).empty())
        throw Error("no database given; set 'database' to the folder to write, e.g. shaded.cdb");
    const std::string path = ctx.get(database_);
    const Format format = ctx.get(format_);
    const Mode mode = ctx.get(mode_);
    const std::string compression = ctx.get(compression_);

    const std::vector<std::string> channels = splitNames(ctx.get(channels_));
    const std::string& pipeline = ctx.get(pipeline_);

    Settings want{path, columns, format, mode, compression, channels, pipeline};
    std::lock_guard<std::mutex> g(mutex_);
    const bool same = last_ && last_->sameDatabase(want);
    if (same && last_->columns != columns)
        throw Error("this row has the columns " + join(columns, ", ") + " but the database " + path +
                    " was started with " + join(last_->columns, ", ") + "; write each database from rows of one kind");
    if (!same) {
        if (writer_) writer_->finish();
        writer_.reset();
        written_.clear();
    }
    if (!writer_) {
        std::error_code ec;
        const auto parent = std::filesystem::path(path).parent_path();
        if (!parent.empty()) std::filesystem::create_directories(parent, ec);
        writer_ = std::make_unique<CinemaWriter>(path, columns, writerOptions(want, same && !written_.empty(), ctx.nodeName()));
    }
    last_ = std::make_unique<Settings>(std::move(want));
    // A resumed database keeps the entries it has (written by an earlier,
    // interrupted run); an entry this node wrote is replaced (the editor
    // re-evaluating after an edit).
    ctx.set(writtenOut_, Value(std::filesystem::absolute(path).lexically_normal().string()));
    const std::string file = writer_->entryFileName(params);
    if (mode == Mode::Resume && writer_->hasEntry(params) && !written_.count(file)) {
        ctx.progress(1.0);
        return;
    }
    writer_->addEntry(params, *image);
    written_.insert(file);
    ctx.progress(1.0);
}

}  // namespace darkroom
