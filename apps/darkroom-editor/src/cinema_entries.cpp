#include "cinema_entries.h"

#include "display.h"

#include <darkroom/error.h>
#include <darkroom/filter.h>
#include <darkroom/data/cinema/composable.h>
#include <darkroom/core/registry.h>
#include <darkroom/core/run_filter.h>

#include <QStringList>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace editor {

QString readableValue(const std::string& cell) {
    // Integers stay as written: "012" is often an identifier, padded.
    if (cell.find_first_of(".eE") == std::string::npos) return QString::fromStdString(cell);
    const char* begin = cell.data();
    const char* end = begin + cell.size();
    while (begin < end && *begin == ' ') ++begin;
    if (begin < end && *begin == '+') ++begin;  // from_chars takes no plus sign
    double v = 0;
    const auto [at, ec] = std::from_chars(begin, end, v);
    if (ec != std::errc() || at != end || !std::isfinite(v)) return QString::fromStdString(cell);
    // The fewest significant digits within a billionth of the value: a sum
    // of steps written with its binary noise (0.44999999999999996) reads
    // 0.45, while values a parameter study tells apart stay apart.
    // At least the digits of the integer part, so that 1250 is not 1.25e+03.
    const int integerDigits = std::abs(v) >= 1 ? int(std::floor(std::log10(std::abs(v)))) + 1 : 1;
    char buf[40];
    for (int digits = std::min(integerDigits, 17); digits <= 17; ++digits) {
        const auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, digits);
        double back = 0;
        std::from_chars(buf, res.ptr, back);
        if (std::abs(back - v) <= 1e-9 * std::abs(v) || digits == 17) return QString::fromLatin1(buf, int(res.ptr - buf));
    }
    return QString::fromStdString(cell);
}

QString readableLabel(const darkroom::CinemaDatabase& db, std::size_t row) {
    // A composable image set's CIS columns describe channels and layers.
    const bool composable = darkroom::isComposableImageSet(db);
    QStringList parts;
    for (std::size_t c : db.parameterColumns()) {
        const std::string& name = db.columns()[c].name;
        if (composable && name.rfind("CIS", 0) == 0) continue;
        parts << QString::fromStdString(name) + QLatin1Char('=') + readableValue(db.cell(row, c));
    }
    return parts.join(QStringLiteral(", "));
}

std::vector<CinemaEntry> cinemaEntries(const darkroom::CinemaDatabase& db) {
    std::vector<CinemaEntry> entries;
    if (darkroom::isComposableImageSet(db)) {
        const auto images = darkroom::composableImages(db);
        for (const auto& image : images)
            for (const auto& layer : image.layers) {
                CinemaEntry e;
                e.parameters = QString::fromStdString(layer.query);
                e.row = layer.channels.empty() ? 0 : layer.channels.front().row;
                e.label = layer.parameters.empty() ? QString::fromStdString(image.id + "/" + layer.id)
                                                   : readableLabel(db, e.row);
                entries.push_back(std::move(e));
            }
        return entries;
    }
    for (std::size_t r = 0; r < db.rowCount(); ++r)
        entries.push_back({readableLabel(db, r), QString::fromStdString(db.formatParameters(r)), r});
    return entries;
}

CinemaEntryReader::CinemaEntryReader(const darkroom::Registry& registry, std::string database)
    : registry_(registry), database_(std::move(database)) {}

CinemaEntryReader::~CinemaEntryReader() = default;

darkroom::BufferPtr CinemaEntryReader::read(std::size_t row) {
    if (!filter_) {
        if (!registry_.filter("CinemaReader"))
            throw darkroom::Error("no CinemaReader node type is registered (cinema-io plugin)");
        filter_ = registry_.createFilter("CinemaReader");
    }
    darkroom::FilterRunOptions o;
    o.threads = 1;  // thumbnails stay in the background
    o.registry = &registry_;
    const auto result = darkroom::runFilter(*filter_,
                                            {{"database", {darkroom::Value(database_)}},
                                             {"entry", {darkroom::Value(std::int64_t(row))}}},
                                            o);
    return result.outputs.at("image").asImage();
}

QImage thumbnail(const darkroom::Buffer& b, int size) {
    const QString mode = preferredMode(displayModes(b));
    if (mode.isEmpty()) return {};
    return renderDisplay(b, mode).scaled(size, size, Qt::KeepAspectRatio, Qt::SmoothTransformation);
}

}  // namespace editor
