// The Cinema Spec D writer: products first, then an atomically replaced
// data.csv, all under a folder lock. See writer.h for the guarantees.
#include "database_lock.h"
#include "database_marker.h"
#include "../io/optional_module.h"

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/data/cinema/csv.h>
#include <darkroom/data/cinema/naming.h>
#include <darkroom/data/cinema/writer.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <optional>
#include <set>

namespace darkroom {

namespace fs = std::filesystem;
using cinema_detail::DatabaseLock;
using cinema_detail::kMarkerFileName;

namespace {

// Rows sort by their values, column by column: numbers (ascending, NaN last)
// before text. Derived from the cell text alone, so an entry sorts the same
// whether it was just added or read back by a resume.
struct SortCell {
    bool isNumber;
    double number;
    std::string text;
};

SortCell sortCell(const std::string& text) {
    double v;
    if (parseCsvNumber(text, v)) return {true, v, text};
    return {false, 0, text};
}

bool cellLess(const SortCell& a, const SortCell& b) {
    if (a.isNumber != b.isNumber) return a.isNumber;
    if (!a.isNumber) return a.text < b.text;
    const bool an = std::isnan(a.number), bn = std::isnan(b.number);
    if (an || bn) return !an && bn;
    return a.number < b.number;
}

// The source of the origin items the writer records itself.
constexpr const char* kLayoutSource = "the database layout";

// What an interrupted atomic write leaves behind: "<stem>.tmp-<pid>-<n><ext>".
bool isTemporaryLeftover(const std::string& name) {
    std::size_t p = name.find(".tmp-");
    while (p != std::string::npos) {
        std::size_t i = p + 5, digits1 = 0, digits2 = 0;
        while (i < name.size() && std::isdigit(static_cast<unsigned char>(name[i]))) ++i, ++digits1;
        if (digits1 && i < name.size() && name[i] == '-') {
            ++i;
            while (i < name.size() && std::isdigit(static_cast<unsigned char>(name[i]))) ++i, ++digits2;
            if (digits2) return true;
        }
        p = name.find(".tmp-", p + 1);
    }
    return false;
}

}  // namespace

struct CinemaWriter::Impl {
    struct Entry {
        std::vector<std::string> cells;  // parameter values as written
        std::vector<SortCell> key;
    };

    std::string folder;
    std::string csvPath;
    std::vector<std::string> columns;
    CinemaWriterOptions options;
    std::unique_ptr<DatabaseLock> lock;
    mutable std::mutex mutex;
    std::map<std::string, Entry> entries;  // by product file name
    std::size_t resumed = 0;
    bool finished = false;

    std::vector<std::string> cellsOf(const CinemaParameters& p) const {
        std::vector<std::string> cells;
        for (const auto& c : columns) {
            auto it = p.find(c);
            if (it == p.end())
                throw Error(fmt::format("entry of database {}: parameter '{}' is missing; expected "
                                        "values for {}",
                                        folder, c, fmt::join(columns, ", ")));
            std::string s = it->second.str();
            if (s.find_first_of("\r\n") != std::string::npos)
                throw Error(fmt::format("entry of database {}: the value of '{}' contains a line "
                                        "break; data.csv cells cannot",
                                        folder, c));
            cells.push_back(std::move(s));
        }
        if (p.size() != columns.size())
            for (const auto& [name, v] : p)
                if (std::find(columns.begin(), columns.end(), name) == columns.end())
                    throw Error(fmt::format("entry of database {}: '{}' is not a column; the columns "
                                            "are {}",
                                            folder, name, fmt::join(columns, ", ")));
        return cells;
    }

    std::string markerPath() const { return (fs::path(folder) / kMarkerFileName).string(); }

    // The caller's origin and the writer's own: the product format and the
    // attachment files (the columns are compared with data.csv's header).
    std::vector<CinemaOriginItem> origin() const {
        std::vector<CinemaOriginItem> out = options.origin;
        out.push_back({kLayoutSource, "products", options.productExtension, false});
        std::string attached;
        for (const auto& a : options.attachments) attached += (attached.empty() ? "" : " ") + a.column + ":" + a.suffix;
        out.push_back({kLayoutSource, "attachments", attached.empty() ? "none" : attached, false});
        return out;
    }

    void writeMarker() const { writeFileAtomic(markerPath(), cinema_detail::markerText(origin())); }

