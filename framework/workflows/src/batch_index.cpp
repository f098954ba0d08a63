#include "batch_index.h"

#include <darkroom/atomic_file.h>
#include <darkroom/data/cinema/csv.h>

#include <filesystem>
#include <set>
#include <sstream>

namespace darkroom::workflows::batch {

namespace fs = std::filesystem;

// The index's file columns: one per output path of the per-entry sinks and
// one per database a row-fed sink writes (its product of the entry); FILE
// alone, or FILE_<node>[_<port>] for several.
std::vector<std::string> indexColumns(const std::vector<OutputPort>& outputs,
                                      const std::vector<DatabaseSink>& databases) {
    std::map<std::string, int> portsPerNode;
    for (const auto& o : outputs) ++portsPerNode[o.node];
    const std::size_t count = outputs.size() + databases.size();
    std::vector<std::string> names;
    for (const auto& o : outputs)
        names.push_back(count == 1 ? "FILE" : "FILE_" + o.node + (portsPerNode[o.node] > 1 ? "_" + o.port : ""));
    for (const auto& d : databases) names.push_back(count == 1 ? "FILE" : "FILE_" + d.node);
    return names;
}

// The index: the database's parameter columns, then the file columns, one
// row per entry in database order, file names relative to the index's folder.
void writeIndex(const std::string& path, const CinemaDatabase& db, const std::vector<std::string>& fileColumns,
                const std::map<std::size_t, std::vector<std::string>>& filesByRow) {
    const fs::path folder = fs::absolute(fs::path(path)).parent_path();
    std::vector<std::string> cells;
    const auto line = [&cells]() {
        std::string text;
        for (std::size_t k = 0; k < cells.size(); ++k) text += (k ? "," : "") + quoteCsvCell(cells[k]);
        cells.clear();
        return text + "\n";
    };
    const auto parameters = db.parameterColumns();
    for (auto c : parameters) cells.push_back(db.columns()[c].name);
    cells.insert(cells.end(), fileColumns.begin(), fileColumns.end());
    std::string text = line();
    for (const auto& [row, files] : filesByRow) {
        for (auto c : parameters) cells.push_back(db.cell(row, c));
        for (const auto& f : files) cells.push_back(fs::absolute(f).lexically_proximate(folder).string());
        text += line();
    }
    if (!folder.empty()) fs::create_directories(folder);
    writeFileAtomic(path, text);
}

void writeIndexOf(const std::string& path, const Plan& p, const std::vector<std::size_t>& todo,
                  const std::vector<std::string>& shadedRecords) {
    std::map<std::size_t, std::vector<std::string>> filesByRow;
    std::vector<bool> shaded(p.rows.size(), false);
    for (const auto& text : shadedRecords) {
        std::istringstream in(text);
        for (std::size_t k; in >> k;) shaded[k] = true;
    }
    const std::set<std::size_t> redo(todo.begin(), todo.end());
    for (std::size_t k = 0; k < p.rows.size(); ++k) {
        if (!shaded[k] && redo.count(k)) continue;
        auto files = p.filesOf(p.rows[k]);
        for (const auto& d : p.databases)
            files.push_back((fs::path(d.database) / (p.db->entryName(p.rows[k]) + "." + d.format)).string());
        filesByRow[p.rows[k]] = std::move(files);
    }
    writeIndex(path, *p.db, indexColumns(p.outputs, p.databases), filesByRow);
}

}  // namespace darkroom::workflows::batch
