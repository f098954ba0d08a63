#pragma once
// Reading a Cinema Spec D database: a folder `name.cdb/` with a `data.csv`
// whose columns are the sampling parameters plus one or more FILE columns
// naming product files relative to the folder.
#include <darkroom/buffer.h>
#include <darkroom/camera.h>
#include <darkroom/export.h>
#include <darkroom/data/cinema/csv.h>
#include <darkroom/diagnostics.h>

#include <cstddef>
#include <optional>
#include <functional>
#include <string>
#include <vector>

namespace darkroom {

struct CinemaColumn {
    std::string name;
    bool isFile = false;   // a FILE column (products), not a parameter
    bool numeric = false;  // every non-empty cell parses as a number
    // Numeric columns: range over the non-NaN values (NaN when there are none).
    double minimum = 0, maximum = 0;
    std::size_t missing = 0;  // empty cells (numeric: also NaN cells)
    // Distinct values in order: numeric columns ascending (as written in the
    // file, NaN/empty left out), text columns in order of first appearance.
    std::vector<std::string> distinct;
};

// One constraint of a query "phi=30, theta=45".
struct CinemaConstraint {
    std::string column;
    std::string value;
};

struct CinemaMatch {
    std::size_t row = 0;
    // Non-empty when a numeric value was snapped to the nearest one present
    // ("phi=31 is not in the database; using the nearest value 30").
    std::vector<std::string> notes;
};

struct CinemaProductInfo {
    std::string column;  // FILE column
    std::string path;    // the product whose header was read (first row)
    int width = 0, height = 0;
    std::vector<ChannelDesc> channels;
    std::optional<Camera> camera;
    std::string error;  // non-empty when the product could not be read
    // Format-specific facts: .npz members with dtype and shape, .vti arrays.
    std::vector<std::string> details;
    // A .csv product is a point list (scene/point_list.h), not an image:
    // `details` says how many points and which columns.
    bool pointList = false;
    // A mesh or a volume (product.h, geometryProduct): what it is, and what
    // to do with it instead of shading (capture it into G-buffers).
    std::string geometry, geometryAdvice;
};

// What `darkroom info` prints.
struct CinemaDescription {
    std::string path;
    std::size_t rows = 0;
    std::vector<CinemaColumn> columns;
    std::vector<CinemaProductInfo> products;  // one per FILE column
    // Composable image sets: one line per image and layer with its channels.
    std::vector<std::string> composable;
    Diagnostics warnings;
};

class DARKROOM_API CinemaDatabase {
public:
    // `path` is the .cdb folder or its data.csv. Throws darkroom::Error naming
    // the file when it is missing or (strict) irregular; warnings() keeps the
    // tolerant reader's notes.
    static CinemaDatabase open(const std::string& path, const CsvReadOptions& options = {});

    const std::string& path() const { return folder_; }  // the .cdb folder
    const std::string& csvPath() const { return csvPath_; }
    const Diagnostics& warnings() const { return table_.warnings; }

    const std::vector<CinemaColumn>& columns() const { return columns_; }
    // Index of a column by name; throws darkroom::Error listing the columns.
    std::size_t column(std::string_view name) const;
    std::optional<std::size_t> findColumn(std::string_view name) const;
    std::vector<std::size_t> fileColumns() const;
    std::vector<std::size_t> parameterColumns() const;

    std::size_t rowCount() const { return table_.rows.size(); }
    // Trimmed, unquoted cell text, and its number (NaN when empty or text).
    const std::string& cell(std::size_t row, std::size_t column) const;
    double number(std::size_t row, std::size_t column) const;
    int line(std::size_t row) const { return table_.rowLines[row]; }

    // The product of `row` in FILE column `fileColumn` ("" = the first FILE
    // column), resolved against the database folder. Throws darkroom::Error
    // when the database has no such FILE column or the cell is empty.
    std::string productPath(std::size_t row, std::string_view fileColumn = {}) const;

    // Parses "phi=30, theta=45" (values may be quoted: name="a, b"); an empty
    // query has no constraints. Throws darkroom::Error on bad syntax.
    static std::vector<CinemaConstraint> parseQuery(std::string_view query);
    // The first row matching every constraint; numeric values snap to the
    // nearest value present in that column (within the column's spacing).
    // No constraints: row 0. Throws darkroom::Error naming the database and
    // listing the available values when nothing matches.
    CinemaMatch find(const std::vector<CinemaConstraint>& constraints) const;
    CinemaMatch find(std::string_view query) const { return find(parseQuery(query)); }
    // Every row matching (same rules); empty when none.
    std::vector<std::size_t> select(const std::vector<CinemaConstraint>& constraints) const;

    // Rows whose values satisfy an SQL WHERE expression ("phi > 0 AND theta =
    // 0"; a leading "WHERE" is allowed), in database order. data.csv is loaded
    // into an in-memory SQLite table `input`: numeric columns REAL (NaN and
    // empty cells NULL), the others TEXT, column names quoted as written.
    // Unlike find()/select(), values are compared exactly. Throws
    // darkroom::Error with SQLite's message and the query text. Empty = all rows.
    // An expression that runs forever (a recursive CTE) stops at
    // --max-node-seconds (InputError naming the option) or when `stop` says
    // so (darkroom::Cancelled), checked every few thousand SQLite steps.
    std::vector<std::size_t> query(const std::string& sqlWhere, const std::function<bool()>& stop = {}) const;
    // True when `where` is SQL rather than the simple "name=value, ..." form:
    // it holds < > ! ( ) or a single quote outside "double quotes", or a word
    // AND, OR, NOT, LIKE, IN, BETWEEN, IS, GLOB, NULL.
    static bool looksLikeSql(std::string_view where);
    // query(where) when looksLikeSql(where), else select(parseQuery(where)).
    std::vector<std::size_t> selectWhere(const std::string& where, const std::function<bool()>& stop = {}) const;

    // "phi=30, theta=45": the row's parameter (non-FILE) columns as written,
    // such that find(formatParameters(r)) returns a row with the same values.
    std::string formatParameters(std::size_t row) const;
    // A file-name-safe form of the same: "phi=30_theta=45".
    std::string entryName(std::size_t row) const;

    // Rows, columns and, per FILE column, the first product's size, channels
    // and camera (read with readCinemaProduct's header reading: images, .npz,
    // .vti; a failure is recorded, not thrown); composable image sets are
    // summarised image by image.
    CinemaDescription describe() const;

private:
    std::string folder_;
    std::string csvPath_;
    CsvTable table_;
    std::vector<CinemaColumn> columns_;
    std::vector<std::vector<double>> numbers_;  // per column (empty for text columns)
};

// Multi-line text for `darkroom info`.
DARKROOM_API std::string formatDescription(const CinemaDescription& d);

}  // namespace darkroom