    // A resume completes only what Darkroom began from the same origin.
    void checkMarkerForResume(bool compareOrigin) const {
        std::optional<std::vector<CinemaOriginItem>> recorded;
        try {
            recorded = cinema_detail::readMarker(folder);
        } catch (const Error& e) {
            throw Error(fmt::format("cannot resume {}: {}", folder, e.what()));
        }
        if (!recorded)
            throw Error(fmt::format("cannot resume {}: it has no {} file, so Darkroom did not create it (or a "
                                    "Darkroom older than this check did, which recorded nothing to compare); "
                                    "capture into a new folder, or remove this one and capture again",
                                    folder, kMarkerFileName));
        if (!compareOrigin) return;
        const std::string change = cinema_detail::describeOriginChange(*recorded, origin());
        if (!change.empty())
            throw Error(fmt::format("cannot resume {}: {}; use {} to start afresh", folder, change,
                                    options.overwriteAdvice));
    }

    std::string stemOf(const std::vector<std::string>& cells) const {
        std::vector<std::pair<std::string, std::string>> pairs;
        for (std::size_t i = 0; i < columns.size(); ++i) pairs.emplace_back(columns[i], cells[i]);
        return cinemaEntryName(pairs);
    }
    std::string fileNameOf(const std::vector<std::string>& cells) const {
        return stemOf(cells) + options.productExtension;
    }
    std::string attachmentNameOf(const std::string& product, const CinemaAttachmentColumn& a) const {
        return product.substr(0, product.size() - options.productExtension.size()) + a.suffix;
    }

    std::string describe(const std::vector<std::string>& cells) const {
        std::string s;
        for (std::size_t i = 0; i < columns.size(); ++i)
            s += fmt::format("{}{}={}", i ? ", " : "", columns[i], cells[i]);
        return s;
    }

    // Called with the mutex held.
    void writeCsv() const {
        std::vector<const std::pair<const std::string, Entry>*> sorted;
        for (const auto& e : entries) sorted.push_back(&e);
        std::sort(sorted.begin(), sorted.end(), [](auto* a, auto* b) {
            const auto& ka = a->second.key;
            const auto& kb = b->second.key;
            for (std::size_t i = 0; i < ka.size(); ++i) {
                if (cellLess(ka[i], kb[i])) return true;
                if (cellLess(kb[i], ka[i])) return false;
            }
            return a->first < b->first;  // total order even for equal values
        });
        std::string text;
        for (const auto& c : columns) text += quoteCsvCell(c) + ",";
        text += "FILE";
        for (const auto& a : options.attachments) text += "," + quoteCsvCell(a.column);
        text += "\n";
        for (const auto* e : sorted) {
            for (const auto& cell : e->second.cells) text += quoteCsvCell(cell) + ",";
            text += quoteCsvCell(e->first);
            for (const auto& a : options.attachments) text += "," + quoteCsvCell(attachmentNameOf(e->first, a));
            text += "\n";
        }
        writeFileAtomic(csvPath, text);
    }

    void validateColumns() const {
        std::set<std::string> seen;
        for (const auto& c : columns) {
            const bool bad = c.empty() || c.find_first_of(",\"\r\n=") != std::string::npos ||
                             c.front() == ' ' || c.back() == ' ';
            if (bad)
                throw Error(fmt::format("database {}: column name '{}' is not usable; expected a "
                                        "non-empty name without commas, quotes, '=' or line breaks",
                                        folder, c));
            if (isCinemaFileColumn(c))
                throw Error(fmt::format("database {}: column name '{}' is reserved for product files",
                                        folder, c));
            if (!seen.insert(c).second)
                throw Error(fmt::format("database {}: column '{}' is given twice", folder, c));
        }
        const std::string& ext = options.productExtension;
        if (ext.size() < 2 || ext[0] != '.' || ext.find_first_of("/\\") != std::string::npos)
            throw Error(fmt::format("database {}: product extension '{}' is not usable; expected e.g. .exr or .png",
                                    folder, ext));
        for (const auto& a : options.attachments) {
            const bool bad = !isCinemaFileColumn(a.column) || a.column == "FILE" ||
                             a.column.find_first_of(",\"\r\n") != std::string::npos || a.suffix.empty() ||
                             a.suffix.find_first_of("/\\,\"\r\n") != std::string::npos || a.suffix == ext;
            if (bad)
                throw Error(fmt::format("database {}: attachment column '{}' with file suffix '{}' is not usable; "
                                        "expected a column FILE_<name> and a suffix such as .<name>.csv",
                                        folder, a.column, a.suffix));
            if (!seen.insert(a.column).second)
                throw Error(fmt::format("database {}: column '{}' is given twice", folder, a.column));
        }
    }

