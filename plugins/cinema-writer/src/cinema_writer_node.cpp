#include "cinema_writer_node.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/row.h>
#include <darkroom/data/cinema/csv.h>
#include <darkroom/data/cinema/pipeline_origin.h>
#include <darkroom/data/cinema/writer.h>

#include <filesystem>
#include <set>

namespace darkroom {

struct CinemaWriterNode::Open {
    std::string path;
    std::vector<std::string> columns;
    Format format;
    Mode mode;
    std::string compression;
    std::vector<std::string> channels;
    std::string pipeline;
    std::unique_ptr<CinemaWriter> writer;
    std::set<std::string> writtenThisRun;  // product file names
};

namespace {

std::vector<std::string> splitChannels(const std::string& text) {
    std::vector<std::string> out;
    std::string word;
    for (char c : text + ",") {
        if (c == ',' || c == ' ' || c == '\t') {
            if (!word.empty()) out.push_back(word);
            word.clear();
        } else {
            word += c;
        }
    }
    return out;
}

}  // namespace

CinemaWriterNode::CinemaWriterNode() = default;

CinemaWriterNode::~CinemaWriterNode() {
    // data.csv is complete after every entry; finishing only rewrites it and
    // removes the lock file. A failure here leaves a valid database with a
    // stale lock, which the next writer takes over.
    if (open_ && open_->writer) {
        try {
            open_->writer->finish();
        } catch (...) {
        }
    }
}

void CinemaWriterNode::execute(Context& ctx) {
    const BufferPtr image = ctx.get(image_);
    const std::string& rowText = ctx.get(row_);
    if (rowText.empty())
        throw Error("'row' is empty: connect CinemaReader's row output (or set row to the entry's parameters, e.g. "
                    "'time=0.5, phi=30')");
    CinemaParameters params;
    std::vector<std::string> columns;
    for (const auto& [column, value] : parseCinemaRow(rowText)) {
        if (isCinemaFileColumn(column)) continue;
        columns.push_back(column);
        params.emplace(column, CinemaValue(value));
    }
    if (columns.empty())
        throw Error("the row '" + rowText + "' has no parameter columns (only FILE columns), so entries could not "
                    "be told apart");
    const std::string& given = ctx.getString(database_.name());
    if (given.empty()) throw Error("no database given; set 'database' to the folder to write, e.g. shaded.cdb");
    const std::string path = std::filesystem::path(ctx.resolveOutputPath(given)).lexically_normal().string();
    const Format format = ctx.get(format_);
    const Mode mode = ctx.get(mode_);
    const std::string compression = ctx.get(compression_);

    const std::vector<std::string> channels = splitChannels(ctx.get(channels_));
    const std::string& pipeline = ctx.get(pipeline_);

    std::lock_guard<std::mutex> g(mutex_);
    const bool reuse = open_ && open_->path == path && open_->format == format && open_->mode == mode &&
                       open_->compression == compression && open_->channels == channels &&
                       open_->pipeline == pipeline;
    if (reuse && open_->columns != columns) {
        std::string have, want;
        for (const auto& c : open_->columns) have += (have.empty() ? "" : ", ") + c;
        for (const auto& c : columns) want += (want.empty() ? "" : ", ") + c;
        throw Error("this row has the columns " + want + " but the database " + path + " was started with " + have +
                    "; write each database from rows of one kind");
    }
    if (!reuse) {
        if (open_ && open_->writer) open_->writer->finish();
        open_.reset();
        CinemaWriterOptions o;
        o.overwrite = mode == Mode::Overwrite;
        o.resume = mode == Mode::Resume;
        o.productExtension = format == Format::Png ? ".png" : ".exr";
        o.image.compression = compression;
        o.image.channels = channels;
        // A resume refuses a database these settings did not write (the
        // product format the writer records itself).
        std::string channelList;
        for (const auto& c : channels) channelList += (channelList.empty() ? "" : ",") + c;
        o.origin.push_back({"the CinemaWriter settings", "channels", channelList.empty() ? "default" : channelList});
        if (format == Format::Exr) o.origin.push_back({"the CinemaWriter settings", "compression", compression});
        for (auto& item : pipelineOriginItems(pipeline)) o.origin.push_back(std::move(item));
        std::error_code ec;
        const auto parent = std::filesystem::path(path).parent_path();
        if (!parent.empty()) std::filesystem::create_directories(parent, ec);
        auto next = std::make_unique<Open>();
        *next = Open{path, columns, format, mode, compression, channels, pipeline, nullptr, {}};
        next->writer = std::make_unique<CinemaWriter>(path, columns, o);
        open_ = std::move(next);
    }
    // A resumed database keeps the entries it has (written by an earlier,
    // interrupted run); an entry written earlier in this run is replaced (the
    // editor re-evaluating after an edit).
    const std::string file = open_->writer->entryFileName(params);
    if (mode == Mode::Resume && open_->writer->hasEntry(params) && !open_->writtenThisRun.count(file)) {
        ctx.progress(1.0);
        return;
    }
    open_->writer->addEntry(params, *image);
    open_->writtenThisRun.insert(file);
    ctx.progress(1.0);
}

}  // namespace darkroom
