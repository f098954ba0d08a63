#pragma once
// What the Cinema browser offers and how it reads it: the same path as the
// pipeline's CinemaReader node (and the runner's --foreach, which drives that
// node), so every product CinemaReader reads (EXR, PNG, .npz, .vti,
// composable image sets) gets a thumbnail, and the thumbnail shows exactly
// what the node will output for that entry.
#include <darkroom/buffer.h>
#include <darkroom/data/cinema/database.h>

#include <QImage>
#include <QString>

#include <memory>
#include <string>
#include <vector>

namespace darkroom {
class Filter;
class Registry;
}  // namespace darkroom

namespace editor {

struct CinemaEntry {
    QString label;       // the list's text
    QString parameters;  // the entry as CinemaReader's `parameters` would choose it (tooltips)
    std::size_t row = 0; // its first data.csv row: CinemaReader's `entry` (drives the sliders)
};

// A cell as a person reads it: a decimal number in its shortest exact form
// ("2.500000E-01" -> "0.25", "1.250000E+03" -> "1250"); integers ("012",
// often padded identifiers) and other text as written.
QString readableValue(const std::string& cell);
// "time=0.25, kind=a": the row's parameter columns (a composable image
// set's without its CIS columns), values readable.
QString readableLabel(const darkroom::CinemaDatabase& db, std::size_t row);

// One entry per data.csv row (labelled readably; `parameters` as written,
// as --foreach sets them, so they find the row exactly);
// in a composable image set, whose rows are single channels, one entry per
// layer ("CISImage=i000, CISLayer=l000"), since that is what CinemaReader
// assembles into one image. Throws darkroom::Error on a malformed set.
std::vector<CinemaEntry> cinemaEntries(const darkroom::CinemaDatabase& db);

// Reads entries through the registry's CinemaReader filter; one reader keeps
// data.csv parsed between calls. Not thread-safe: one per thread.
class CinemaEntryReader {
public:
    CinemaEntryReader(const darkroom::Registry& registry, std::string database);
    ~CinemaEntryReader();
    // Throws darkroom::Error (also when no CinemaReader type is registered).
    darkroom::BufferPtr read(std::size_t row);

private:
    const darkroom::Registry& registry_;
    std::string database_;
    std::unique_ptr<darkroom::Filter> filter_;
};

// A thumbnail of preferredMode(); empty when the buffer has nothing to show.
QImage thumbnail(const darkroom::Buffer& b, int size);

}  // namespace editor