    // Everything in the folder but our lock file.
    std::vector<fs::path> contents() const {
        std::vector<fs::path> out;
        for (const auto& e : fs::directory_iterator(folder))
            if (e.path().filename() != DatabaseLock::kFileName) out.push_back(e.path());
        std::sort(out.begin(), out.end());
        return out;
    }

    void removeTemporaryLeftovers() const {
        std::error_code ec;
        for (const auto& p : contents())
            if (isTemporaryLeftover(p.filename().string()) && fs::is_regular_file(fs::symlink_status(p, ec)))
                fs::remove(p);
    }

    // Darkroom's own files besides data.csv: the marker and the leftovers of
    // interrupted writes.
    bool isOwnFile(const fs::path& p) const {
        const std::string name = p.filename().string();
        return name == kMarkerFileName || isTemporaryLeftover(name);
    }

    // The data.csv a resume reads; none when the folder holds nothing else
    // than the leftovers of interrupted writes.
    std::optional<CsvTable> resumableTable() const {
        if (!fs::exists(csvPath)) {
            for (const auto& p : contents())
                if (!isOwnFile(p))
                    throw Error(fmt::format("cannot resume {}: it has no data.csv, so it is not a Cinema "
                                            "database written by Darkroom; use {} to replace it",
                                            folder, options.overwriteAdvice));
            return std::nullopt;
        }
        CsvReadOptions strict;
        strict.strict = true;
        try {
            return readCsvFile(csvPath, strict);
        } catch (const Error& e) {
            throw Error(fmt::format("cannot resume {}: {}; use {} to start afresh", folder, e.what(),
                                    options.overwriteAdvice));
        }
    }

    void resumeExisting() {
        const std::optional<CsvTable> existing = resumableTable();
        if (!existing) {
            // Nothing but what an interrupted start leaves: a fresh database.
            removeTemporaryLeftovers();
            return;
        }
        checkMarkerForResume(true);
        const CsvTable& table = *existing;
        std::vector<std::string> expected = columns;
        expected.push_back("FILE");
        for (const auto& a : options.attachments) expected.push_back(a.column);
        if (table.header != expected)
            throw Error(fmt::format("cannot resume {}: its columns are {} but this capture writes {}; "
                                    "use {} to replace it",
                                    folder, fmt::join(table.header, ","), fmt::join(expected, ","),
                                    options.overwriteAdvice));
        // Only once nothing refuses the resume: a refusal leaves the folder as it was.
        removeTemporaryLeftovers();
        const std::size_t extra = options.attachments.size();
        for (const auto& row : table.rows) {
            std::vector<std::string> cells(row.begin(), row.end() - 1 - std::ptrdiff_t(extra));
            const std::string& file = row[columns.size()];
            // Products and attachments are renamed into place complete, so
            // one that exists under its final name is whole; an entry missing
            // any of its files is recomputed.
            std::error_code ec;
            const fs::path product = fs::path(folder) / file;
            if (file != fileNameOf(cells) || !fs::is_regular_file(product, ec) ||
                fs::file_size(product, ec) == 0)
                continue;
            bool complete = true;
            for (std::size_t k = 0; k < extra; ++k) {
                const std::string name = attachmentNameOf(file, options.attachments[k]);
                complete = complete && row[columns.size() + 1 + k] == name &&
                           fs::is_regular_file(fs::path(folder) / name, ec);
            }
            if (!complete) continue;
            Entry e{cells, {}};
            for (const auto& c : cells) e.key.push_back(sortCell(c));
            entries.emplace(file, std::move(e));
        }
        resumed = entries.size();
    }

    // What --overwrite removes: the files data.csv lists (plain names in the
    // folder), data.csv, the marker and leftovers of interrupted writes.
    // Everything else (files of other tools, subfolders) stays.
    void removeForOverwrite(bool apply) const {
        std::optional<std::vector<CinemaOriginItem>> marker;
        try {
            marker = cinema_detail::readMarker(folder);
        } catch (const Error& e) {
            throw Error(fmt::format("refusing to overwrite {}: {}; nothing was removed", folder, e.what()));
        }
        if (!marker)
            throw Error(fmt::format("refusing to overwrite {}: it has no {} file, so Darkroom did not create it "
                                    "(or a Darkroom older than this check did); nothing was removed. Remove the "
                                    "folder yourself if it may go, or write to another folder",
                                    folder, kMarkerFileName));
        std::vector<fs::path> doomed;
        std::error_code ec;
        if (fs::exists(fs::symlink_status(csvPath, ec))) {
            CsvTable table;
            try {
                table = readCsvFile(csvPath, {});
            } catch (const Error& e) {
                throw Error(fmt::format("refusing to overwrite {}: {}, so what Darkroom wrote there is unknown; "
                                        "nothing was removed",
                                        folder, e.what()));
            }
            for (std::size_t c = 0; c < table.header.size(); ++c) {
                if (!isCinemaFileColumn(table.header[c])) continue;
                for (const auto& row : table.rows) {
                    if (c >= row.size()) continue;
                    const std::string& name = row[c];
                    const bool plain = !name.empty() && name != "." && name != ".." &&
                                       name.find_first_of("/\\") == std::string::npos;
                    const fs::path p = fs::path(folder) / name;
                    if (plain && fs::is_regular_file(fs::symlink_status(p, ec))) doomed.push_back(p);
                }
            }
            doomed.push_back(csvPath);
        }
        for (const auto& p : contents())
            if (isTemporaryLeftover(p.filename().string()) && fs::is_regular_file(fs::symlink_status(p, ec)))
                doomed.push_back(p);
        if (!apply) return;
        for (const auto& p : doomed) fs::remove(p);
        // The marker last: a kill part way leaves a folder still marked as ours.
        fs::remove(markerPath());
    }

    // Called with the lock held: what the folder holds against the mode.
    // `apply` false only checks (CinemaWriter::check).
    void openExisting(bool apply) {
        if (contents().empty()) return;
        if (options.resume) {
            if (apply) {
                resumeExisting();
            } else if (resumableTable()) {
                checkMarkerForResume(!options.origin.empty());
            }
        } else if (options.overwrite) {
            removeForOverwrite(apply);
        } else {
            throw Error(fmt::format("database {} already exists and is not empty; use {} to replace it or {} "
                                    "to complete it",
                                    folder, options.overwriteAdvice, options.resumeAdvice));
        }
    }

    void checkAttachmentColumns(const std::vector<std::string>& cells, const std::vector<std::string>& given) const {
        for (const auto& a : options.attachments)
            if (std::find(given.begin(), given.end(), a.column) == given.end())
                throw Error(fmt::format("entry {} of database {}: the file for column {} is missing", describe(cells),
                                        folder, a.column));
        for (const auto& column : given)
            if (std::none_of(options.attachments.begin(), options.attachments.end(),
                             [&](const CinemaAttachmentColumn& a) { return a.column == column; }))
                throw Error(fmt::format("entry {} of database {}: {} is not an attachment column of this database",
                                        describe(cells), folder, column));
    }

    // Called with the mutex held.
    void checkCanAdd(const std::vector<std::string>& cells, const std::string& file) const {
        if (finished) throw Error(fmt::format("database {}: addEntry after finish()", folder));
        auto it = entries.find(file);
        if (it != entries.end() && it->second.cells != cells)
            throw Error(fmt::format("database {}: entries '{}' and '{}' would share the file {}; "
                                    "make the parameter values distinguishable",
                                    folder, describe(it->second.cells), describe(cells), file));
    }

    void record(std::vector<std::string> cells, const std::string& file) {
        Entry e{std::move(cells), {}};
        for (const auto& c : e.cells) e.key.push_back(sortCell(c));
        entries.insert_or_assign(file, std::move(e));
    }
};

namespace {

// Renames a finished file into place; across file systems, copies it beside
// its destination first so the destination still appears whole.
void moveFileInto(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    fs::rename(from, to, ec);
    if (ec == std::errc::cross_device_link) {
        const std::string tmp = createTemporaryFile(to.string());
        fs::copy_file(from, tmp, fs::copy_options::overwrite_existing, ec);
        if (!ec) {
            commitFile(tmp, to.string());
            fs::remove(from, ec);
            return;
        }
        fs::remove(tmp);
    }
    if (ec) throw Error(fmt::format("cannot move {} to {}: {}", from.string(), to.string(), ec.message()));
}

}  // namespace

void adviseNodeMode(CinemaWriterOptions& options, const std::string& node) {
    options.overwriteAdvice = "mode: overwrite (--set " + node + ".mode=overwrite)";
    options.resumeAdvice = "mode: resume (--set " + node + ".mode=resume)";
}

CinemaWriter::CinemaWriter(std::string path, std::vector<std::string> columnNames,
                           CinemaWriterOptions options)
    : impl_(std::make_unique<Impl>()) {
    Impl& d = *impl_;
    while (path.size() > 1 && path.back() == '/') path.pop_back();
    d.folder = std::move(path);
    d.csvPath = (fs::path(d.folder) / "data.csv").string();
    d.columns = std::move(columnNames);
    d.options = std::move(options);
    if (d.options.overwrite && d.options.resume)
        throw Error(fmt::format("database {}: {} and {} exclude each other", d.folder, d.options.overwriteAdvice,
                                d.options.resumeAdvice));
    d.validateColumns();

    std::error_code ec;
    if (fs::exists(d.folder, ec) && !fs::is_directory(d.folder, ec))
        throw Error(fmt::format("cannot write database {}: a file of that name exists", d.folder));
    fs::create_directories(d.folder, ec);
    if (ec) throw Error(fmt::format("cannot create database folder {}: {}", d.folder, ec.message()));

    d.lock = std::make_unique<DatabaseLock>(d.folder);
    try {
        d.openExisting(true);
        // The marker before data.csv: a folder with a data.csv of ours always has one.
        d.writeMarker();
        d.writeCsv();
    } catch (const fs::filesystem_error& e) {
        d.lock->releaseAndRemove();
        throw Error(fmt::format("database {}: {}", d.folder, e.what()));
    } catch (...) {
        d.lock->releaseAndRemove();
        throw;
    }
}

void CinemaWriter::check(std::string path, const CinemaWriterOptions& options) {
    Impl d;
    while (path.size() > 1 && path.back() == '/') path.pop_back();
    d.folder = std::move(path);
    d.csvPath = (fs::path(d.folder) / "data.csv").string();
    d.options = options;
    if (d.options.overwrite && d.options.resume)
        throw Error(fmt::format("database {}: {} and {} exclude each other", d.folder, d.options.overwriteAdvice,
                                d.options.resumeAdvice));
    std::error_code ec;
    if (!fs::exists(d.folder, ec)) return;
    if (!fs::is_directory(d.folder, ec))
        throw Error(fmt::format("cannot write database {}: a file of that name exists", d.folder));
    // Taking the lock is the only way to know that no one holds it.
    DatabaseLock lock(d.folder);  // removed by its destructor on every path
    try {
        d.openExisting(false);
    } catch (const fs::filesystem_error& e) {
        throw Error(fmt::format("database {}: {}", d.folder, e.what()));
    }
}

std::vector<CinemaOriginItem> CinemaWriter::recordedOrigin(const std::string& path) {
    std::vector<CinemaOriginItem> out;
    if (const auto recorded = cinema_detail::readMarker(path))
        for (const auto& item : *recorded)
            if (item.source != kLayoutSource) out.push_back(item);
    return out;
}

CinemaWriter::~CinemaWriter() = default;

const std::string& CinemaWriter::path() const { return impl_->folder; }
const std::vector<std::string>& CinemaWriter::columns() const { return impl_->columns; }

std::string CinemaWriter::entryFileName(const CinemaParameters& parameters) const {
    return impl_->fileNameOf(impl_->cellsOf(parameters));
}

bool CinemaWriter::hasEntry(const CinemaParameters& parameters) const {
    const auto cells = impl_->cellsOf(parameters);
    const std::string file = impl_->fileNameOf(cells);
    std::lock_guard<std::mutex> g(impl_->mutex);
    auto it = impl_->entries.find(file);
    return it != impl_->entries.end() && it->second.cells == cells;
}

namespace {

// The product of one entry: an image file by its extension, or pycinema's
// .h5 with the entry's parameters in its meta group, as pycinema's writer
// keeps them there (docs/formats.md): numbers as numbers.
void writeProduct(const Buffer& image, const std::string& path, const CinemaParameters& parameters,
                  const CinemaWriterOptions& options) {
    if (options.productExtension != ".h5") return writeImage(image, path, options.image);
    h5::MetaValues meta;
    for (const auto& [column, value] : parameters) {
        // A cell copied as text from another database ("2.0") that reads as
        // a number in data.csv is a number to pycinema too.
        double number = 0;
        if (value.isNumber())
            meta[column] = value.number();
        else if (parseCsvNumber(value.text(), number))
            meta[column] = number;
        else
            meta[column] = value.text();
    }
    io::h5Module("writing '" + path + "'").writeImageFile(image, path, meta);
}

}  // namespace

void CinemaWriter::addEntry(const CinemaParameters& parameters, const Buffer& image,
                            const std::map<std::string, std::string>& attachments) {
    Impl& d = *impl_;
    auto cells = d.cellsOf(parameters);
    const std::string file = d.fileNameOf(cells);
    std::vector<std::string> given;
    for (const auto& [column, bytes] : attachments) given.push_back(column);
    d.checkAttachmentColumns(cells, given);
    {
        std::lock_guard<std::mutex> g(d.mutex);
        d.checkCanAdd(cells, file);
    }
    // The product first (atomically), the row naming it second: a kill in
    // between leaves a product no row names, which a resume rewrites.
    writeProduct(image, (fs::path(d.folder) / file).string(), parameters, d.options);
    for (const auto& a : d.options.attachments)
        writeFileAtomic((fs::path(d.folder) / d.attachmentNameOf(file, a)).string(), attachments.at(a.column));
    std::lock_guard<std::mutex> g(d.mutex);
    d.record(std::move(cells), file);
    d.writeCsv();
}

void CinemaWriter::adoptEntries(const std::vector<CinemaStagedEntry>& staged) {
    Impl& d = *impl_;
    struct Adoption {
        std::vector<std::string> cells;
        std::string file;
        std::vector<std::pair<fs::path, fs::path>> moves;  // product first, then attachments
    };
    std::vector<Adoption> todo;
    std::map<std::string, std::vector<std::string>> inBatch;  // file -> cells
    std::lock_guard<std::mutex> g(d.mutex);
    for (const auto& s : staged) {
        Adoption a{d.cellsOf(s.parameters), {}, {}};
        a.file = d.fileNameOf(a.cells);
        std::vector<std::string> given;
        for (const auto& [column, path] : s.attachments) given.push_back(column);
        d.checkAttachmentColumns(a.cells, given);
        d.checkCanAdd(a.cells, a.file);
        const auto [earlier, fresh] = inBatch.emplace(a.file, a.cells);
        if (!fresh && earlier->second != a.cells)
            throw Error(fmt::format("database {}: entries '{}' and '{}' would share the file {}; "
                                    "make the parameter values distinguishable",
                                    d.folder, d.describe(earlier->second), d.describe(a.cells), a.file));
        std::error_code ec;
        if (!fs::is_regular_file(s.product, ec) || fs::file_size(s.product, ec) == 0)
            throw Error(fmt::format("entry {} of database {}: its product {} is missing or empty", d.describe(a.cells),
                                    d.folder, s.product));
        a.moves.emplace_back(s.product, fs::path(d.folder) / a.file);
        for (const auto& column : d.options.attachments) {
            const std::string& from = s.attachments.at(column.column);
            if (!fs::is_regular_file(from, ec))
                throw Error(fmt::format("entry {} of database {}: its file {} for column {} is missing",
                                        d.describe(a.cells), d.folder, from, column.column));
            a.moves.emplace_back(from, fs::path(d.folder) / d.attachmentNameOf(a.file, column));
        }
        todo.push_back(std::move(a));
    }
    // Rows only for entries whose files all moved; data.csv also when a move fails.
    try {
        for (auto& a : todo) {
            for (const auto& [from, to] : a.moves) moveFileInto(from, to);
            d.record(std::move(a.cells), a.file);
        }
    } catch (...) {
        d.writeCsv();
        throw;
    }
    d.writeCsv();
}

std::size_t CinemaWriter::entryCount() const {
    std::lock_guard<std::mutex> g(impl_->mutex);
    return impl_->entries.size();
}

std::size_t CinemaWriter::resumedCount() const { return impl_->resumed; }

void CinemaWriter::finish() {
    std::lock_guard<std::mutex> g(impl_->mutex);
    if (impl_->finished) return;
    impl_->writeCsv();
    impl_->finished = true;
    impl_->lock->releaseAndRemove();
}

}  // namespace darkroom
